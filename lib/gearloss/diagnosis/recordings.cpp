#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/run_order.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <sstream>
#include <map>
#include <unordered_map>
#include <numbers>
#include <optional>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/model/validate.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::diagnosis {

namespace {

constexpr double rpm = std::numbers::pi / 30.0;
// A raw log's time stamps, in seconds, within +-kMaxTime: Unix times (1.7e9 s) fit, and the
// resolution of a double there (1e-4 s) stays far below a sample period; beyond it a
// 5-minute block could no longer be told from the next one.
constexpr double kMaxTime = 1e12;
// Exact duplicate rows named one by one in the warnings; further ones are counted.
constexpr int kDuplicateWarnings = 10;


// A column is a quantity and its unit, "speed_in_rpm", "speed_in_Hz", "speed_in_1/min",
// "speed_in_rad/s", "torque_in_Nm", "P_loss_kW", "oil_temp_C", "oil_temp_K", "time_min":
// the prefix names the quantity, the rest is a unit read by the units module (rotational
// speeds with its convention: Hz and 1/min count revolutions, a bare 1/s is ambiguous).
struct QuantityColumn {
    const char* prefix;
    const char* key;
    const units::Dimension* dim;
    bool temperature;  // an absolute temperature (degC, K, degF)
};
const QuantityColumn kQuantityColumns[] = {
    {"speed_in_", "speed_in", &units::dim::angular_speed, false},  {"speed_out_", "speed_out", &units::dim::angular_speed, false},
    {"torque_in_", "torque_in", &units::dim::torque, false},       {"torque_out_", "torque_out", &units::dim::torque, false},
    {"P_loss_", "loss", &units::dim::power, false},                {"time_", "time", &units::dim::time, false},
    {"oil_temp_", "oil", &units::dim::temperature, true},          {"ambient_temp_", "ambient", &units::dim::temperature, true},
    {"room_temp_", "ambient", &units::dim::temperature, true},     {"wall_temp_", "wall", &units::dim::temperature, true},
};

struct ColumnDef {
    std::string key;
    double scale = 1, offset = 0;  // SI = scale * cell + offset
};

// The definition of a header cell; nullopt for an unknown column. A known
// quantity with a unit that is unknown, of the wrong dimension or ambiguous is an error.
std::optional<ColumnDef> column_definition(const std::string& name, const std::string& file, int line, int col) {
    if (name == "label") return ColumnDef{"label"};
    if (name == "oil") return ColumnDef{"oil_file"};  // the oil of each test (multi-oil campaigns)
    for (const char* c : kRunOrderColumns)  // the order of the tests (run_order.hpp)
        if (name == c) return ColumnDef{std::string("order_") + c};
    for (const auto& q : kQuantityColumns) {
        const std::string prefix = q.prefix;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string unit = name.substr(prefix.size());
        try {
            const units::UnitFactor f = units::parse_unit(unit);
            if (f.dim != *q.dim || f.affine != q.temperature)
                throw units::UnitError(fmt::format("unit '{}' is not {}", unit,
                                                   q.temperature ? "a temperature (C, degC, K)" : units::to_string(*q.dim)));
            if (q.temperature) return ColumnDef{q.key, f.scale, f.offset};
            // The same kind check as a YAML value: a torque in J or Wh, an angle unit in a
            // loss, a speed whose angles repeat are refused naming the column.
            return ColumnDef{q.key, units::checked_value(units::unit_quantity(f), *q.dim, unit), f.offset};
        } catch (const units::UnitError& e) {
            throw InputError(file, line, col, io::excerpt(name), e.message);
        }
    }
    return std::nullopt;
}

struct Table {
    std::vector<std::string> header;
    std::map<std::string, size_t> col;  // key -> column index
    std::vector<ColumnDef> def;         // per column (key empty: unknown)
    std::vector<std::vector<std::string>> rows;
    std::vector<int> lines;
    std::vector<int> data_rows;         // 1 = first data line of the file (exact duplicates merged keep their number)
    char separator = ',';               // detected from the header (io::detect_separator)
};

Table read_table(const std::string& file, const std::string& text, std::vector<std::string>& warnings) {
    io::CsvReader csv(text, file);
    io::CsvRecord rec;
    Table t;
    // A note for the header's messages when the columns are not comma-separated.
    const auto noted = [&](const std::string& msg) {
        const std::string note = io::separator_note(csv.separator());
        return note.empty() ? msg : note + "; " + msg;
    };
    if (!csv.next(rec)) throw InputError(file, csv.line(), 0, "", "no header line");
    int ln = rec.line;
    const std::vector<std::string> header = rec.cells;
    t.separator = csv.separator();
    if (header.size() == 1)
        if (const std::string hint = io::separator_hint(std::string(rec.text)); !hint.empty()) throw InputError(file, ln, 0, "", hint);
    t.header = header;
    t.def.resize(header.size());
    std::vector<std::string> unknown;
    for (size_t i = 0; i < header.size(); ++i) {
        const auto def = column_definition(header[i], file, ln, static_cast<int>(i + 1));
        if (!def) {
            unknown.push_back(fmt::format("{}:{}:{}: unknown column '{}' ignored", file, ln, i + 1, io::excerpt(header[i])));
            continue;
        }
        if (t.col.count(def->key))
            throw InputError(file, ln, static_cast<int>(i + 1), io::excerpt(header[i]),
                             "column duplicates another for the same quantity");
        t.col[def->key] = i;
        t.def[i] = *def;
    }
    // Not one known column: not a recordings file at all (a password file, say). Its first
    // line is not quoted.
    if (t.col.empty())
        throw InputError(file, ln, 0, "",
                         noted("the header names none of the recordings columns (speed_in_rpm, torque_in_Nm, P_loss_W, "
                               "oil_temp_C, time_s, ...); this is not a gearloss recordings CSV file"));
    warnings.insert(warnings.end(), unknown.begin(), unknown.end());
    // Exact duplicates (every cell equal after trimming): a row exported twice would count
    // twice as evidence. Merged into the first, with a warning naming both lines.
    std::unordered_map<std::string, int> first_line;
    int duplicates = 0, data_row = 0;
    while (csv.next(rec)) {
        io::throw_if_interrupted();
        ln = rec.line;
        // A row of empty cells (a spreadsheet's blank row: ",,,,") is no data.
        if (std::all_of(rec.cells.begin(), rec.cells.end(), [](const std::string& c) { return c.empty(); })) continue;
        ++data_row;
        auto& cells = rec.cells;
        if (cells.size() != t.header.size()) {
            std::string msg = fmt::format("row has {} cells, the header has {}", cells.size(), t.header.size());
            if (const std::string hint = io::separator_hint(std::string(rec.text), csv.separator()); !hint.empty())
                msg += "; " + hint;
            else if (const std::string note = io::separator_note(csv.separator()); !note.empty())
                msg += "; " + note;
            throw InputError(file, ln, 0, "", msg);
        }
        std::string key;
        for (const auto& c : cells) key.append(std::to_string(c.size())).append(":").append(c);
        const auto [it, fresh] = first_line.emplace(std::move(key), ln);
        if (!fresh) {
            if (++duplicates <= kDuplicateWarnings)
                warnings.push_back(fmt::format("{}:{}: row repeats line {} exactly; counted once", file, ln, it->second));
            continue;
        }
        t.rows.push_back(std::move(cells));
        t.lines.push_back(ln);
        t.data_rows.push_back(data_row);
    }
    if (duplicates > kDuplicateWarnings)
        warnings.push_back(fmt::format("{}: {} more rows repeat an earlier row exactly; each counted once", file,
                                       duplicates - kDuplicateWarnings));
    if (t.rows.empty()) throw InputError(file, ln, 0, "", "no data rows");
    return t;
}

constexpr double kMaxRecordedLoss = 1e10;             // W
// The plausibility of a recorded point (check_point). A loss beyond the input power by more
// than the rounding of its cells (0.1 %, and 1 mW) is an error; a loss over half the input
// power (efficiency below 50 %) a finding.
constexpr double kPowerRounding = 1e-3, kPowerFloor = 1e-3;
constexpr double kLossShareFinding = 0.5;
// A loss column and the input power less the output power may differ by the torque and
// speed sensors' error: 1 % of the input power (a torque meter's 0.1-0.5 % of full scale
// twice, with margin) or 10 % of the loss, whichever is larger; beyond it a finding.
constexpr double kBalanceShareOfInput = 0.01, kBalanceShareOfLoss = 0.10;
constexpr double kMaxRecordedTemperature = 20273.15;  // K: 20 000 degC (a 9999 degC typo stays an outlier to report)

// Value of `key` in row r, converted to SI by the definition of its header.
double cell(const std::string& file, const Table& t, size_t r, const std::string& key, bool* present = nullptr) {
    const auto it = t.col.find(key);
    if (it == t.col.end() || (present && t.rows[r][it->second].empty())) {
        if (present) *present = false;
        return 0;
    }
    const std::string& s = t.rows[r][it->second];
    const std::string& name = t.header[it->second];
    const int column = static_cast<int>(it->second + 1);
    const double v = io::csv_cell_number(s, file, t.lines[r], column, name, t.separator);
    if (present) *present = true;
    const double si = v * t.def[it->second].scale + t.def[it->second].offset;
    if (!std::isfinite(si))
        throw InputError(file, t.lines[r], column, name, "'" + io::excerpt(s) + "' is out of range (overflows in SI units)");
    // The ranges the model states (gearloss/model/validate.hpp), so that no statistic of the diagnosis
    // overflows: a recording outside them is an error at its cell, not a point to fit.
    std::optional<std::string> fault;
    if (key == "speed_in" || key == "speed_out") fault = solver::speed_fault(si);
    else if (key == "torque_in" || key == "torque_out") fault = solver::torque_fault(si);
    else if (key == "loss" && !(std::abs(si) <= kMaxRecordedLoss))
        fault = fmt::format("loss {:.4g} W beyond the stated range (|P| <= {:g} W)", si, kMaxRecordedLoss);
    else if ((key == "oil" || key == "ambient") && !(si <= kMaxRecordedTemperature))
        fault = fmt::format("temperature {:.4g} degC beyond the stated range (at most {:g} degC)", si - 273.15,
                            kMaxRecordedTemperature - 273.15);
    if (fault) throw InputError(file, t.lines[r], column, name, *fault);
    return si;
}

// Line and column of `key` in row r, for errors about its value.
[[noreturn]] void fail_cell(const std::string& file, const Table& t, size_t r, const std::string& key,
                            const std::string& message) {
    const auto it = t.col.find(key);
    const int column = it == t.col.end() ? 0 : static_cast<int>(it->second + 1);
    throw InputError(file, t.lines[r], column, it == t.col.end() ? key : t.header[it->second], message);
}

// Where `key` stands in row r, "file:line:column (header)", for a finding about its value.
std::string cell_place(const std::string& file, const Table& t, size_t r, const std::string& key) {
    const auto it = t.col.find(key);
    if (it == t.col.end()) return fmt::format("{}:{}", file, t.lines[r]);
    return fmt::format("{}:{}:{} ({})", file, t.lines[r], it->second + 1, io::excerpt(t.header[it->second]));
}

// Where a point's errors and findings go: a cell of a steady row ("file:line:column (header)"),
// or a test of a raw log ("file:line: test 2 (lines 40-940)", the means of its last 30 min).
struct PointPlace {
    std::function<std::string(const std::string& key)> at;                  // for a finding
    std::function<void(const std::string& key, const std::string& msg)> fail;  // an error; throws
};

// A recorded point checked against itself before any fit (the power balance of the gearbox:
// P_in = P_out + P_loss, with P = T omega). Errors: a loss above the input power (it cannot lose
// more than goes in), a negative loss beyond kLossShareFinding of the input power (an output
// power above 1.5 times the input), an output standing still while the input turns. Findings:
// a loss above kLossShareFinding of the input power, any other negative loss (recorded or
// derived), a loss column that contradicts the recorded output torque and speed, oil colder
// than the ambient.
void check_point(const PointPlace& where, const RecordedPoint& p, bool loss_recorded, std::vector<std::string>& findings) {
    const double P_in = p.torque_in * p.speed_in;
    const char* loss_key = loss_recorded ? "loss" : "torque_out";
    // Driven from the input (a negative input power is the output driving: no bound here).
    if (P_in >= 0 && p.loss > P_in * (1 + kPowerRounding) + kPowerFloor)
        where.fail(loss_key, fmt::format("loss {:.6g} W exceeds the input power {:.6g} W (torque_in x speed_in): a gearbox "
                                         "cannot lose more than it is given",
                                         p.loss, P_in));
    if (p.speed_out && *p.speed_out == 0 && p.speed_in > 0)
        where.fail("speed_out", fmt::format("output speed 0 while the input turns at {:.6g} rpm: no gear train does that (a "
                                            "slipping clutch, a gearbox in neutral or a failed sensor)",
                                            p.speed_in / rpm));
    // A negative loss: the output power above the input power. A torque sensor's offset or gain
    // does that at light load (the diagnosis names such an artefact), so it is a finding; beyond
    // half the input power no sensor error explains it (a torque in the wrong unit, columns swapped).
    if (p.loss < 0) {
        const double excess = -p.loss;
        const std::string what = fmt::format("loss {:.6g} W is negative: the output power {:.6g} W exceeds the input power "
                                             "{:.6g} W (torque_in x speed_in)",
                                             p.loss, P_in + excess, P_in);
        if (P_in > 0 && excess > kLossShareFinding * P_in)
            where.fail(loss_key, what + fmt::format(" by more than {:.0f} % of it: a gearbox does not make power ({} in the "
                                                    "wrong unit, or columns swapped?)",
                                                    100 * kLossShareFinding,
                                                    loss_recorded ? "the loss or a torque" : "torque_out or speed_out"));
        findings.push_back(fmt::format("{}: {}: a gearbox does not make power (a torque sensor's offset or gain at light "
                                       "load, or a sign or unit slip?)",
                                       where.at(loss_key), what));
    }
    if (P_in > 0 && p.loss > kLossShareFinding * P_in)
        findings.push_back(fmt::format("{}: loss {:.4g} W is {:.0f} % of the input power {:.4g} W (more than {:.0f} %): a "
                                       "no-load test, or a loss or torque in the wrong unit?",
                                       where.at(loss_recorded ? "loss" : "torque_in"), p.loss, 100 * p.loss / P_in, P_in,
                                       100 * kLossShareFinding));
    if (loss_recorded && p.torque_out && p.speed_out && P_in > 0) {
        const double balance = P_in - std::abs(*p.torque_out * *p.speed_out);
        const double tolerance = std::max(kBalanceShareOfInput * P_in, kBalanceShareOfLoss * std::abs(p.loss));
        if (std::abs(p.loss - balance) > tolerance)
            findings.push_back(fmt::format(
                "{}: recorded loss {:.4g} W contradicts the input power less the output power, {:.4g} W - {:.4g} W = "
                "{:.4g} W (tolerance {:.3g} W: {:.0f} % of the input power or {:.0f} % of the loss, the larger)",
                where.at("loss"), p.loss, P_in, P_in - balance, balance, tolerance, 100 * kBalanceShareOfInput,
                100 * kBalanceShareOfLoss));
    }
    if (p.oil_temp && p.ambient_temp && *p.oil_temp < *p.ambient_temp)
        findings.push_back(fmt::format("{}: oil {:.4g} degC colder than the ambient {:.4g} degC: a running gearbox heats its "
                                       "oil above the ambient (a swapped or failed sensor, or a test still warming up)",
                                       where.at("oil"), *p.oil_temp - 273.15, *p.ambient_temp - 273.15));
}

// Output speeds whose sign differs from most of the others (a negated cell): the ratio check
// compares magnitudes and a log test averages the rows, so neither would see it. `speed_out`
// holds the row index and value of every recorded non-zero output speed.
void check_output_signs(const std::string& file, const Table& t, const std::vector<std::pair<size_t, double>>& speed_out,
                        std::vector<std::string>& findings) {
    size_t negative = 0;
    for (const auto& [r, v] : speed_out) negative += v < 0;
    const size_t positive = speed_out.size() - negative;
    if (negative == positive) return;  // no majority (also none recorded)
    const bool minority_negative = negative < positive;
    const size_t minority = std::min(negative, positive);
    int named = 0;
    for (const auto& [r, v] : speed_out) {
        if ((v < 0) != minority_negative) continue;
        if (++named > kDuplicateWarnings) break;
        findings.push_back(fmt::format("{}: output speed {:.6g} rpm turns the other way from the output speed of {} of the "
                                       "{} rows (a sign lost or added in this row?)",
                                       cell_place(file, t, r, "speed_out"), v / rpm, std::max(negative, positive),
                                       speed_out.size()));
    }
    if (minority > static_cast<size_t>(kDuplicateWarnings))
        findings.push_back(fmt::format("{}: {} more rows with the output speed turning the other way", file,
                                       minority - kDuplicateWarnings));
}

const char* run_order_format(const std::string& c) {
    if (c == "run") return "number";
    if (c == "date") return "date YYYY-MM-DD[ hh:mm[:ss]]";
    return "clock time hh:mm[:ss], date and time YYYY-MM-DD hh:mm, or number";
}

// The run order from the first of `run`, `date` (with `time` as its clock, when both are
// there) or `time` that the file has: a cell that is not such a value is an error at it.
void read_run_order(const std::string& file, const Table& t, Recordings& rec) {
    for (const char* c : kRunOrderColumns) {
        const auto it = t.col.find(std::string("order_") + c);
        if (it == t.col.end()) continue;
        const auto clock = t.col.find("order_time");
        const bool with_clock = std::string(c) == "date" && clock != t.col.end();
        for (size_t r = 0; r < t.rows.size(); ++r) {
            const auto key = run_order_key(c, t.rows[r][it->second]);
            if (!key)
                throw InputError(file, t.lines[r], static_cast<int>(it->second + 1), c,
                                 fmt::format("'{}' is not a {}: the column records the order of the tests (leave it "
                                             "out when that is not known)",
                                             io::excerpt(t.rows[r][it->second]), run_order_format(c)));
            double v = *key;
            if (with_clock) {
                const auto tod = run_order_key("time", t.rows[r][clock->second]);
                if (!tod)
                    throw InputError(file, t.lines[r], static_cast<int>(clock->second + 1), "time",
                                     fmt::format("'{}' is not a clock time hh:mm[:ss]", io::excerpt(t.rows[r][clock->second])));
                v += *tod;
            }
            rec.points[r].run_order = v;
        }
        rec.run_order_column = c;
        return;
    }
}

void require(const std::string& file, const Table& t, const char* key, const char* name) {
    if (!t.col.count(key)) throw InputError(file, 1, 0, name, std::string("required column '") + name + "' is missing");
}

}  // namespace

Recordings read_recordings(const std::string& file, const StabilisationCriterion& crit) {
    // A regular file of at most 64 MiB (a FIFO or a device is refused by name, unread).
    return read_recordings_text(io::read_input_file(file, io::kMaxCsvFileBytes), file, crit);
}

Recordings read_recordings_text(const std::string& text, const std::string& file, const StabilisationCriterion& crit) {
    // The criterion bounds the block loop below: at most window/block + 1 blocks per test.
    if (!(crit.window_s > 0 && crit.block_s > 0 && std::isfinite(crit.window_s) && crit.window_s / crit.block_s <= 1e6 &&
          crit.max_variation >= 0))
        throw InputError("stabilisation criterion: window and block must be positive, at most 1e6 blocks");
    io::check_input_text(text, file, io::kMaxCsvFileBytes);
    Recordings rec;
    rec.file = file;
    Table t = read_table(file, text, rec.warnings);
    if (const auto it = t.col.find("speed_out"); it != t.col.end()) {
        rec.speed_out_column = static_cast<int>(it->second + 1);
        rec.speed_out_header = t.header[it->second];
    }
    auto get = [&](size_t r, const char* key, bool* present = nullptr) { return cell(file, t, r, key, present); };

    require(file, t, "speed_in", "speed_in_rpm");
    require(file, t, "torque_in", "torque_in_Nm");
    if (!t.col.count("time")) {
        if (!t.col.count("loss") && !(t.col.count("torque_out") && t.col.count("speed_out")))
            throw InputError(file, 1, 0, "P_loss_W",
                             "required column 'P_loss_W' is missing (or give torque_out_Nm and speed_out_rpm)");
        std::vector<std::pair<size_t, double>> speed_out;  // row, value: non-zero output speeds
        for (size_t r = 0; r < t.rows.size(); ++r) {
            RecordedPoint p;
            p.row = t.data_rows[r];
            p.line = t.lines[r];
            p.speed_in = get(r, "speed_in");
            p.torque_in = get(r, "torque_in");
            bool has = false;
            double v = get(r, "oil", &has);
            if (has) p.oil_temp = v;
            v = get(r, "ambient", &has);
            if (has) p.ambient_temp = v;
            v = get(r, "torque_out", &has);
            if (has) p.torque_out = v;
            v = get(r, "speed_out", &has);
            if (has) p.speed_out = v;
            v = get(r, "loss", &has);
            if (has) p.loss = v;
            else if (p.torque_out && p.speed_out)
                p.loss = p.torque_in * p.speed_in - std::abs(*p.torque_out * *p.speed_out);
            else
                fail_cell(file, t, r, "loss", "empty loss cell and no output torque and speed");
            if (!std::isfinite(p.loss))
                fail_cell(file, t, r, "torque_out", "the loss from input and output power overflows (not a finite number)");
            if (t.col.count("label")) {
                p.label = t.rows[r][t.col["label"]];
                if (!io::is_printable_utf8(p.label))
                    fail_cell(file, t, r, "label", "'" + io::excerpt(p.label) +
                                                       "': a label must be printable UTF-8 text (save the file as UTF-8)");
            }
            if (t.col.count("oil_file")) {
                p.oil = t.rows[r][t.col["oil_file"]];
                if (!io::is_printable_utf8(p.oil) || p.oil.size() > 4096)
                    fail_cell(file, t, r, "oil_file", "'" + io::excerpt(p.oil) + "': an oil file name must be printable text");
            }
            if (p.speed_in < 0) fail_cell(file, t, r, "speed_in", "negative speed");
            if (p.oil_temp && *p.oil_temp <= 0) fail_cell(file, t, r, "oil", "below absolute zero");
            const PointPlace cell_of_row{
                [&](const std::string& key) { return cell_place(file, t, r, key); },
                [&](const std::string& key, const std::string& msg) { fail_cell(file, t, r, key, msg); }};
            check_point(cell_of_row, p, t.col.count("loss") > 0, rec.warnings);
            if (p.speed_out && *p.speed_out != 0) speed_out.emplace_back(r, *p.speed_out);
            rec.points.push_back(p);
        }
        check_output_signs(file, t, speed_out, rec.warnings);
        read_run_order(file, t, rec);
        return rec;
    }

    // Raw log: split into tests at set-point changes, keep the last 30 min of each.
    rec.from_log = true;
    rec.run_order_column = "time";  // its time stamps order the tests
    if (t.col.count("oil_file"))
        throw InputError(file, 1, static_cast<int>(t.col["oil_file"] + 1), "oil",
                         "the oil column is read in steady-point recordings; give a raw log per oil");
    for (const char* k : {"speed_out", "torque_out", "oil"})
        if (!t.col.count(k))
            throw InputError(file, 1, 0, k, std::string("a raw log needs the column for '") + k +
                                                "' (speed_out_rpm, torque_out_Nm, oil_temp_C)");
    require(file, t, "ambient", "room_temp_C");
    struct Sample {
        double time, n, T, n_out, T_out, oil, room;
        int line;
    };
    std::vector<Sample> s;
    std::vector<std::pair<size_t, double>> log_speed_out;  // row, value: non-zero output speeds
    for (size_t r = 0; r < t.rows.size(); ++r) {
        io::throw_if_interrupted();
        Sample x{get(r, "time"), get(r, "speed_in"), get(r, "torque_in"), get(r, "speed_out"),
                 get(r, "torque_out"), get(r, "oil"), get(r, "ambient"), t.lines[r]};
        if (!(std::abs(x.time) <= kMaxTime))
            fail_cell(file, t, r, "time", fmt::format("time {:g} s is out of range (at most {:g} s in magnitude)", x.time, kMaxTime));
        if (!s.empty() && !(x.time > s.back().time))  // a property of the row, not of a cell
            throw InputError(file, x.line, 0, "time_s", "time must increase from row to row");
        if (!(x.oil > 0)) fail_cell(file, t, r, "oil", "below absolute zero");
        if (!(x.room > 0)) fail_cell(file, t, r, "ambient", "below absolute zero");
        s.push_back(x);
        if (x.n_out != 0) log_speed_out.emplace_back(r, x.n_out);
    }
    check_output_signs(file, t, log_speed_out, rec.warnings);
    // A new test starts when speed or torque leaves the current set-point for
    // 10 consecutive samples (20 s at 0.5 Hz); the set-point is the running mean.
    std::vector<std::pair<size_t, size_t>> tests;
    size_t start = 0, off = 0;
    double sum_n = 0, sum_T = 0;
    size_t count = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (count > 0) {
            const double n_ref = sum_n / count, T_ref = sum_T / count;
            const bool away = std::abs(s[i].n - n_ref) > std::max(0.03 * std::abs(n_ref), 5 * rpm) ||
                              std::abs(s[i].T - T_ref) > std::max(0.05 * std::abs(T_ref), 3.0);
            off = away ? off + 1 : 0;
            if (off >= 10) {
                const size_t cut = i + 1 - off;
                tests.push_back({start, cut});
                start = cut;
                sum_n = sum_T = 0;
                count = 0;
                for (size_t j = cut; j <= i; ++j) {
                    sum_n += s[j].n;
                    sum_T += s[j].T;
                    ++count;
                }
                off = 0;
                continue;
            }
            if (away) continue;
        }
        sum_n += s[i].n;
        sum_T += s[i].T;
        ++count;
    }
    tests.push_back({start, s.size()});
    int number = 0;
    for (const auto& [a, b] : tests) {
        if (b - a < 2) continue;
        ++number;
        RecordedPoint p;
        p.row = number;
        p.run_order = number;
        p.line = s[a].line;
        p.label = fmt::format("test {} (lines {}-{})", number, s[a].line, s[b - 1].line);
        const double t_end = s[b - 1].time;
        const double duration = t_end - s[a].time;
        size_t w0 = a;
        while (w0 < b && s[w0].time < t_end - crit.window_s) ++w0;
        double n = 0, T = 0, no = 0, To = 0, oil = 0, room = 0, loss = 0;
        for (size_t j = w0; j < b; ++j) {
            n += s[j].n;
            T += s[j].T;
            no += s[j].n_out;
            To += s[j].T_out;
            oil += s[j].oil;
            room += s[j].room;
            loss += s[j].T * s[j].n - std::abs(s[j].T_out * s[j].n_out);
        }
        const double k = static_cast<double>(b - w0);
        p.speed_in = n / k;
        p.torque_in = T / k;
        p.speed_out = no / k;
        p.torque_out = To / k;
        p.oil_temp = oil / k;
        p.ambient_temp = room / k;
        p.loss = loss / k;
        for (double x : {p.speed_in, p.torque_in, *p.speed_out, *p.torque_out, *p.oil_temp, *p.ambient_temp, p.loss})
            if (!std::isfinite(x))
                throw InputError(file, p.line, 0, "",
                                 fmt::format("test {} (lines {}-{}): its means overflow (not finite numbers)", number,
                                             s[a].line, s[b - 1].line));
        // Criterion: 5-min block means of (T_oil - T_room) over the last 30 min vary < 0.5 K.
        // The block count is bounded as well as the time: window/block + 1 blocks at most.
        double lo = 1e300, hi = -1e300;
        const double max_blocks = std::ceil(crit.window_s / crit.block_s) + 1;
        int blocks = 0;
        for (double b0 = t_end - crit.window_s; b0 < t_end - 1e-9 && ++blocks <= max_blocks; b0 += crit.block_s) {
            double sum = 0;
            int m = 0;
            for (size_t j = w0; j < b; ++j)
                if (s[j].time >= b0 && s[j].time < b0 + crit.block_s + 1e-9) {
                    sum += s[j].oil - s[j].room;
                    ++m;
                }
            if (m == 0) continue;
            lo = std::min(lo, sum / m);
            hi = std::max(hi, sum / m);
        }
        if (*p.oil_temp < *p.ambient_temp)
            rec.warnings.push_back(fmt::format(
                "{}:{}: test {} (lines {}-{}): oil {:.4g} degC colder than the room {:.4g} degC over its last {:.0f} min: a "
                "running gearbox heats its oil above the room (a swapped or failed sensor?)",
                file, s[a].line, number, s[a].line, s[b - 1].line, *p.oil_temp - 273.15, *p.ambient_temp - 273.15,
                std::min(duration, crit.window_s) / 60));
        // The means of the test checked as a steady point (the power balance, the output turning).
        const std::string test_name = fmt::format("test {} (lines {}-{}, the means of its last {:.0f} min)", number,
                                                  s[a].line, s[b - 1].line, std::min(duration, crit.window_s) / 60);
        const PointPlace test_place{
            [&](const std::string&) { return fmt::format("{}:{}: {}", file, s[a].line, test_name); },
            [&](const std::string& key, const std::string& msg) {
                const auto it = t.col.find(key);
                throw InputError(file, s[a].line, it == t.col.end() ? 0 : static_cast<int>(it->second + 1),
                                 it == t.col.end() ? key : t.header[it->second], test_name + ": " + msg);
            }};
        RecordedPoint means = p;
        means.oil_temp.reset();  // the oil-colder-than-room finding is given below, with the window
        check_point(test_place, means, false, rec.warnings);
        p.stabilisation_drift = hi - lo;
        p.stabilised = duration >= crit.window_s - 1e-6 && p.stabilisation_drift < crit.max_variation;
        if (!p.stabilised)
            rec.warnings.push_back(fmt::format(
                "{}: test {} at {:.0f} rpm / {:.0f} N m never stabilised ((T_oil - T_room) varied {:.2f} K over the "
                "last {:.0f} min; criterion < {:.1f} K)",
                file, number, p.speed_in / rpm, p.torque_in, p.stabilisation_drift,
                std::min(duration, crit.window_s) / 60, crit.max_variation));
        rec.points.push_back(p);
    }
    return rec;
}

}  // namespace gearloss::diagnosis
