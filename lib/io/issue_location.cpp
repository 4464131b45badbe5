#include "io/issue_location.hpp"

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

}  // namespace gearloss::io
