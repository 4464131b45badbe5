#pragma once
// Where each item and key of a loaded case was written, kept with the model so that an error
// found after loading (topology, validation, a point out of range) points at its line
// without reading the file again (which may have changed since).
#include <string>
#include <unordered_map>

#include "gearloss/core/errors.hpp"

namespace gearloss {

class SourceIndex {
public:
    // `path`: "section.item.key.subkey" with list items by their name ("bearings.B1_RMS11.C0").
    void add(const std::string& path, const SourceLocation& at);
    // The file the case came from (the answer when nothing deeper is known).
    void set_file(std::string file) { file_ = std::move(file); }
    const std::string& file() const { return file_; }
    // The deepest recorded place of section / item / dotted key: the key, else its parent
    // keys, else the item (a bearing "B6.2" of `count: 2` under "B6"), else the section, else
    // the file alone.
    SourceLocation find(const std::string& section, const std::string& item, const std::string& key) const;
    // Whether the case wrote exactly this path (of two spellings of a setting, the one it used).
    bool has(const std::string& path) const { return at_.count(path) != 0; }
    size_t size() const { return at_.size(); }

private:
    std::unordered_map<std::string, SourceLocation> at_;
    std::string file_;
};

}  // namespace gearloss
