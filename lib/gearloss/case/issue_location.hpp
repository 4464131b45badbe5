#pragma once
// Points an issue found after loading (solver::Issue, gearbox::TopologyError: section,
// item name, dotted key) back at the line of the case description it comes from.
#include <optional>
#include <string>

#include "gearloss/core/source_index.hpp"
#include "gearloss/case/yaml_reader.hpp"

namespace gearloss::io {

// The item of a list by its `name` (or its scalar value); a bearing of `count: N` is
// listed once under the name without its ".k" suffix.
std::optional<YamlNode> find_named_item(const YamlNode& list, const std::string& name);

// The node of `section` / `item` / dotted `key` below the case's root, as deep as it
// exists (the root when the section is absent). An "oil" section that names a separate
// file is looked up in that file.
YamlNode locate_in_case(const YamlNode& root, const std::string& section, const std::string& item,
                        const std::string& key);

// Records where every key and list item below `node` was written, under `prefix`, with list
// items by their `name`, as SourceIndex::find looks them up.
void index_sources(const YamlNode& node, const std::string& prefix, SourceIndex& out);

}  // namespace gearloss::io
