#include "gearloss/map/job.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/case/sweep.hpp"

namespace gearloss::map {

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;

std::string prefix(const std::vector<std::string>& values) {
    std::string s;
    for (const auto& v : values) s += io::csv_cell(v) + ",";
    return s;
}

// The rows' keys of a grid as written (rounded like the CSV): its speeds and torques, or
// its points. A grid and the point list of the same rows hash differently, which can only
// make merge refuse shards of jobs that are the same, never join different ones.
uint64_t grid_key(const io::OperatingGrid& g) {
    Fnv1a f;
    f.add(g.is_grid ? "grid" : "points");
    if (g.is_grid) {
        for (double w : g.speeds) f.add(io::csv_number(w * kRpm));
        f.add("x");
        for (double T : g.torques) f.add(io::csv_number(T));
    } else {
        for (const auto& [w, T] : g.points) f.add(io::csv_number(w * kRpm) + "," + io::csv_number(T));
    }
    return f.h;
}

std::string thermal_mode(const io::Case& c) {
    return c.model.thermal.mode == solver::ThermalMode::fixed ? "fixed" : "stabilised";
}
}  // namespace

namespace {
// `path` is `prefix` or a key below it ("oil", "oil.name"; not "oil_level").
bool under(const std::string& path, const char* prefix) {
    const size_t n = std::strlen(prefix);
    return path.compare(0, n, prefix) == 0 && (path.size() == n || path[n] == '.');
}
}  // namespace

const char* SweepOverrides::setting(const std::string& path) const {
    if (oil && under(path, "oil")) return oil;
    if (oil_temperature && (path == "thermal.mode" || under(path, "thermal.oil_temperature"))) return oil_temperature;
    if (ratio && path == "gearbox.ratio") return ratio;
    const bool points = under(path, "operating.points");
    if (speeds && (points || under(path, "operating.speeds"))) return speeds;
    if (torques && (points || under(path, "operating.torques"))) return torques;
    return nullptr;
}

MapJob sweep_job(std::shared_ptr<io::Sweep> sweep, const io::Case& first, std::function<io::Case(io::Case)> prepare,
                 const SweepOverrides& given) {
    std::vector<std::string> labels;
    bool grid_swept = false, thermal_swept = false;
    for (const auto& a : sweep->axes()) {
        labels.push_back(a.label);
        for (const auto& p : a.paths) {
            grid_swept = grid_swept || under(p, "operating");
            thermal_swept = thermal_swept || p == "thermal.mode";
            if (const char* name = given.setting(p))
                throw InputError("", 0, 0, name, fmt::format("the case's sweep sets '{}': {} would replace the value of "
                                                             "every variant; give one or the other", p, name));
        }
    }
    MapJob::Source src = MapJob::sweep_source(std::move(sweep), std::move(prepare));
    if (!grid_swept || (given.speeds && given.torques)) src.grid = first.grid;
    src.thermal = thermal_swept && !given.oil_temperature ? "swept" : thermal_mode(first);
    return MapJob(std::move(labels), std::move(src));
}

MapJob::Source MapJob::sweep_source(std::shared_ptr<io::Sweep> sweep, std::function<io::Case(io::Case)> prepare) {
    Source src;
    src.count = sweep->size();
    src.values = [sweep](size_t v) { return sweep->values(v); };
    src.load = [sweep, prepare = std::move(prepare)](size_t v) {
        io::Case c = sweep->variant(v);  // its errors name the variant
        try {
            return prepare(std::move(c));
        } catch (const InputError& e) {
            throw InputError(e.file, e.line, e.column, e.key, e.message + " (sweep variant " + sweep->tag(v) + ")");
        }
    };
    return src;
}

MapJob::MapJob(std::vector<std::string> sweep_labels, Source source)
    : labels_(std::move(sweep_labels)), source_(std::move(source)) {
    if (source_.count == 0) throw std::logic_error("a map job without variants");
    offsets_.reserve(source_.count + 1);
    Fnv1a rows;
    const uint64_t shared = source_.grid ? grid_key(*source_.grid) : 0;
    for (size_t v = 0; v < source_.count; ++v) {
        if ((v & 255) == 0) io::throw_if_interrupted();
        rows.add(prefix(source_.values(v)));
        if (source_.grid) {
            offsets_.push_back(offsets_.back() + source_.grid->size());
            rows.add(fmt::format("{:016x}", shared));
        } else {
            // The sweep may change the grid: each variant is loaded for its rows.
            const io::Case c = source_.load(v);
            offsets_.push_back(offsets_.back() + c.grid.size());
            rows.add(fmt::format("{:016x}", grid_key(c.grid)));
        }
    }
    rows_key_ = rows.h;
}

namespace {
MapJob::Source held(std::shared_ptr<const std::vector<MapJob::Variant>> v) {
    MapJob::Source s;
    s.count = v->size();
    s.values = [v](size_t k) { return (*v)[k].values; };
    s.load = [v](size_t k) { return (*v)[k].c; };
    // The case or --oil-temp decides the mode; a sweep may mix them.
    for (const auto& x : *v) {
        const std::string m = thermal_mode(x.c);
        s.thermal = s.thermal.empty() || s.thermal == m ? m : "mixed";
    }
    return s;
}
}  // namespace

MapJob::MapJob(std::vector<std::string> sweep_labels, std::vector<Variant> variants)
    : MapJob(std::move(sweep_labels), held(std::make_shared<const std::vector<Variant>>(std::move(variants)))) {}

io::Case MapJob::load(size_t v) const { return source_.load(v); }

const std::string& MapJob::columns(bool detail) const {
    auto& c = columns_[detail ? 1 : 0];
    if (!c) c = csv_header(load(0).model, detail);
    return *c;
}

std::string MapJob::header(bool detail) const {
    std::string h;
    for (const auto& l : labels_) h += io::csv_cell(l) + ",";
    return h + columns(detail);
}

Fingerprint MapJob::fingerprint() const {
    Fingerprint fp = inputs;
    fp.add("thermal", source_.thermal);
    fp.add("points", fmt::format("{:016x}", rows_key_));
    return fp;
}

namespace {
// The variants with rows in [begin, end): the first and one past the last.
std::pair<size_t, size_t> variants_of(const std::vector<size_t>& offsets, size_t begin, size_t end) {
    const auto first = std::upper_bound(offsets.begin(), offsets.end() - 1, begin) - offsets.begin() - 1;
    size_t last = static_cast<size_t>(first);
    while (last + 1 < offsets.size() && offsets[last] < end) ++last;
    return {static_cast<size_t>(first), last};
}

void require_columns(const io::Case& c, const std::string& columns, bool detail) {
    if (csv_header(c.model, detail) != columns)
        throw InputError(c.file, 0, 0, "sweep",
                         detail ? "the sweep changes the components (different --detail columns); map it without --detail"
                                : "the sweep changes the loss mechanisms (different CSV columns)");
}
}  // namespace

void MapJob::check(size_t begin, size_t end, bool detail) const {
    const std::string& columns = this->columns(detail);
    const auto [v0, v1] = variants_of(offsets_, begin, end);
    for (size_t v = v0; v < v1; ++v) {
        io::throw_if_interrupted();
        require_columns(load(v), columns, detail);
    }
}

size_t MapJob::run(const MapOptions& opt, size_t begin, size_t end, const TextSink& write, MapSummary* summary) const {
    end = std::min(end, total_points());
    if (begin >= end) return 0;
    const std::string& columns = this->columns(opt.detail);
    const auto [v0, v1] = variants_of(offsets_, begin, end);
    MapOptions part = opt;
    for (size_t v = v0; v < v1; ++v) {
        io::throw_if_interrupted();
        const io::Case c = load(v);
        require_columns(c, columns, opt.detail);
        if (c.grid.size() != offsets_[v + 1] - offsets_[v])
            throw std::logic_error(fmt::format("sweep variant {}: {} points, the job counted {}", v, c.grid.size(),
                                               offsets_[v + 1] - offsets_[v]));
        const size_t a = std::max(begin, offsets_[v]), b = std::min(end, offsets_[v + 1]);
        // Progress over the whole job (or shard), not per variant.
        if (opt.progress) {
            const size_t before = a - begin, all = end - begin;
            part.progress = [&opt, before, all](size_t d, size_t) { opt.progress(before + d, all); };
        }
        stream_rows(c.model, c.grid, a - offsets_[v], b - offsets_[v], part, csv_formatter(c.model, opt.detail, prefix(values(v))),
                    write, summary);
    }
    return end - begin;
}

std::pair<size_t, size_t> Shard::range(size_t total) const {
    // total * k / n, exactly and without overflow for any total: total = q n + r, r < n.
    const size_t n = static_cast<size_t>(count), q = total / n, r = total % n;
    const auto at = [&](size_t k) { return q * k + r * k / n; };
    const size_t k = static_cast<size_t>(index - 1);
    return {at(k), at(k + 1)};
}

Shard parse_shard(const std::string& text) {
    Shard s;
    const auto slash = text.find('/');
    try {
        if (slash == std::string::npos) throw std::invalid_argument("no slash");
        // Digits and the slash only: std::stoi would skip a leading space or sign (' 1/2', '+1/2').
        if (text.find_first_not_of("0123456789/") != std::string::npos) throw std::invalid_argument("not a digit");
        size_t p1 = 0, p2 = 0;
        s.index = std::stoi(text.substr(0, slash), &p1);
        s.count = std::stoi(text.substr(slash + 1), &p2);
        if (p1 != slash || p2 != text.size() - slash - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
        throw InputError("", 0, 0, "--shard", "'" + io::excerpt(text) + "' is not K/N (e.g. 3/16)");
    }
    if (s.count < 1 || s.count > 100000 || s.index < 1 || s.index > s.count)
        throw InputError("", 0, 0, "--shard", "'" + io::excerpt(text) + "': need 1 <= K <= N <= 100000");
    return s;
}

size_t run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard, const TextSink& write,
               MapSummary* summary) {
    const size_t total = job.total_points();
    const auto [begin, end] = shard ? shard->range(total) : std::pair<size_t, size_t>{0, total};
    const std::string header = job.header(opt.detail);
    // A bad variant stops the run before a point is solved. A shard checks every variant of a
    // job of up to 1 000 (~0.2 s), so that every shard fails as the single run does, and only
    // its own beyond (100 000 variants would take 20 s each time a shard starts).
    constexpr size_t kShardChecksAll = 1000;
    const bool all = !shard || job.variant_count() <= kShardChecksAll;
    job.check(all ? 0 : begin, all ? total : end, opt.detail);
    if (shard) {
        // Readers that know only "... job <hash>" (older merges) still parse the line.
        const Fingerprint fp = job.fingerprint();
        write(fmt::format("# gearloss shard {}/{}: rows {}-{} of {}, job {:016x}; {}\n", shard->index, shard->count, begin,
                          end, total, fp.total(), fp.text()));
    }
    write(header);
    return job.run(opt, begin, end, write, summary);
}

std::string run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard) {
    std::string out;
    run_job(job, opt, shard, [&out](std::string_view s) { out += s; });
    return out;
}

}  // namespace gearloss::map
