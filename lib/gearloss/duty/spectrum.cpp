#include "gearloss/duty/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::duty {

namespace {

// The columns of a spectrum: a quantity prefix and its unit ("speed_in_rpm", "duration_h"), read
// by the units module as the recordings' headers are; or a column without a unit.
enum class Column { speed, torque, duration, share, time, ignored };

struct ColumnDef {
    Column what = Column::ignored;
    double scale = 1;  // SI = scale * cell
};

struct Prefixed {
    const char* prefix;
    Column what;
    const units::Dimension* dim;
};
const Prefixed kPrefixed[] = {
    {"speed_in_", Column::speed, &units::dim::angular_speed},
    {"torque_in_", Column::torque, &units::dim::torque},
    {"duration_", Column::duration, &units::dim::time},
    {"time_", Column::time, &units::dim::time},
};

std::optional<ColumnDef> column_definition(const std::string& name, const std::string& file, int line, int col) {
    if (name == "hours") return ColumnDef{Column::duration, 3600.0};
    if (name == "share") return ColumnDef{Column::share, 1.0};
    if (name == "share_%" || name == "share_percent") return ColumnDef{Column::share, 0.01};
    if (name == "label" || name == "bin") return ColumnDef{Column::ignored, 1.0};
    for (const auto& q : kPrefixed) {
        const std::string prefix = q.prefix;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string unit = name.substr(prefix.size());
        try {
            const units::UnitFactor f = units::parse_unit(unit);
            if (f.dim != *q.dim || f.affine)
                throw units::UnitError(fmt::format("unit '{}' is not {}", unit, units::to_string(*q.dim)));
            // The kind checks of a YAML value: a torque in J, a speed whose angles repeat are refused.
            return ColumnDef{q.what, units::checked_value(units::unit_quantity(f), *q.dim, unit)};
        } catch (const units::UnitError& e) {
            throw InputError(file, line, col, io::excerpt(name), e.message);
        }
    }
    return std::nullopt;
}

const char* kHeaderHelp =
    "a duty spectrum names speed_in_<unit> and torque_in_<unit>, and either duration_<unit>, hours, share or "
    "share_% (time at level) or time_<unit> (time series), e.g. speed_in_rpm,torque_in_Nm,hours";

}  // namespace

double Spectrum::total_time() const {
    if (kind == SpectrumKind::time_series) return time.empty() ? 0.0 : time.back() - time.front();
    double t = 0;
    for (double d : duration) t += d;
    return t;
}

Spectrum read_spectrum_text(const std::string& text, const std::string& file, double share_total) {
    io::check_input_text(text, file, io::kMaxCsvFileBytes);
    io::CsvReader csv(text, file);
    io::CsvRecord rec;
    Spectrum s;
    s.file = file;
    const auto noted = [&](const std::string& msg) {
        const std::string note = io::separator_note(csv.separator());
        return note.empty() ? msg : msg + "; " + note;
    };
    if (!csv.next(rec)) throw InputError(file, csv.line(), 0, "", "no header line; " + std::string(kHeaderHelp));
    const int header_line = rec.line;
    const std::vector<std::string> header = rec.cells;
    if (header.size() == 1)
        if (const std::string hint = io::separator_hint(std::string(rec.text)); !hint.empty())
            throw InputError(file, header_line, 0, "", hint);
    std::vector<ColumnDef> def(header.size());
    int col_of[5] = {-1, -1, -1, -1, -1};  // per Column (speed .. time)
    for (size_t i = 0; i < header.size(); ++i) {
        const int c = static_cast<int>(i + 1);
        const auto d = column_definition(header[i], file, header_line, c);
        if (!d) {
            s.warnings.push_back(fmt::format("{}:{}:{}: unknown column '{}' ignored", file, header_line, c, io::excerpt(header[i])));
            continue;
        }
        def[i] = *d;
        if (d->what == Column::ignored) continue;
        int& slot = col_of[static_cast<int>(d->what)];
        // duration and share are one quantity, the weight of a bin.
        const bool weight = d->what == Column::duration || d->what == Column::share;
        const int other = weight ? col_of[static_cast<int>(d->what == Column::duration ? Column::share : Column::duration)] : -1;
        if (slot >= 0 || other >= 0)
            throw InputError(file, header_line, c, io::excerpt(header[i]),
                             fmt::format("column duplicates column {} for the same quantity", (slot >= 0 ? slot : other) + 1));
        slot = static_cast<int>(i);
    }
    const int is = col_of[static_cast<int>(Column::speed)], iq = col_of[static_cast<int>(Column::torque)];
    const int id = col_of[static_cast<int>(Column::duration)], ish = col_of[static_cast<int>(Column::share)];
    const int it = col_of[static_cast<int>(Column::time)];
    const int iw = id >= 0 ? id : ish;
    if (is < 0 || iq < 0 || (iw < 0) == (it < 0)) {
        std::string what = is < 0 ? "no speed_in_<unit> column" : iq < 0 ? "no torque_in_<unit> column"
                           : it >= 0 ? "both a time column and a bin's duration or share: one kind of spectrum only"
                                     : "neither a time column nor a bin's duration or share";
        throw InputError(file, header_line, 0, "", noted(what + "; " + kHeaderHelp));
    }
    s.kind = it >= 0 ? SpectrumKind::time_series : SpectrumKind::time_at_level;
    s.from_share = ish >= 0;
    s.speed_column = is + 1;
    s.torque_column = iq + 1;
    s.speed_header = header[is];
    s.torque_header = header[iq];
    s.weight_column = (it >= 0 ? it : iw) + 1;
    s.weight_header = header[it >= 0 ? it : iw];
    const char sep = csv.separator();
    const auto number = [&](const io::CsvRecord& r, int k) {
        const double v = io::csv_cell_number(r.cells[k], file, r.line, k + 1, header[k], sep) * def[k].scale;
        if (!std::isfinite(v))
            throw InputError(file, r.line, k + 1, header[k], "'" + io::excerpt(r.cells[k]) + "' overflows in SI units");
        return v;
    };
    std::vector<double> weight;
    int last_line = header_line;
    while (csv.next(rec)) {
        io::throw_if_interrupted();
        last_line = rec.line;
        // A spreadsheet's blank row (",,,") is no data.
        if (std::all_of(rec.cells.begin(), rec.cells.end(), [](const std::string& c) { return c.empty(); })) continue;
        if (rec.cells.size() != header.size()) {
            std::string msg = fmt::format("row has {} cells, the header has {}", rec.cells.size(), header.size());
            if (const std::string hint = io::separator_hint(std::string(rec.text), sep); !hint.empty()) msg += "; " + hint;
            throw InputError(file, rec.line, 0, "", noted(msg));
        }
        const double w = number(rec, is), T = number(rec, iq);
        // The model's stated range (gearloss/model/validate.hpp), at the cell.
        if (auto f = solver::speed_fault(w)) throw InputError(file, rec.line, is + 1, header[is], *f);
        if (auto f = solver::torque_fault(T)) throw InputError(file, rec.line, iq + 1, header[iq], *f);
        if (s.kind == SpectrumKind::time_series) {
            const double t = number(rec, it);
            if (!s.time.empty() && !(t > s.time.back()))
                throw InputError(file, rec.line, it + 1, header[it],
                                 fmt::format("time {:g} s does not increase (the row before, line {}, is at {:g} s)", t,
                                             s.line.back(), s.time.back()));
            s.time.push_back(t);
        } else {
            const double x = number(rec, iw);
            if (x < 0)
                throw InputError(file, rec.line, iw + 1, header[iw],
                                 fmt::format("{} {:g}: a bin's {} cannot be negative", s.from_share ? "share" : "duration",
                                             x / def[iw].scale, s.from_share ? "share" : "time"));
            weight.push_back(x);
        }
        s.speed.push_back(w);
        s.torque.push_back(T);
        s.line.push_back(rec.line);
    }
    if (s.kind == SpectrumKind::time_series) {
        if (s.time.size() < 2) throw InputError(file, last_line, 0, "", "a time series needs at least two samples");
        // Gaps: an interval much longer than the series' usual one (the median).
        std::vector<double> dt;
        for (size_t i = 1; i < s.time.size(); ++i) dt.push_back(s.time[i] - s.time[i - 1]);
        std::vector<double> sorted = dt;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double median = sorted[sorted.size() / 2];
        for (size_t i = 0; i < dt.size(); ++i)
            if (dt[i] > kMaxGapFactor * median)
                throw InputError(file, s.line[i + 1], it + 1, header[it],
                                 fmt::format("a gap of {:g} s after line {} (the samples are {:g} s apart otherwise, more "
                                             "than {:g} times that is a gap): fill the gap or split the file",
                                             dt[i], s.line[i], median, kMaxGapFactor));
        return s;
    }
    if (weight.empty()) throw InputError(file, last_line, 0, "", "no bins (no data rows)");
    double sum = 0;
    for (double x : weight) sum += x;
    if (!(sum > 0))
        throw InputError(file, last_line, iw + 1, header[iw],
                         fmt::format("the {} of the bins sum to 0: the spectrum has no time", s.from_share ? "shares" : "durations"));
    if (s.from_share) {
        if (!(share_total > 0 && std::isfinite(share_total)))
            throw InputError("", 0, 0, "--total-time", "the total time the shares are scaled to must be positive");
        for (double& x : weight) x = x / sum * share_total;
    }
    s.duration = std::move(weight);
    return s;
}

Spectrum read_spectrum(const std::string& file, double share_total) {
    // A regular file of at most 64 MiB (a FIFO or a device is refused by name, unread).
    return read_spectrum_text(io::read_input_file(file, io::kMaxCsvFileBytes), file, share_total);
}

}  // namespace gearloss::duty
