#include "gearloss/core/issue.hpp"

namespace gearloss {

std::string Issue::path() const {
    std::string p = section;
    if (!item.empty()) p += (p.empty() ? "" : ".") + item;
    if (!key.empty()) p += (p.empty() ? "" : ".") + key;
    return p;
}

std::string Issue::text() const { return path() + ": " + message; }

}  // namespace gearloss
