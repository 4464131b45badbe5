// gearloss merge: shard files joined into the single-run CSV, streamed. The first two
// lines of every shard (the shard line with the job's fingerprint, and the header) are
// checked against each other before any row is copied; then the rows are copied shard by
// shard, each checked on the way (cells, finite numbers, the promised count).
#include "gearloss/map/job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <string_view>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/line_reader.hpp"

namespace gearloss::map {

namespace {
struct Part {
    int index = 0, count = 0;
    size_t begin = 0, end = 0, total = 0;
    std::string job, header, file;
    Fingerprint fp;
};

// The shard line and the header of `file`.
Part read_head(const std::string& file) {
    // Only a regular file: opening a FIFO would block before any interrupt could be seen.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw InputError(file, 0, 0, "", std::filesystem::exists(file, ec) ? "not a regular file (a shard is a CSV file)"
                                                                            : "cannot open shard file");
    io::LineReader in(file);
    Part p;
    p.file = file;
    std::string_view first, header;
    char job[17] = {0};
    if (!in.next(first) || !in.last_line_ended() || !in.next(header) || !in.last_line_ended() ||
        std::sscanf(std::string(first).c_str(), "# gearloss shard %d/%d: rows %zu-%zu of %zu, job %16s", &p.index, &p.count,
                    &p.begin, &p.end, &p.total, job) != 6)
        throw InputError(file, 1, 1, "", "not a shard of `gearloss map --shard K/N` (first line)");
    p.job = job;
    if (const auto semi = first.find("; "); semi != std::string_view::npos) p.fp = Fingerprint::parse(first.substr(semi + 2));
    p.header = std::string(header) + "\n";
    return p;
}

// What each column of a map may hold: the sweep's values (any text) before `speed_in_rpm`,
// the status in `status`, and numbers (or nothing) everywhere else.
struct Columns {
    size_t count = 0, labels = 0, status = size_t(-1);
    explicit Columns(const std::string& header) {
        const auto cells = io::split_csv_cells(std::string_view(header).substr(0, header.size() - 1));  // without the '\n'
        count = cells.size();
        for (size_t i = 0; i < cells.size(); ++i) {
            if (cells[i] == "speed_in_rpm" && labels == 0) labels = i;
            if (cells[i] == "status") status = i;
        }
    }
};

bool is_status(std::string_view s) {
    return s == "ok" || s == "above_oil_limit" || s == "no_equilibrium" || s.rfind("out_of_range: ", 0) == 0;
}

// A row has the header's cells, each what its column holds as gearloss writes it: a number in
// plain decimal or exponent form (no sign '+', blank, hexadecimal, "nan" or "inf"), or nothing;
// a status the solver gives. An edited or damaged shard is not merged into a map.
void check_row(const std::string& file, int line, std::string_view row, const Columns& columns) {
    const auto cells = io::split_csv_cells(row);
    if (cells.size() != columns.count) {
        // A shard saved again by a spreadsheet in a locale with decimal commas: ';' between cells.
        const std::string hint = io::separator_hint(std::string(row));
        throw InputError(file, line, 0, "",
                         fmt::format("{} cells, the header has {}{}", cells.size(), columns.count, hint.empty() ? "" : "; " + hint));
    }
    for (size_t i = columns.labels; i < cells.size(); ++i) {
        const std::string_view cell = cells[i];
        const auto fail = [&](const std::string& why) {
            throw InputError(file, line, static_cast<int>(i + 1), "", "'" + io::excerpt(cell) + "' " + why);
        };
        if (i == columns.status) {
            if (!is_status(cell)) fail("is not a status of a map point (an edited or damaged shard)");
            continue;
        }
        if (cell.empty()) continue;
        double v = 0;
        const io::CellNumber kind = io::read_cell_number(cell, v);
        if (kind == io::CellNumber::not_finite) fail("is not a finite number (an edited or damaged shard)");
        if (kind == io::CellNumber::not_number) fail("is not a number as gearloss writes one (an edited or damaged shard)");
    }
}

// The rows of one shard to `write`, checked.
void copy_rows(const Part& p, const TextSink& write) {
    io::LineReader in(p.file);
    std::string_view line;
    in.next(line);  // shard line and header, read and checked before
    in.next(line);
    const Columns columns(p.header);
    const size_t promised = p.end - p.begin;
    size_t rows = 0;
    bool ended = true;
    std::string out;
    while (in.next(line)) {
        if ((rows & 4095) == 0) io::throw_if_interrupted();
        ++rows;
        ended = in.last_line_ended();
        if (rows > promised) continue;  // counted for the message below
        check_row(p.file, in.line_number(), line, columns);
        out.append(line);
        out += '\n';
        if (out.size() >= (size_t{1} << 20)) {
            write(out);
            out.clear();
        }
    }
    if (!ended)
        throw InputError(p.file, in.line_number(), 0, "", "the last row has no line end: the shard was cut (incomplete run?)");
    if (rows != promised)
        throw InputError(p.file, in.line_number(), 0, "",
                         fmt::format("has {} rows, the shard line promises {} (incomplete run?)", rows, promised));
    write(out);
}
}  // namespace

void merge_shards(const std::vector<std::string>& files, const TextSink& write) {
    std::vector<Part> parts;
    for (const auto& file : files) {
        io::throw_if_interrupted();
        parts.push_back(read_head(file));
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
        // The rows a shard of this cut must hold: a line edited to another range is refused.
        const auto [b, e] = Shard{p.index, p.count}.range(p.total);
        if (p.index < 1 || p.index > p.count || p.begin != b || p.end != e)
            throw InputError(p.file, 1, 1, "",
                             fmt::format("shard {}/{} of {} rows holds rows {}-{}, not {}-{} (an edited shard line)", p.index,
                                         p.count, p.total, b, e, p.begin, p.end));
    }
    for (size_t i = 1; i < parts.size(); ++i)
        if (parts[i].index == parts[i - 1].index)
            throw InputError(parts[i].file, 1, 1, "", fmt::format("shard {} given twice (also {})", parts[i].index,
                                                                  parts[i - 1].file));
    std::string missing;
    for (int k = 1, i = 0; k <= f.count; ++k) {
        if (i < static_cast<int>(parts.size()) && parts[i].index == k) ++i;
        else missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    }
    if (!missing.empty())
        throw InputError("", 0, 0, "merge", fmt::format("missing shard(s) {} of {}", missing, f.count));
    write(f.header);
    for (const auto& p : parts) copy_rows(p, write);
}

std::string merge_shards(const std::vector<std::string>& files) {
    std::string out;
    merge_shards(files, [&out](std::string_view s) { out += s; });
    return out;
}

}  // namespace gearloss::map
