#include "gearloss/map/job.hpp"

#include <algorithm>
#include <string_view>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_format.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/sweep.hpp"

namespace gearloss::map {

namespace {
constexpr double kRpm = 30.0 / std::numbers::pi;

std::string prefix(const std::vector<std::string>& values) {
    std::string s;
    for (const auto& v : values) s += io::csv_cell(v) + ",";
    return s;
}
}  // namespace

size_t MapJob::total_points() const {
    size_t n = 0;
    for (const auto& v : variants) n += v.c.grid.size();
    return n;
}

std::string MapJob::header(bool detail) const {
    std::string h;
    for (const auto& l : sweep_labels) h += io::csv_cell(l) + ",";
    const std::string body = csv_header(variants.front().c.model, detail);
    for (const auto& v : variants)
        if (csv_header(v.c.model, detail) != body)
            throw InputError(v.c.file, 0, 0, "sweep",
                             "the sweep changes the components (different --detail columns); map it without --detail");
    return h + body;
}

Fingerprint MapJob::fingerprint() const {
    Fingerprint fp = inputs;
    // The case or --oil-temp decides the mode; a sweep may mix them.
    std::string thermal;
    for (const auto& v : variants) {
        const std::string m = v.c.model.thermal.mode == solver::ThermalMode::fixed ? "fixed" : "stabilised";
        thermal = thermal.empty() || thermal == m ? m : "mixed";
    }
    fp.add("thermal", thermal);
    // The rows' keys as written (rounded like the CSV): the resolved grid and sweep.
    Fnv1a f;
    for (const auto& v : variants) {
        const std::string p = prefix(v.values);
        for (size_t i = 0; i < v.c.grid.size(); ++i) {
            if ((i & 4095) == 0) io::throw_if_interrupted();  // a million points take a second
            const auto [w, T] = v.c.grid.at(i);
            f.add(p + io::csv_number(w * kRpm) + "," + io::csv_number(T));
        }
    }
    fp.add("points", f.hex());
    return fp;
}

std::pair<size_t, size_t> Shard::range(size_t total) const {
    const size_t k = static_cast<size_t>(index - 1), n = static_cast<size_t>(count);
    return {total * k / n, total * (k + 1) / n};
}

Shard parse_shard(const std::string& text) {
    Shard s;
    const auto slash = text.find('/');
    try {
        if (slash == std::string::npos) throw std::invalid_argument("no slash");
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

JobOutput run_job(const MapJob& job, const MapOptions& opt, const std::optional<Shard>& shard) {
    const size_t total = job.total_points();
    const auto [begin, end] = shard ? shard->range(total) : std::pair<size_t, size_t>{0, total};
    JobOutput res;
    std::string& out = res.csv;
    if (shard) {
        // Readers that know only "... job <hash>" (older merges) still parse the line.
        const Fingerprint fp = job.fingerprint();
        out += fmt::format("# gearloss shard {}/{}: rows {}-{} of {}, job {:016x}; {}\n", shard->index, shard->count,
                           begin, end, total, fp.total(), fp.text());
    }
    out += job.header(opt.detail);
    size_t offset = 0;
    MapOptions part_opt = opt;
    for (const auto& v : job.variants) {
        const size_t n = v.c.grid.size();
        const size_t a = std::max(begin, offset), b = std::min(end, offset + n);
        if (a < b) {
            io::OperatingGrid part;
            part.is_grid = false;
            for (size_t i = a; i < b; ++i) part.points.push_back(v.c.grid.at(i - offset));
            // Progress over the whole job (or shard), not per variant.
            if (opt.progress) {
                const size_t before = a - begin, all = end - begin;
                part_opt.progress = [&opt, before, all](size_t d, size_t) { opt.progress(before + d, all); };
            }
            const auto results = run_map(v.c.model, part, part_opt);
            io::throw_if_interrupted();  // the points run_map skipped are not rows
            const std::string p = prefix(v.values);
            constexpr size_t kBlock = 1 << 16;  // an interrupt is seen between blocks
            for (size_t i = 0; i < results.size(); i += kBlock) {
                io::throw_if_interrupted();
                for (const auto& chunk : csv_row_chunks(v.c.model, results, i, i + kBlock, opt.detail, p, opt.threads))
                    out += chunk;
            }
            res.results.insert(res.results.end(), results.begin(), results.end());
        }
        offset += n;
    }
    return res;
}

namespace {
// Every row of a shard has the header's number of cells, and no cell is a value that is not
// finite ("nan", "inf", "1e999"): an edited or damaged shard is not merged into a map.
void check_shard_rows(const std::string& file, const std::string& header, const std::string& body) {
    const size_t cells = static_cast<size_t>(std::count(header.begin(), header.end(), ',')) + 1;
    int line = 3;
    for (size_t a = 0; a < body.size(); ++line) {
        const size_t e = body.find('\n', a);
        const std::string_view row(body.data() + a, e - a);
        size_t n = 0;
        for (size_t c0 = 0;; ++n) {
            const size_t c1 = std::min(row.find(',', c0), row.size());
            std::string cell(row.substr(c0, c1 - c0));
            char* end = nullptr;
            const double v = cell.empty() ? 0.0 : std::strtod(cell.c_str(), &end);
            if (!cell.empty() && end && *end == '\0' && !std::isfinite(v))
                throw InputError(file, line, static_cast<int>(n + 1), "",
                                 "'" + io::excerpt(cell) + "' is not a finite number (an edited or damaged shard)");
            if (c1 == row.size()) break;
            c0 = c1 + 1;
        }
        if (n + 1 != cells)
            throw InputError(file, line, 0, "", fmt::format("{} cells, the header has {}", n + 1, cells));
        a = e + 1;
    }
}
}  // namespace

std::string merge_shards(const std::vector<std::string>& files) {
    struct Part {
        int index = 0, count = 0;
        size_t begin = 0, end = 0, total = 0;
        std::string job, header, body, file;
        Fingerprint fp;
    };
    std::vector<Part> parts;
    for (const auto& file : files) {
        io::throw_if_interrupted();
        // Only a regular file: opening a FIFO would block before any interrupt could be seen.
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
            throw InputError(file, 0, 0, "", std::filesystem::exists(file, ec) ? "not a regular file (a shard is a CSV file)"
                                                                                : "cannot open shard file");
        const std::string text = io::read_input_file(file, io::kMaxShardFileBytes);
        Part p;
        p.file = file;
        const auto nl1 = text.find('\n');
        const auto nl2 = nl1 == std::string::npos ? std::string::npos : text.find('\n', nl1 + 1);
        char job[17] = {0};
        if (nl2 == std::string::npos ||
            std::sscanf(text.substr(0, nl1).c_str(), "# gearloss shard %d/%d: rows %zu-%zu of %zu, job %16s", &p.index,
                        &p.count, &p.begin, &p.end, &p.total, job) != 6)
            throw InputError(file, 1, 1, "", "not a shard of `gearloss map --shard K/N` (first line)");
        p.job = job;
        const std::string line = text.substr(0, nl1);
        if (const auto semi = line.find("; "); semi != std::string::npos) p.fp = Fingerprint::parse(line.substr(semi + 2));
        p.header = text.substr(nl1 + 1, nl2 - nl1);
        p.body = text.substr(nl2 + 1);
        const size_t rows = static_cast<size_t>(std::count(p.body.begin(), p.body.end(), '\n'));
        if (rows != p.end - p.begin || (!p.body.empty() && p.body.back() != '\n'))
            throw InputError(file, 0, 0, "", fmt::format("has {} rows, the shard line promises {} (incomplete run?)", rows,
                                                         p.end - p.begin));
        check_shard_rows(file, p.header, p.body);
        parts.push_back(std::move(p));
    }
    if (parts.empty()) throw InputError("", 0, 0, "merge", "no shard files given");
    std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.index < b.index; });
    const Part& f = parts.front();
    for (const auto& p : parts) {
        // Name what differs, so the stale or foreign shard can be found and recomputed.
        auto diff = p.fp.differences(f.fp, p.file, f.file);
        if (p.fp.parts().empty() != f.fp.parts().empty())  // not a list of every component
            diff = {"program version (" + (p.fp.parts().empty() ? p.file : f.file) +
                    " has no component fingerprint: written by an older release)"};
        if (diff.empty() && p.job != f.job) diff.push_back("job fingerprint");
        if (diff.empty() && p.header != f.header) diff.push_back("CSV columns");
        if (!diff.empty()) {
            std::string what;
            for (const auto& d : diff) what += (what.empty() ? "" : "; ") + d;
            throw InputError(p.file, 1, 1, "",
                             fmt::format("shard {} differs from {} (not the same map job) in: {}", p.file, f.file, what));
        }
        if (p.count != f.count || p.total != f.total)
            throw InputError(p.file, 1, 1, "",
                             fmt::format("shard {} is {}/{} of {} rows, {} is {}/{} of {} rows: the same job cut "
                                         "differently; recompute with one --shard K/N count",
                                         p.file, p.index, p.count, p.total, f.file, f.index, f.count, f.total));
    }
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i > 0 && parts[i].index == parts[i - 1].index)
            throw InputError(parts[i].file, 1, 1, "", fmt::format("shard {} given twice (also {})", parts[i].index,
                                                                  parts[i - 1].file));
    }
    std::string missing;
    for (int k = 1, i = 0; k <= f.count; ++k) {
        if (i < static_cast<int>(parts.size()) && parts[i].index == k) ++i;
        else missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    }
    if (!missing.empty())
        throw InputError("", 0, 0, "merge", fmt::format("missing shard(s) {} of {}", missing, f.count));
    std::string out = f.header;
    for (const auto& p : parts) {
        io::throw_if_interrupted();
        out += p.body;
    }
    return out;
}

}  // namespace gearloss::map
