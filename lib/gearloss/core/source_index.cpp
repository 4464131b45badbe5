// Where each item and key of a loaded case was written.
#include "gearloss/core/source_index.hpp"

namespace gearloss {

void SourceIndex::add(const std::string& path, const SourceLocation& at) {
    if (at.known()) at_.emplace(path, at);  // the first place a path is written wins
}

namespace {
// "B6.2" -> "B6": the item a numbered copy (`count: N`) comes from; empty when not numbered.
std::string without_copy_number(const std::string& item) {
    const auto dot = item.rfind('.');
    if (dot == std::string::npos || dot + 1 == item.size() ||
        item.find_first_not_of("0123456789", dot + 1) != std::string::npos)
        return {};
    return item.substr(0, dot);
}
}  // namespace

SourceLocation SourceIndex::find(const std::string& section, const std::string& item, const std::string& key) const {
    for (const std::string& name : {item, without_copy_number(item)}) {
        if (!item.empty() && name.empty()) continue;
        std::string base = section;
        if (!name.empty()) base += (base.empty() ? "" : ".") + name;
        // The key and then each of its parents.
        std::string k = key;
        while (!k.empty()) {
            const auto it = at_.find(base.empty() ? k : base + "." + k);
            if (it != at_.end()) return it->second;
            const auto dot = k.rfind('.');
            k = dot == std::string::npos ? std::string() : k.substr(0, dot);
        }
        if (const auto it = at_.find(base); it != at_.end() && !base.empty()) return it->second;
        if (item.empty()) break;
    }
    if (const auto it = at_.find(section); it != at_.end()) return it->second;
    return {file_, 0, 0};
}

}  // namespace gearloss
