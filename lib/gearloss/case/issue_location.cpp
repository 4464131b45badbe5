#include "gearloss/case/issue_location.hpp"

#include <filesystem>

namespace gearloss::io {

std::optional<YamlNode> find_named_item(const YamlNode& list, const std::string& name) {
    if (!list.is_sequence()) return std::nullopt;
    for (int pass = 0; pass < 2; ++pass) {
        std::string want = name;
        if (pass == 1) {
            const auto dot = name.rfind('.');
            if (dot == std::string::npos || dot + 1 == name.size() ||
                name.find_first_not_of("0123456789", dot + 1) != std::string::npos)
                break;
            want = name.substr(0, dot);
        }
        for (const auto& it : list.items()) {
            if (it.is_scalar() && it.as_string() == want) return it;
            if (it.is_map())
                if (auto n = it.get("name"); n && n->is_scalar() && n->as_string() == want) return it;
        }
    }
    return std::nullopt;
}

namespace {
// Descends a dotted key path as far as it exists.
YamlNode descend(YamlNode n, const std::string& key) {
    size_t start = 0;
    while (start < key.size()) {
        const size_t dot = key.find('.', start);
        const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        auto next = n.get(part);
        if (!next) break;
        n = *next;
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return n;
}
}  // namespace

YamlNode locate_in_case(const YamlNode& root, const std::string& section, const std::string& item,
                        const std::string& key) {
    std::optional<YamlNode> node = root.get(section);
    if (node && section == "oil" && node->is_scalar()) {
        const auto p = std::filesystem::path(root.file()).parent_path() / node->as_string();
        std::error_code ec;
        if (std::filesystem::is_regular_file(p, ec)) {
            const YamlNode oil_root = YamlNode::load_file(p.string());
            node = oil_root.has("oil") ? oil_root.at("oil") : oil_root;
        }
    }
    if (!node) node = root;
    if (!item.empty())
        if (auto it = find_named_item(*node, item)) node = *it;
    return descend(*node, key);
}

namespace {
void index_below(const YamlNode& node, const std::string& prefix, SourceIndex& out, int depth) {
    if (depth > 16) return;  // deeper than any key the model reports (the reader bounds nesting)
    auto join = [&](const std::string& k) { return prefix.empty() ? k : prefix + "." + k; };
    if (node.is_map()) {
        for (const auto& [k, child] : node.entries()) {
            out.add(join(k), child.location());
            index_below(child, join(k), out, depth + 1);
        }
    } else if (node.is_sequence()) {
        // Named items only (gears, bearings, ...): a list of values (speeds, points) is one key.
        if (node.raw().size() == 0 || !node.raw()[0].IsMap()) return;
        for (const auto& it : node.items()) {
            const auto n = it.is_map() ? it.get("name") : std::nullopt;
            if (!n || !n->is_scalar()) continue;
            const std::string name = n->as_string();
            out.add(join(name), it.location());
            index_below(it, join(name), out, depth + 1);
        }
    }
}

// index_below on the yaml-cpp nodes themselves, the same entries in the same order, without a
// YamlNode (its file and key path copied) per node: index_below was a third of the time of
// building a parsed case (a sweep variant), this walk half that. below() is false, `out` partly
// filled, at a key that is not a plain value: index_below then gives the error of
// YamlNode::entries for it (its own walk reaches a key of that kind too, the same one or an
// earlier one).
class FastIndex {
public:
    FastIndex(const std::string& file, SourceIndex& out) : file_(file), out_(out) {}

    bool below(const YAML::Node& node, const std::string& prefix, int depth) {
        if (depth > 16) return true;
        if (node.IsMap()) {
            for (const auto& kv : node) {
                if (!kv.first.IsScalar()) return false;
                const std::string path = join(prefix, kv.first.Scalar());
                add(path, kv.second);
                if (!below(kv.second, path, depth + 1)) return false;
            }
        } else if (node.IsSequence()) {
            if (node.size() == 0 || !node[0].IsMap()) return true;
            for (const auto& item : node) {
                const std::string* name = item.IsMap() ? scalar_name(item) : nullptr;
                if (!name) continue;
                const std::string path = join(prefix, *name);
                add(path, item);
                if (!below(item, path, depth + 1)) return false;
            }
        }
        return true;
    }

private:
    const std::string& file_;
    SourceIndex& out_;

    static std::string join(const std::string& prefix, const std::string& k) { return prefix.empty() ? k : prefix + "." + k; }
    // As YamlNode::location.
    void add(const std::string& path, const YAML::Node& n) {
        const YAML::Mark m = n.Mark();
        if (!m.is_null() && m.line >= 0) out_.add(path, {file_, m.line + 1, m.column + 1});
    }
    // The item's `name` when it is a plain value (as YamlNode::get("name") and is_scalar), else null.
    static const std::string* scalar_name(const YAML::Node& item) {
        for (const auto& kv : item)
            if (kv.first.IsScalar() && kv.first.Scalar() == "name")
                return kv.second.IsScalar() ? &kv.second.Scalar() : nullptr;  // the document's own text
        return nullptr;
    }
};
}  // namespace

void index_sources(const YamlNode& node, const std::string& prefix, SourceIndex& out) {
    if (!prefix.empty()) out.add(prefix, node.location());
    if (!FastIndex(node.file(), out).below(node.raw(), prefix, 0)) index_below(node, prefix, out, 0);
}

}  // namespace gearloss::io
