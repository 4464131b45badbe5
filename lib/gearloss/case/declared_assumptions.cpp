// The case's own `assumed:` list (declared_assumptions.hpp).
#include "gearloss/case/declared_assumptions.hpp"

#include <optional>
#include <string>

#include "gearloss/case/config_internal.hpp"

namespace gearloss::io {
namespace {

// The node a key path names: mapping keys, and a list item by its `name`.
std::optional<YamlNode> node_at(const YamlNode& root, const std::string& path) {
    std::optional<YamlNode> cur = root;
    size_t begin = 0;
    while (cur && begin <= path.size()) {
        const size_t end = std::min(path.find('.', begin), path.size());
        const std::string seg = path.substr(begin, end - begin);
        if (seg.empty()) return std::nullopt;
        if (cur->is_map()) {
            cur = cur->get(seg);
        } else if (cur->is_sequence()) {
            std::optional<YamlNode> found;
            for (const auto& item : cur->items())
                if (item.is_map() && item.has("name") && item.at("name").is_scalar() && item.at("name").as_string() == seg)
                    found = item;
            cur = found;
        } else {
            return std::nullopt;
        }
        begin = end + 1;
    }
    return cur;
}

// The value as the case writes it: a scalar, "[a, b]" for a list, "{k: v}" for a mapping.
std::string value_text(const YamlNode& n, int depth = 0) {
    if (n.is_scalar()) return n.as_string();
    if (depth > 4) return "...";
    std::string s;
    if (n.is_sequence()) {
        for (const auto& item : n.items()) s += (s.empty() ? "" : ", ") + value_text(item, depth + 1);
        return "[" + s + "]";
    }
    if (n.is_map()) {
        for (const auto& [k, v] : n.entries()) s += (s.empty() ? "" : ", ") + k + ": " + value_text(v, depth + 1);
        return "{" + s + "}";
    }
    return "~";
}

}  // namespace

void read_declared_assumptions(const YamlNode& root, std::vector<AssumedValue>& out, const std::string& prefix) {
    const auto list = root.get("assumed");
    if (!list) return;
    if (!list->is_sequence()) list->fail("a list of {key, reason, source} entries (docs/config.md)");
    for (const auto& e : list->items()) {
        if (!e.is_map()) e.fail("an entry is {key: housing.oil_level, reason: ..., source: ...}");
        e.allow_keys({"key", "reason", "source"});
        const std::string key = e.at("key").as_string();
        const auto value = node_at(root, key);
        if (!value || key.starts_with("assumed"))
            e.at("key").fail("'" + excerpt(key) + "' names no value of the case (a key path such as housing.oil_level or "
                             "bearings.B1.D; a list item by its name)");
        const std::string reason = e.at("reason").as_title();
        const std::string source = e.has("source") ? e.at("source").as_title() : std::string("the case");
        out.push_back({prefix + key, excerpt(value_text(*value), 200), reason, detail::located_at(value->location()), source});
    }
}

}  // namespace gearloss::io
