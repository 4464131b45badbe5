// Case loader: assembles a Case (gearbox ratios, housing, operating grid) from the sections of config_*.cpp.
#include "gearloss/case/config.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

#include "gearloss/case/case_plausibility.hpp"
#include "gearloss/case/config_internal.hpp"
#include "gearloss/case/declared_assumptions.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/case/issue_location.hpp"
#include "gearloss/case/mechanism_config.hpp"
#include "gearloss/case/sweep.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/units/ranges.hpp"

namespace gearloss::io {

namespace fs = std::filesystem;

namespace {
// Position where the unit starts in "600rpm" / "1.5e-3 m" (an 'e' followed by a
// digit or sign belongs to the number); npos when there is no unit.
size_t unit_start(const std::string& s) {
    // The unit is whatever follows the number ("700 1/min": "1/min", not "min").
    size_t b = 0;
    while (b < s.size() && s[b] == ' ') ++b;
    if (b < s.size() && s[b] == '+') ++b;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data() + b, s.data() + s.size(), v);
    if (ec != std::errc() && ec != std::errc::result_out_of_range) return std::string::npos;
    size_t u = static_cast<size_t>(ptr - s.data());
    while (u < s.size() && s[u] == ' ') ++u;
    return u < s.size() ? u : std::string::npos;
}
}  // namespace

std::vector<double> parse_value_list(const std::string& text, const units::Dimension& d, const char* what,
                                     const char* example) {
    // Items are comma-separated; a unit on the last item applies to items
    // without one: "600,700,800rpm". An item may be a range START:STOP:STEP
    // ("300:3000:100rpm", units/ranges.hpp), its unit being that of the range's STEP.
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == ',') {
            std::string p = text.substr(start, i - start);
            p.erase(0, p.find_first_not_of(' '));
            p.erase(p.find_last_not_of(' ') + 1);
            parts.push_back(p);
            start = i + 1;
        }
    const auto is_range = [](const std::string& p) { return p.find(':') != std::string::npos; };
    const auto unit_of = [&](const std::string& p) {
        if (is_range(p)) return units::range_unit(p);
        const size_t u = unit_start(p);
        return u == std::string::npos ? std::string() : p.substr(u);
    };
    const std::string unit = unit_of(parts.back());
    // A comma always separates items (there is no decimal comma: "1000,5rpm" is 1000 and 5 rpm),
    // and a unit is given on every item or on the last one only: "600rpm,700,800rpm" is refused.
    const bool some_bare = std::any_of(parts.begin(), parts.end(), [&](const std::string& p) {
        return !p.empty() && unit_of(p).empty();
    });
    for (size_t i = 0; some_bare && i + 1 < parts.size(); ++i)
        if (!unit_of(parts[i]).empty())
            throw InputError("", 0, 0, what,
                             "'" + excerpt(text) + "' mixes items with and without a unit; give the unit on every item "
                             "or on the last one only (e.g. '" + example + "')");
    std::vector<double> out;
    const auto read = [&](const std::string& q) {
        out.push_back(units::checked_value(units::parse_quantity(q), d, q));
    };
    for (const auto& p : parts) {
        if (p.empty()) throw InputError("", 0, 0, what, "empty item in '" + excerpt(text) + "' (expected e.g. '" + example + "')");
        try {
            if (is_range(p)) {
                for (const auto& q : units::expand_range(p, unit)) read(q);
            } else {
                read(unit_start(p) == std::string::npos ? p + " " + unit : p);
            }
        } catch (const units::UnitError& e) {
            throw InputError("", 0, 0, what, e.message + " (expected e.g. '" + example + "')");
        }
        if (out.size() > units::kMaxListItems)
            throw InputError("", 0, 0, what, fmt::format("'{}': more than {} values", excerpt(text), units::kMaxListItems));
    }
    return out;
}

namespace {

// The values of a scalar `it`: one value, or a range START:STOP:STEP (units/ranges.hpp) of them.
void append_values(std::vector<double>& v, const YamlNode& it, const units::Dimension& d, const char* example) {
    if (!it.is_scalar() || it.as_string().find(':') == std::string::npos) {
        v.push_back(it.as_quantity(d, example));
        return;
    }
    const std::string text = it.as_string();
    try {
        for (const auto& q : units::expand_range(text, "")) v.push_back(units::checked_value(units::parse_quantity(q), d, q));
    } catch (const units::UnitError& e) {
        it.fail(e.message + " (expected e.g. '" + example + "' or a range START:STOP:STEP such as '300:3000:100 rpm')");
    }
    if (v.size() > units::kMaxListItems) it.fail(fmt::format("more than {} values in the list", units::kMaxListItems));
}

std::vector<double> load_axis(const YamlNode& n, const units::Dimension& d, const char* example) {
    std::vector<double> v;
    if (n.is_sequence()) {
        for (const auto& it : n.items()) append_values(v, it, d, example);
    } else if (n.is_scalar() && n.as_string().find(':') != std::string::npos) {
        append_values(v, n, d, example);  // "300:3000:100 rpm"
    } else if (n.is_map()) {
        n.allow_keys({"from", "to", "count"});
        const double a = n.at("from").as_quantity(d, example), b = n.at("to").as_quantity(d, example);
        const int c = n.at("count").as_int();
        if (c < 1 || c > 1000000) n.at("count").fail("count must be 1..1000000");
        for (int i = 0; i < c; ++i) v.push_back(c == 1 ? a : a + (b - a) * i / (c - 1));
    } else {
        n.fail(std::string("expected a list of values, a range START:STOP:STEP or {from, to, count}, e.g. [") + example + "]");
    }
    if (v.empty()) n.fail("empty list");
    return v;
}

}  // namespace

namespace detail {

std::string located_at(const SourceLocation& at) {
    return at.known() ? fmt::format("{}:{}:{}", at.file, at.line, at.column) : std::string();
}

void assume(std::vector<AssumedValue>* out, const YamlNode& parent, std::string key, std::string value,
            std::string reason) {
    if (out) out->push_back({std::move(key), std::move(value), std::move(reason), located_at(parent.location())});
}

std::string number_text(double v) { return fmt::format("{:g}", v); }

void note_bearing_friction(Case& c) {
    std::erase_if(c.assumed, [](const AssumedValue& a) {
        return a.key.starts_with("bearings.") && a.key.ends_with(".mu_ehl");
    });
    const auto& oil = c.model.oil;
    for (const auto& b : c.model.gearbox.bearings) {
        const bool roller = bearings::is_roller(b.spec.type);
        if ((roller ? oil.bearing_roller : oil.bearing_ball).mu_ehl) continue;
        const SourceLocation at = case_location(c, "bearings", b.name);
        c.assumed.push_back({"bearings." + b.name + ".mu_ehl", number_text(b.spec.mu_ehl),
                             fmt::format("SKF (2004) full-film default for a {} bearing with {} oil (the oil gives no "
                                         "bearing_friction.{}.mu_ehl)",
                                         bearings::to_string(b.spec.type), lubricant::to_string(oil.base),
                                         roller ? "roller" : "ball"),
                             located_at(at)});
    }
}

}  // namespace detail

SourceLocation case_location(const Case& c, const std::string& section, const std::string& item, const std::string& key) {
    SourceLocation at = c.model.source ? c.model.source->find(section, item, key) : SourceLocation{};
    if (at.file.empty()) at.file = c.file;
    return at;
}

void replace_oil(Case& c, const lubricant::Oil& oil, const std::vector<AssumedValue>& assumed_by_oil) {
    replace_oil(c.model, oil);
    std::erase_if(c.assumed, [](const AssumedValue& a) { return a.key.starts_with("oil."); });
    c.assumed.insert(c.assumed.end(), assumed_by_oil.begin(), assumed_by_oil.end());
    detail::note_bearing_friction(c);
    detail::note_mechanism_settings(c);
}

void replace_oil_file(Case& c, const std::string& file) {
    std::vector<AssumedValue> assumed;
    const lubricant::Oil oil = load_oil_file(file, &assumed);
    replace_oil(c, oil, assumed);
    c.oil_file = file;
}

void replace_oil(solver::Model& m, const lubricant::Oil& oil) {
    m.oil = oil;
    for (auto& b : m.gearbox.bearings) detail::set_bearing_friction(b.spec, oil);
}

Case load_case(const std::string& file, const std::optional<std::string>& ratio_override) {
    const std::string text = read_input_file(file, kMaxYamlFileBytes);  // a regular file, bounded (gearloss/io/csv_read.hpp)
    return load_case_text(text, file, fs::path(file).parent_path().string(), ratio_override);
}

namespace {
Case build_case(const YamlNode& root, const std::string& file, const std::string& base_dir,
                const std::optional<std::string>& ratio_override, const OilFileReader& read_oil);

// Any structural surprise inside yaml-cpp is still an input error with its position.
[[noreturn]] void unexpected_structure(const std::string& file, const YAML::Exception& e) {
    throw InputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, "",
                     "unexpected YAML structure: " + e.msg);
}
}  // namespace

Case load_case_text(const std::string& text, const std::string& file, const std::string& base_dir,
                    const std::optional<std::string>& ratio_override) {
    try {
        const YamlNode root = YamlNode::load_text(text, file);
        return build_case(root, file, base_dir, ratio_override, {});
    } catch (const YAML::Exception& e) {
        unexpected_structure(file, e);
    }
}

Case load_case_node(const YamlNode& root, const std::string& file, const std::string& base_dir,
                    const std::optional<std::string>& ratio_override, const OilFileReader& read_oil) {
    try {
        return build_case(root, file, base_dir, ratio_override, read_oil);
    } catch (const YAML::Exception& e) {
        unexpected_structure(file, e);
    }
}

namespace {
Case build_case(const YamlNode& root, const std::string& file, const std::string& base_dir,
                const std::optional<std::string>& ratio_override, const OilFileReader& read_oil) {
    Case c;
    c.file = file;
    // Where every item and key was written, kept with the model for errors found later.
    auto source = std::make_shared<SourceIndex>();
    source->set_file(file);
    index_sources(root, "", *source);
    root.allow_keys({"name", "description", "oil", "materials", "shafts", "gears", "meshes", "bearings", "seals",
                     "clutches", "housing", "thermal", "gearbox", "operating", "options", "mechanisms", "calibration", "vehicle",
                     "sweep", "bearing_catalogue", "assumed"});
    c.sweep = read_sweep(root);
    auto& m = c.model;
    m.name = root.has("name") ? root.at("name").as_title() : fs::path(file).stem().string();
    if (!root.has("name")) detail::assume(&c.assumed, root, "name", m.name, "the case file's name");

    const YamlNode oil = root.at("oil");
    if (oil.is_scalar()) {
        const fs::path p = fs::path(base_dir) / oil.as_string();
        std::error_code ec;  // non-throwing: a malformed name is an input error, not a crash
        if (!fs::is_regular_file(p, ec)) oil.fail("oil file '" + excerpt(p.string(), 200) + "' does not exist or is not a file");
        const YamlNode oil_root = read_oil ? read_oil(p.string()) : YamlNode::load_file(p.string());
        const YamlNode oil_node = oil_root.has("oil") ? oil_root.at("oil") : oil_root;
        m.oil = load_oil(oil_node, &c.assumed);
        c.oil_file = p.lexically_normal().string();
        index_sources(oil_node, "oil", *source);  // the oil's keys in their own file
    } else {
        m.oil = load_oil(oil, &c.assumed);
    }

    detail::Loader L{root, m, {}, {}, {}, base_dir, &c.bearings_resolved, &c.assumed};
    L.load_materials();
    L.load_shafts();
    L.load_gears();
    L.load_meshes();
    L.load_bearings();
    L.load_seals();
    L.load_clutches();

    const YamlNode gbn = root.at("gearbox");
    gbn.allow_keys({"input", "output", "ratio", "ratios"});
    m.gearbox.input_shaft = L.shaft_ref(gbn.at("input"));
    m.gearbox.output_shaft = L.shaft_ref(gbn.at("output"));
    if (auto rs = gbn.get("ratios")) {
        for (auto& [name, rn] : rs->entries()) {
            if (const std::string why = name_problem(name, YamlNode::kMaxNameBytes); !why.empty())
                rn.fail("ratio '" + excerpt(name) + "': " + why);
            rn.allow_keys({"engage", "note"});
            std::vector<int> eng;
            for (const auto& g : rn.at("engage").items()) {
                const int gi = L.gear_ref(g);
                if (!m.gearbox.gears[gi].free) g.fail("gear '" + g.as_string() + "' is fixed to its shaft; only 'mount: free' gears are engaged");
                eng.push_back(gi);
            }
            m.gearbox.ratios.push_back({name, eng});
        }
        const std::string sel = ratio_override ? *ratio_override : (gbn.has("ratio") ? gbn.at("ratio").as_string() : "");
        if (sel.empty()) gbn.fail("several ratios are defined; select one with 'ratio' (or --ratio)");
        const auto it = std::find_if(m.gearbox.ratios.begin(), m.gearbox.ratios.end(),
                                     [&](const auto& r) { return r.name == sel; });
        if (it == m.gearbox.ratios.end()) {
            const std::string all = fmt::format("{}", fmt::join(m.ratio_names(), ", "));
            if (ratio_override) throw InputError(file, 0, 0, "--ratio", "unknown ratio '" + sel + "'; defined: " + all);
            gbn.at("ratio").fail("unknown ratio '" + excerpt(sel) + "'; defined: " + all);
        }
        m.gearbox.engaged = it->engaged;
        m.ratio = sel;
    } else if (ratio_override) {
        throw InputError(file, 0, 0, "--ratio", "the config defines no 'gearbox.ratios'");
    }

    const YamlNode h = root.at("housing");
    h.allow_keys({"oil_volume", "oil_level", "lubrication", "gravity", "note"});
    const auto lubrication = h.has("lubrication") ? h.at("lubrication").as_enum<solver::Lubrication>(
                                                        {{"dip", solver::Lubrication::dip}, {"injection", solver::Lubrication::injection}})
                                                  : solver::Lubrication::dip;
    if (!h.has("lubrication")) detail::assume(&c.assumed, h, "housing.lubrication", "dip", "splash lubrication from the sump");
    m.gearbox.oil_volume = h.positive_quantity("oil_volume", units::dim::volume, "2 L");
    if (auto lv = h.get("oil_level")) m.gearbox.oil_level = lv->as_quantity(units::dim::length, "-60 mm");
    if (auto gv = h.get("gravity")) m.gearbox.gravity = detail::load_gravity(*gv);
    else
        detail::assume(&c.assumed, h, "housing.gravity", "[0, -1, 0]",
                       "shafts horizontal, gravity along -y (y up: the frame of the mesh angles and the oil level)");

    detail::load_thermal(root.at("thermal"), m.thermal, &c.assumed);
    if (auto o = root.get("options")) detail::load_options(*o, m);
    if (auto mech = root.get("mechanisms")) load_mechanism_settings(*mech, m);
    if (auto cal = root.get("calibration")) load_calibration(*cal, m);

    const YamlNode op = root.at("operating");
    op.allow_keys({"speeds", "torques", "points"});
    if (op.has("points")) {
        if (op.has("speeds") || op.has("torques")) op.fail("give either 'points' or 'speeds' and 'torques'");
        c.grid.is_grid = false;
        for (const auto& p : op.at("points").items()) {
            const auto pr = p.items();
            if (pr.size() != 2) p.fail("each point is [speed, torque], e.g. [800 rpm, 250 N*m]");
            c.grid.points.emplace_back(pr[0].as_quantity(units::dim::angular_speed, "800 rpm"),
                                       pr[1].as_quantity(units::dim::torque, "250 N*m"));
        }
        if (c.grid.points.empty()) op.at("points").fail("empty list");
    } else {
        c.grid.speeds = load_axis(op.at("speeds"), units::dim::angular_speed, "800 rpm");
        c.grid.torques = load_axis(op.at("torques"), units::dim::torque, "250 N*m");
    }

    if (auto v = root.get("vehicle")) {
        load_vehicle(*v, c);
        for (size_t i = 0; i < c.vehicle->gears.size(); ++i)
            if (std::ranges::none_of(m.gearbox.ratios, [&](const auto& r) { return r.name == c.vehicle->gears[i]; }))
                v->at("gears").items()[i].fail("'" + excerpt(c.vehicle->gears[i]) + "' is not one of gearbox.ratios");
        if (c.vehicle->gears.empty() && !m.gearbox.ratios.empty())
            v->fail("the case defines gearbox.ratios: list the vehicle's gears (vehicle.gears); only a gearbox of one "
                    "fixed ratio leaves them out");
    }

    m.source = std::move(source);
    detail::note_bearing_friction(c);
    detail::note_mechanism_settings(c);
    // Errors found once the model is assembled point at the item they come from. Every
    // ratio is checked here, so a ratio selected at run time (Model::select_ratio, for a
    // drive cycle or a loss table per gear) needs no check that could fail without a line.
    const auto assemble = [&](solver::Model& mm) {
        const bool other = mm.ratio != m.ratio;
        const std::string in_ratio = other ? "ratio '" + mm.ratio + "': " : "";
        const YamlNode ratio_node = other ? gbn.at("ratios").at(mm.ratio) : gbn;
        try {
            mm.finalise();
        } catch (const gearbox::TopologyError& e) {
            (e.section.empty() ? ratio_node : locate_in_case(root, e.section, e.item, e.key)).fail(in_ratio + e.message);
        }
        if (const auto issues = solver::validate(mm); !issues.empty()) {
            const auto& first = issues.front();
            locate_in_case(root, first.section, first.item, first.key).fail(in_ratio + solver::summarise(issues));
        }
    };
    assemble(m);
    detail::note_weights(c);
    if (m.gearbox.ratios.size() > 1) {
        solver::Model other = m;
        for (const auto& r : m.gearbox.ratios)
            if (r.name != m.ratio) {
                other.gearbox.engaged = r.engaged;
                other.ratio = r.name;
                assemble(other);
            }
    }
    // Values the case gives but declares assumed (a case written by `gearloss import`).
    read_declared_assumptions(root, c.assumed);
    check_case_plausibility(root, c, lubrication);
    return c;
}
}  // namespace

}  // namespace gearloss::io
