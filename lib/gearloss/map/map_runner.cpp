#include "gearloss/map/map_runner.hpp"

#include "gearloss/io/csv_format.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <set>
#include <string_view>
#include <filesystem>
#include <optional>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <omp.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/case/issue_location.hpp"
#include "gearloss/case/yaml_reader.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::map {

namespace {
constexpr double rpm = 30.0 / std::numbers::pi;
}  // namespace

namespace {
// The issue as an error at the line of its item: from the places the loader recorded, or (a
// model without them) by finding the item in the case file again.
InputError locate(const io::Case& k, const solver::Issue& is, const std::string& message, const CaseOverrides& o) {
    if (is.section == "thermal" && is.key == "oil_temperature" && !o.oil_temp.empty())
        return InputError("", 0, 0, "--oil-temp", message);
    if (is.section == "operating" && is.key == "speeds" && o.speeds) return InputError("", 0, 0, "--speed", message);
    if (is.section == "operating" && is.key == "torques" && o.torques) return InputError("", 0, 0, "--torque", message);
    if (k.model.source && !(is.section == "oil" && !o.oil.empty())) {
        SourceLocation at = k.model.source->find(is.section, is.item, is.key);
        if (at.file.empty()) at.file = k.file;
        return InputError(at, is.path(), message);
    }
    try {
        std::optional<io::YamlNode> node;
        if (is.section == "oil" && !o.oil.empty()) {
            const io::YamlNode oil_root = io::YamlNode::load_file(o.oil);
            node = io::locate_in_case(oil_root.has("oil") ? oil_root.at("oil") : oil_root, "", "", is.key);
        } else {
            node = io::locate_in_case(io::YamlNode::load_file(k.file), is.section, is.item, is.key);
        }
        node->fail(message);
    } catch (const InputError& e) {
        if (e.line > 0) return InputError(e.file, e.line, e.column, is.path(), message);
    } catch (const std::exception&) {
        // the file is no longer readable: the issue without its line
    }
    return InputError(k.file, 0, 0, is.path(), message);
}

[[noreturn]] void raise(const io::Case* k, const std::vector<solver::Issue>& issues, const CaseOverrides& o) {
    const auto& first = issues.front();
    const std::string message = solver::summarise(issues);
    if (k) throw locate(*k, first, message, o);
    throw InputError("", 0, 0, first.section == "operating" ? (first.key == "speeds" ? "--speed" : "--torque") : first.path(),
                     message);
}
}  // namespace

void validate_case(const io::Case& k, const CaseOverrides& o) {
    std::vector<solver::Issue> issues = solver::validate(k.model);
    if (o.grid) {
        const auto& g = k.grid;
        if (g.size() > o.max_points)
            issues.push_back({"operating", "", g.is_grid ? "speeds" : "points",
                              fmt::format("{} operating points; a map holds at most {}", g.size(), o.max_points)});
        auto check = [&](const std::vector<double>& v, const char* key, bool speed) {
            for (double x : v)
                if (auto f = speed ? solver::speed_fault(x) : solver::torque_fault(x)) {
                    issues.push_back({"operating", "", key, *f});
                    return;
                }
        };
        if (g.is_grid) {
            check(g.speeds, "speeds", true);
            check(g.torques, "torques", false);
        } else {
            for (const auto& [w, T] : g.points) {
                auto f = solver::speed_fault(w);
                if (!f) f = solver::torque_fault(T);
                if (f) {
                    issues.push_back({"operating", "", "points", *f});
                    break;
                }
            }
        }
    }
    if (!issues.empty()) raise(&k, issues, o);
}

void validate_point(double omega_in, double torque_in) {
    const auto issues = solver::validate_operating_point(omega_in, torque_in);
    if (!issues.empty()) raise(nullptr, issues, {});
}

void MapOptions::validate() const {
    if (threads < 0 || threads > 1024)
        throw InputError("", 0, 0, "--threads", fmt::format("{} threads: give 1 to 1024 (0 = all cores)", threads));
}

std::vector<solver::PointResult> run_map(const solver::Model& m, const io::OperatingGrid& grid, const MapOptions& opt) {
    opt.validate();
    if (grid.size() > kMaxGridPoints)
        throw InputError("", 0, 0, "operating",
                         fmt::format("{} operating points; a map holds at most {}", grid.size(), kMaxGridPoints));
    const long n = static_cast<long>(grid.size());
    // Reserved, then filled block by block: initialising all results at once (~0.5 kB a
    // point) would take seconds on a large map before the first interrupt check.
    std::vector<solver::PointResult> out;
    out.reserve(static_cast<size_t>(n));
    constexpr long kBlock = 1L << 16;
    const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    std::atomic<size_t> done{0};
    std::atomic<bool> stop{false};
    // Threads bound to cores (proc_bind): unbound, the scheduler migrates them
    // between cores and a short map loses a third of its parallel speed-up.
    // The empty region places the team before the work starts.
#pragma omp parallel num_threads(threads) proc_bind(close)
    { (void)omp_get_thread_num(); }
    for (long b0 = 0; b0 < n && !stop.load(); b0 += kBlock) {
        const long b1 = std::min(n, b0 + kBlock);
        out.resize(static_cast<size_t>(b1));
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64) proc_bind(close)
        for (long i = b0; i < b1; ++i) {
            if (stop.load(std::memory_order_relaxed)) continue;
            if (io::g_interrupted.load(std::memory_order_relaxed)) {
                stop = true;
                continue;
            }
            const auto [w, T] = grid.at(static_cast<size_t>(i));
            out[static_cast<size_t>(i)] = solver::solve_point(m, w, T, opt.detail);
            const size_t d = ++done;
            if (opt.progress && omp_get_thread_num() == 0 && (d & 255) == 0) opt.progress(d, static_cast<size_t>(n));
        }
    }
    if (opt.progress) opt.progress(done.load(), static_cast<size_t>(n));
    return out;
}

namespace {
// "P_churn_{}_W" with the component's name.
std::string component_column(const std::string& pattern, const std::string& name) {
    const size_t at = pattern.find("{}");
    if (at == std::string::npos) return pattern;
    std::string s = pattern;
    s.replace(at, 2, name);
    return s;
}
// The --detail layout of a model's mechanisms (their quantities and component counts),
// built once per model and thread rather than for every row.
struct DetailLayout {
    unsigned long long id = 0;
    size_t sizes[5] = {};
    std::vector<std::vector<losses::DetailQuantity>> quantities;  // per mechanism
    std::vector<size_t> components;                               // per mechanism
};
const DetailLayout& detail_layout(const solver::Model& m) {
    thread_local DetailLayout d;
    const auto& gb = m.gearbox;
    const size_t sizes[5] = {gb.gears.size(), gb.meshes.size(), gb.bearings.size(), gb.seals.size(), gb.clutches.size()};
    if (d.id == m.mechanisms.id() && std::equal(sizes, sizes + 5, d.sizes)) return d;
    d.id = m.mechanisms.id();
    std::copy(sizes, sizes + 5, d.sizes);
    d.quantities.clear();
    d.components.clear();
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        d.quantities.push_back(m.mechanisms[i].quantities());
        d.components.push_back(m.mechanisms[i].components(m).size());
    }
    return d;
}
}  // namespace

std::string csv_header(const solver::Model& m, bool detail) {
    std::string h = "speed_in_rpm,torque_in_Nm,power_in_W,ambient_temp_C,oil_temp_C";
    for (size_t i = 0; i < m.mechanisms.size(); ++i) h += fmt::format(",{}", m.mechanisms[i].column());
    h += ",P_total_W,power_out_W,torque_out_Nm,efficiency,lambda_min,status";
    if (detail) {
        for (size_t i = 0; i < m.mechanisms.size(); ++i) {
            const auto& mech = m.mechanisms[i];
            const auto quantities = mech.quantities();
            for (const auto& c : mech.components(m))
                for (const auto& q : quantities)
                    if (!q.column.empty()) h += "," + component_column(q.column, c);
        }
        // A name can make a column of another (mesh "min": lambda_min): every column once.
        std::set<std::string_view> seen;
        for (size_t a = 0; a <= h.size();) {
            const size_t e = std::min(h.find(',', a), h.size());
            if (!seen.insert(std::string_view(h).substr(a, e - a)).second)
                throw InputError("", 0, 0, "--detail",
                                 fmt::format("column '{}' would appear twice: rename the component it comes from",
                                             h.substr(a, e - a)));
            a = e + 1;
        }
    }
    return h + "\n";
}

void append_csv_row(std::string& s, const solver::Model& m, const solver::PointResult& r, bool detail) {
    // Appended cell by cell into one string: a map formats a row per point.
    using io::append_csv_fixed;
    using io::append_csv_number;
    const bool ok = solver::has_values(r.status);
    const auto& L = r.losses;
    append_csv_number(s, r.speed_in * rpm);
    s += ',';
    append_csv_number(s, r.torque_in);
    s += ',';
    append_csv_number(s, r.power_in);
    s += ',';
    append_csv_fixed(s, r.ambient - 273.15, 2);
    s += ',';
    if (ok) {
        append_csv_fixed(s, r.oil_temperature - 273.15, 3);
        for (double P : L.power) {
            s += ',';
            append_csv_number(s, P);
        }
        for (double v : {L.total(), r.power_out, r.torque_out}) {
            s += ',';
            append_csv_number(s, v);
        }
        s += ',';
        if (r.has_efficiency) append_csv_fixed(s, r.efficiency, 6);
        s += ',';
        if (L.has_lambda) append_csv_number(s, L.lambda_min);
        s += ',';
    } else {
        s.append(m.mechanisms.size() + 6, ',');
    }
    s += solver::status_text(r);
    if (detail) {
        const bool have = ok && L.detail.size() == m.mechanisms.size();
        const DetailLayout& layout = detail_layout(m);
        for (size_t i = 0; i < m.mechanisms.size(); ++i) {
            const auto& quantities = layout.quantities[i];
            const size_t nc = layout.components[i];
            for (size_t c = 0; c < nc; ++c)
                for (size_t q = 0; q < quantities.size(); ++q) {
                    if (quantities[q].column.empty()) continue;
                    const double v = have ? L.detail[i].at(c, q) : std::nan("");
                    s += ',';
                    if (std::isfinite(v)) append_csv_number(s, v * quantities[q].csv_scale);
                }
        }
    }
    s += '\n';
}

std::string csv_row(const solver::Model& m, const solver::PointResult& r, bool detail) {
    std::string s;
    append_csv_row(s, m, r, detail);
    return s;
}

}  // namespace gearloss::map
