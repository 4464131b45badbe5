// The sidecar FILE.meta.json of a CSV output (docs/outputs.md).
#include "gearloss/io/json_text.hpp"
#include "gearloss/map/output_metadata.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/results/reports.hpp"
#include "gearloss/losses/loss_mechanism.hpp"
#include "gearloss/map/fingerprint.hpp"

namespace gearloss::map {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// A number, or null when it is not finite (JSON has no NaN or infinity).
ordered_json number(double v) { return io::json_number(v); }

ordered_json text_or_null(const std::string& s) { return s.empty() ? ordered_json(nullptr) : ordered_json(s); }

ordered_json oil_entry(const lubricant::Oil& oil, const std::string& file) {
    ordered_json o;
    o["name"] = oil.name;
    o["base"] = lubricant::to_string(oil.base);
    o["file"] = text_or_null(file);
    o["max_temperature_C"] = number(oil.max_temperature - 273.15);
    return o;
}

// "transfer-box, oil 75W90-A, ratio 3rd, oil temperature 80 degC (fixed)": for plot titles.
std::string title(const io::Case& c, const MetadataRequest& r) {
    const auto& m = c.model;
    std::string oil = m.oil.name;
    if (!r.oils.empty()) {
        oil.clear();
        for (const auto& o : r.oils) oil += (oil.empty() ? "" : " vs ") + o.oil.name;
    }
    std::string s = fmt::format("{}, oil {}", m.name, oil);
    if (r.ratios.size() > 1) {
        s += ", ratios";
        for (size_t i = 0; i < r.ratios.size(); ++i) s += (i ? ", " : " ") + r.ratios[i];
    } else if (!m.ratio.empty()) {
        s += ", ratio " + m.ratio;
    }
    // A command that describes its own thermal state (a table's temperature axis, a cycle's transient).
    if (r.thermal.is_object() && r.thermal.contains("oil_temperatures_C")) {
        std::string list;
        for (const auto& T : r.thermal["oil_temperatures_C"]) list += (list.empty() ? "" : ", ") + fmt::format("{:g}", T.get<double>());
        s += ", oil temperatures " + list + " degC (fixed)";
    } else if (r.thermal.is_object() && r.thermal.value("mode", "") == "transient") {
        s += ", transient oil temperature";
        if (r.thermal.contains("start_temperature_C") && r.thermal["start_temperature_C"].is_number())
            s += fmt::format(" from {:g} degC", r.thermal["start_temperature_C"].get<double>());
    } else if (m.thermal.mode == solver::ThermalMode::fixed)
        s += fmt::format(", oil temperature {:g} degC (fixed)", m.thermal.oil_temperature - 273.15);
    else
        s += ", stabilised oil temperature";
    return s;
}

const char* unit_of_suffix(const std::string& s) {
    static const std::pair<const char*, const char*> table[] = {
        {"W", "W"},     {"kW", "kW"}, {"C", "degC"}, {"K", "K"},   {"Nm", "N*m"}, {"rpm", "rpm"},
        {"um", "um"},   {"mm", "mm"}, {"m", "m"},    {"s", "s"},   {"Pa", "Pa"},  {"MPa", "MPa"},
        {"GPa", "GPa"}, {"N", "N"},   {"J", "J"},    {"kJ", "kJ"}, {"kg", "kg"},  {"percent", "%"},
        {"mps", "m/s"}, {"kmh", "km/h"}};
    for (const auto& [suffix, unit] : table)
        if (s == suffix) return unit;
    return nullptr;
}

}  // namespace

std::optional<std::string> column_unit(const std::string& name) {
    // "Torque Loss [Nm]" (VECTO): the unit in brackets.
    if (const size_t a = name.rfind('['); a != std::string::npos && name.back() == ']') {
        const std::string u = name.substr(a + 1, name.size() - a - 2);
        const char* known = unit_of_suffix(u);
        return known ? std::string(known) : u;
    }
    if (name == "status" || name.starts_with("status_") || name.ends_with("_status") || name.ends_with("_form") ||
        name.ends_with("_forms") || name == "ratio" || name == "gear" || name == "oil" || name == "cycle")
        return std::nullopt;
    const size_t u = name.rfind('_');
    if (u != std::string::npos)
        if (const char* known = unit_of_suffix(name.substr(u + 1))) return std::string(known);
    return std::string("1");  // mu, lambda, efficiency, ratios: dimensionless
}

std::string case_hash(const io::Case& c) {
    std::string text;
    try {
        text = io::read_input_file(c.file, io::kMaxYamlFileBytes);
    } catch (const std::exception&) {
        return "";  // a case given as text: no file to hash
    }
    Fnv1a h;
    h.add(text);
    std::vector<std::string> files;
    JobInputs in;
    in.config = c.file;
    for (const auto& [path, file] : named_files(in)) {
        h.add(path).add(io::read_regular_file(file, io::kMaxCsvFileBytes));
        files.push_back(fs::weakly_canonical(file).string());
    }
    // Rows taken from the shipped bearing catalogue are inputs too: the data folder is found at
    // run time (GEARLOSS_DATA_DIR) and its file may differ from the one this program shipped with.
    if (std::ranges::any_of(c.bearings_resolved,
                            [](const io::BearingResolution& b) { return b.entry_location.starts_with(io::kShippedCatalogueName); }))
        for (const auto& path : io::shipped_bearing_catalogue("bearings[].designation").paths())
            h.add(io::kShippedCatalogueName).add(io::read_regular_file(path, io::kMaxCsvFileBytes));
    // An oil file that replaced the case's own (--oil) is part of what was computed.
    if (!c.oil_file.empty() &&
        std::find(files.begin(), files.end(), fs::weakly_canonical(c.oil_file).string()) == files.end())
        h.add("--oil").add(io::read_input_file(c.oil_file, io::kMaxYamlFileBytes));
    return h.hex();
}

ordered_json output_metadata(const io::Case& c, const MetadataRequest& r) {
    const auto& m = c.model;
    ordered_json j;
    j["format"] = kMetadataFormat;
    j["gearloss_version"] = GEARLOSS_VERSION;
    j["command"] = r.command;
    j["command_line"] = r.command_line;
    j["case"] = {{"file", c.file}, {"name", m.name}, {"title", title(c, r)}, {"hash", case_hash(c)}};
    if (r.oils.empty()) {
        j["oil"] = oil_entry(m.oil, c.oil_file);
    } else {
        j["oils"] = ordered_json::array();
        for (const auto& o : r.oils) j["oils"].push_back(oil_entry(o.oil, o.file));
    }
    const bool fixed = m.thermal.mode == solver::ThermalMode::fixed;
    j["thermal"] = {{"mode", fixed ? "fixed" : "stabilised"},
                    {"oil_temperature_C", fixed ? number(m.thermal.oil_temperature - 273.15) : ordered_json(nullptr)},
                    {"ambient_C", number(m.thermal.ambient - 273.15)}};
    if (!r.thermal.is_null()) j["thermal"] = r.thermal;
    // i = n_in / n_out, signed (negative: the output turns the other way).
    const double speed_ratio = m.layout.ratio;
    if (r.ratios.size() > 1) {
        // An output over several ratios (a loss table, a drive cycle): each row names its own.
        j["ratio"] = {{"name", nullptr}, {"value", nullptr}, {"names", r.ratios}};
    } else {
        j["ratio"] = {{"name", text_or_null(m.ratio)},
                      {"value", speed_ratio != 0 ? number(1.0 / speed_ratio) : ordered_json(nullptr)}};
    }
    ordered_json forms = ordered_json::object();
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto& mech = m.mechanisms[i];
        for (const auto& a : mech.forms(m)) forms[fmt::format("{}.{}", mech.name(), a.axis)] = mech.form(m, a.axis);
    }
    j["model_forms"] = forms;
    ordered_json mechanisms = ordered_json::object();
    for (size_t i = 0; i < m.mechanisms.size(); ++i)
        mechanisms[std::string(m.mechanisms[i].name())] = m.mechanisms[i].enabled();
    j["mechanisms_enabled"] = mechanisms;
    j["assumed"] = io::assumed_json(c.assumed);
    // The case's plausibility findings (the selected churning form outside its range, ...), as
    // on stderr; absent when there are none.
    if (!c.warnings.empty()) j["findings"] = c.warnings;
    // Bearings taken from a catalogue by designation: which row of which file (absent otherwise).
    ordered_json rows = ordered_json::array();
    for (const auto& b : c.bearings_resolved)
        if (!b.designation.empty())
            rows.push_back(ordered_json{{"bearing", b.bearing}, {"designation", b.designation}, {"row", b.entry},
                            {"location", b.entry_location}});
    if (!rows.empty()) j["bearing_catalogue_rows"] = std::move(rows);
    j["sweep"] = ordered_json::array();
    for (const auto& s : c.sweep) j["sweep"].push_back({{"label", s.label}, {"values", s.values}});
    // A CSV's columns; the metadata inside a JSON document (point --json) describes no CSV.
    if (!r.columns.empty()) j["columns"] = ordered_json::array();
    for (const auto& name : r.columns) {
        std::optional<std::string> unit = column_unit(name);
        const bool text = std::ranges::find(r.text_columns, name) != r.text_columns.end() ||
                          std::ranges::any_of(c.sweep, [&](const io::SweepAxis& s) { return s.label == name; });
        if (text) unit.reset();
        for (const auto& [col, u] : r.units)
            if (col == name) unit = u;
        j["columns"].push_back({{"name", name}, {"unit", unit ? ordered_json(*unit) : ordered_json(nullptr)}});
    }
    return j;
}

std::string vecto_provenance(const io::Case& c) {
    const auto one_line = [](std::string s) {
        std::ranges::replace_if(s, [](char ch) { return ch == '\n' || ch == '\r'; }, ' ');
        return s;
    };
    const auto& m = c.model;
    const bool fixed = m.thermal.mode == solver::ThermalMode::fixed;
    const double speed_ratio = m.layout.ratio;
    std::string s = fmt::format("# gearloss {} torque-loss table (VECTO .vtlm)\n", GEARLOSS_VERSION);
    s += one_line(fmt::format("# case: {} ({}), hash {}", c.file, m.name, case_hash(c))) + "\n";
    s += one_line(fmt::format("# oil: {} ({}){}", m.oil.name, lubricant::to_string(m.oil.base),
                              c.oil_file.empty() ? "" : ", " + c.oil_file)) + "\n";
    s += fixed ? fmt::format("# oil temperature: {:g} degC (fixed)\n", m.thermal.oil_temperature - 273.15)
               : std::string("# oil temperature: stabilised (heat balance per point)\n");
    s += one_line(fmt::format("# gear: {}, i = n_in/n_out = {:.6g}", m.ratio.empty() ? "(single ratio)" : m.ratio,
                              speed_ratio != 0 ? 1.0 / speed_ratio : 0.0)) + "\n";
    return s;
}

ordered_json merged_metadata(const std::vector<std::string>& shards, const std::vector<std::string>& command_line,
                             std::string_view header) {
    ordered_json j;
    if (!shards.empty()) {
        try {
            j = ordered_json::parse(io::read_regular_file(sidecar_path(shards.front()), io::kMaxYamlFileBytes), nullptr, false);
        } catch (const std::exception&) {
            j = nullptr;  // no sidecar next to the shard (or not readable): the keys below only
        }
        if (!j.is_object() || j.value("format", "") != kMetadataFormat) j = nullptr;
    }
    if (j.is_null()) {
        j = ordered_json::object();
        j["format"] = kMetadataFormat;
        j["gearloss_version"] = GEARLOSS_VERSION;
        for (const char* key : {"case", "oil", "thermal", "ratio", "model_forms"}) j[key] = nullptr;
        j["assumed"] = ordered_json::array();
        j["sweep"] = ordered_json::array();
    }
    j["gearloss_version"] = GEARLOSS_VERSION;
    j["command"] = "merge";
    j["command_line"] = command_line;
    j["merged_from"] = shards;
    ordered_json columns = ordered_json::array();
    const auto old = j.contains("columns") && j["columns"].is_array() ? j["columns"] : ordered_json::array();
    for (const auto& name : header_columns(header)) {
        ordered_json unit = column_unit(name) ? ordered_json(*column_unit(name)) : ordered_json(nullptr);
        for (const auto& c : old)  // the shard's sidecar knows the text columns (sweep labels)
            if (c.is_object() && c.value("name", "") == name && c.contains("unit")) unit = c["unit"];
        columns.push_back({{"name", name}, {"unit", unit}});
    }
    j["columns"] = columns;
    return j;
}

std::string header_line(std::string_view text) {
    size_t a = 0;
    while (a < text.size()) {
        const size_t e = std::min(text.find('\n', a), text.size());
        if (text[a] != '#') {
            std::string_view line = text.substr(a, e - a);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            return std::string(line);
        }
        a = e + 1;
    }
    return "";
}

std::vector<std::string> header_columns(std::string_view line) {
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
    if (line.empty()) return {};
    // Cells as gearloss writes them (io::csv_cell): split at commas outside quotes, a quoted
    // cell unquoted ("" inside it is one quote).
    std::vector<std::string> out;
    for (std::string_view raw : io::split_csv_cells(line)) {
        if (raw.size() >= 2 && raw.front() == '"' && raw.back() == '"') {
            std::string s;
            for (size_t i = 1; i + 1 < raw.size(); ++i) {
                s += raw[i];
                if (raw[i] == '"' && raw[i + 1] == '"') ++i;
            }
            out.push_back(std::move(s));
        } else {
            out.emplace_back(raw);
        }
    }
    return out;
}

std::string json_text(const ordered_json& j) {
    // dump() would throw on invalid UTF-8; names and titles are checked UTF-8 when read.
    return j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

std::string sidecar_path(const std::string& csv_path) { return csv_path + io::kSidecarSuffix; }

bool wants_sidecar(const std::string& csv_path) {
    if (csv_path.empty() || csv_path == "-") return false;
    const auto kind = io::resolve_output(csv_path).kind;
    return kind == io::OutputTarget::Kind::regular || kind == io::OutputTarget::Kind::absent;
}

void write_sidecar(const std::string& csv_path, const ordered_json& meta) {
    if (!wants_sidecar(csv_path)) return;
    io::AtomicFile f(sidecar_path(csv_path));
    // dump() would throw on invalid UTF-8; names and titles are checked UTF-8 when read, and
    // anything else (a path from the command line) is replaced rather than refused.
    f.write(json_text(meta));
    f.commit();
}

}  // namespace gearloss::map
