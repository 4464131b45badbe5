#pragma once
// The sidecar FILE.meta.json written next to every CSV gearloss writes to a file: what the
// file was computed from (program version, command line, case and its hash, oil, thermal
// mode, ratio, model forms, the values the case left to defaults, sweep axes) and what each
// column holds (name and unit). Schema "gearloss-metadata/1", every key in docs/outputs.md.
// In map/ rather than results/ because the case hash follows the files the case names
// (map::named_files, the rule `merge` uses for its fingerprint).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"

namespace gearloss::map {

inline constexpr const char* kMetadataFormat = "gearloss-metadata/1";

// One oil of a comparison ("oils": [...] instead of "oil").
struct MetadataOil {
    lubricant::Oil oil;
    std::string file;  // the oil file as given ("" = inline in the case)
};

struct MetadataRequest {
    std::string command = {};               // "map", "compare", ...
    std::vector<std::string> command_line = {};  // argv as given
    std::vector<std::string> columns = {};  // the CSV header, in order
    std::vector<std::string> text_columns = {};  // columns holding text (unit null) besides status and sweep labels
    std::vector<MetadataOil> oils = {};     // compare: every oil, the reference first (then "oils" replaces "oil")
    // Unit of a column whose name does not say it (column_unit's answer otherwise).
    std::vector<std::pair<std::string, std::string>> units = {};
    // Replaces the "thermal" object when not null (a drive cycle: "mode": "transient").
    nlohmann::ordered_json thermal = {};
    // Every ratio the output covers when it is more than the case's one (a loss table, a drive
    // cycle): the title lists them and "ratio" gives their names instead of one ratio.
    std::vector<std::string> ratios = {};
};

// The unit a column's name carries ("P_mesh_W": "W", "oil_temp_C": "degC", "Torque Loss [Nm]":
// "N*m", "efficiency": "1"), or nullopt for a text column (status, form names).
std::optional<std::string> column_unit(const std::string& name);

// FNV-1a (64 bit, hex) of the case text, every file it names (its oil file, sweep files, by
// key path and content) and an oil file that replaced its oil (--oil): one character changed
// in any of them changes it; the directory it is run from does not. Empty when the case file
// cannot be read (a case given as text).
std::string case_hash(const io::Case& c);

// The sidecar document for an output computed from `c` (the case as the command used it:
// --oil, --oil-temp and --ratio applied).
nlohmann::ordered_json output_metadata(const io::Case& c, const MetadataRequest& r);

// The sidecar of `gearloss merge`'s output: the first shard's sidecar (every shard is one job,
// merge checked their fingerprints) with the merge's command line, "merged_from" and the
// columns of `header_line`; without a readable shard sidecar, the keys that need no case
// (case, oil, thermal, ratio... null).
nlohmann::ordered_json merged_metadata(const std::vector<std::string>& shards, const std::vector<std::string>& command_line,
                                       std::string_view header_line);

// The header of a CSV text: its first line that does not start with '#' (without the newline).
std::string header_line(std::string_view csv_text);
// The cells of a CSV line gearloss wrote (a header's column names): split at commas outside
// quotes, quoted cells unquoted.
std::vector<std::string> header_columns(std::string_view header_line);

// The '#' provenance lines at the top of a VECTO table (program version, case file, name and
// hash, oil, oil temperature, gear and its ratio). VECTO's CSV reader skips lines that start
// with '#' (VECTO source, TU Graz for the European Commission, VectoCore/Utils/VectoCSVFile.cs:
// ReadCSV parses with CommentTokens = {"#"}, and its own writer starts files with a
// "# VECTO <version>" line), so the table reads as before. Each line is one line: line breaks
// in a name or path are replaced by blanks.
std::string vecto_provenance(const io::Case& c);

// A JSON document as gearloss writes it: indented by 2, one trailing newline, non-finite
// numbers as null, invalid UTF-8 (a path from the command line) replaced, never refused.
std::string json_text(const nlohmann::ordered_json& j);

// "map.csv" -> "map.csv.meta.json".
std::string sidecar_path(const std::string& csv_path);
// Whether an output path gets a sidecar: a file, not standard output ("-", /dev/stdout) or a
// device, FIFO or descriptor (io::OutputTarget).
bool wants_sidecar(const std::string& csv_path);
// Writes `meta` (indented, one trailing newline; non-finite numbers as null) to
// sidecar_path(csv_path) atomically (io::AtomicFile: inside a command's OutputTransaction it
// appears together with the CSV, or neither does). Nothing for standard output.
void write_sidecar(const std::string& csv_path, const nlohmann::ordered_json& meta);

}  // namespace gearloss::map
