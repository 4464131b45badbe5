#pragma once
// Reading REXS files into the model of gearloss/rexs/model.hpp:
//   .rexs   XML (pugixml)
//   .rexsj  JSON (nlohmann-json)
//   .rexsz  a zip archive (libzip) holding exactly one .rexs or .rexsj model (other members,
//           such as the gear files REXS allows beside the model, are left alone); ".zip" too.
// Another extension is read by its first bytes ('<' XML, '{' JSON, "PK" zip).
// Bounded like every reader of gearloss: at most kMaxRexsBytes of model text (also for the
// member inside an archive, checked against what is read, not what the archive claims), at
// most kMaxRexsDepth levels of nesting, at most kMaxRexsArchiveEntries members; XML entities
// of a document type are never expanded (pugixml has no DTD support), JSON has no aliases.
// The version must be one of 1.0 .. 1.6. Every failure is an InputError naming the file (and
// the component, relation or attribute when known).
#include <cstddef>
#include <string>
#include <string_view>

#include "gearloss/rexs/model.hpp"

namespace gearloss::rexs {

inline constexpr std::size_t kMaxRexsBytes = std::size_t{64} << 20;  // 64 MiB of XML or JSON
inline constexpr int kMaxRexsDepth = 32;
inline constexpr int kMaxRexsArchiveEntries = 1000;

// Reads the file by its extension (or first bytes); `shown` names it in messages (default: path).
Model read_model(const std::string& path, const std::string& shown = "");

// From text in memory; `shown` names it in messages.
Model parse_xml(std::string_view text, const std::string& shown);
Model parse_json(std::string_view text, const std::string& shown);

// The versions gearloss reads ("1.0" .. "1.6"); InputError naming the file otherwise.
void check_version(const std::string& version, const std::string& shown);

}  // namespace gearloss::rexs
