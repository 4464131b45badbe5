#pragma once
// A YAML node with its file and key path, so that every read can fail with an
// error naming the file, line and key, and unknown keys are caught.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::io {

// Assignment rebinds the handle only (YAML::Node::reset): YAML::Node's own assignment
// would overwrite the document's data with the other node's.
class YamlNode {
public:
    YamlNode(YAML::Node node, std::string file, std::string path);
    YamlNode(const YamlNode&) = default;
    YamlNode(YamlNode&&) = default;
    YamlNode& operator=(const YamlNode& other);
    YamlNode& operator=(YamlNode&& other) { return *this = static_cast<const YamlNode&>(other); }
    ~YamlNode() = default;
    // Reads a regular file of at most kMaxYamlFileBytes (see read_input_file), then load_text.
    static YamlNode load_file(const std::string& file);
    // Parses `text`; `name` is the file name used in messages. Bounded: the text as in
    // check_input_text, one document only, at most 64 levels of nesting and at most
    // 1,000,000 nodes once aliases are expanded, no alias inside the node it names, no
    // duplicate keys; the top level is a mapping.
    static YamlNode load_text(const std::string& text, const std::string& name);

    const std::string& file() const { return file_; }
    const std::string& path() const { return path_; }
    const YAML::Node& raw() const { return node_; }
    bool is_map() const { return node_.IsMap(); }
    bool is_sequence() const { return node_.IsSequence(); }
    bool is_scalar() const { return node_.IsScalar(); }
    bool has(const std::string& key) const;

    // Where the node was written (line 0 when unknown).
    SourceLocation location() const;
    [[noreturn]] void fail(const std::string& message) const;
    // "file:line:col: key.path: message", for warnings that point at this node.
    std::string located(const std::string& message) const;

    YamlNode at(const std::string& key) const;                 // required
    std::optional<YamlNode> get(const std::string& key) const; // optional
    std::vector<YamlNode> items() const;                       // sequence elements
    std::vector<std::pair<std::string, YamlNode>> entries() const;  // map entries

    // Rejects keys that are not in `allowed`, suggesting the closest one.
    void allow_keys(std::initializer_list<const char*> allowed) const;

    std::string as_string() const;
    // The name of a component (gear, shaft, mesh, bearing, seal, clutch) or of a case or oil:
    // not empty, at most kMaxNameBytes, printable UTF-8 (no control character, no line
    // break), and no ',' or '"' (names become CSV column names).
    static constexpr std::size_t kMaxNameBytes = 64;
    std::string as_name() const;
    // The title of a case or an oil: not empty, at most kMaxTitleBytes, printable UTF-8 on one line.
    static constexpr std::size_t kMaxTitleBytes = 200;
    std::string as_title() const;
    double as_number() const;             // plain number, no unit
    int as_int() const;
    bool as_bool() const;
    // Quantity with a unit of the expected dimension, converted to SI.
    double as_quantity(const units::Dimension& expected, const char* example) const;
    // An angle, written with its unit ("20 deg", "0.35 rad"); a bare number is an error.
    double as_angle(const char* example) const;
    // Temperature: "40 degC" / "313.15 K" (absolute).
    double as_temperature() const;
    template <class E>
    E as_enum(std::initializer_list<std::pair<const char*, E>> choices) const {
        const std::string s = as_string();
        std::string list;
        for (const auto& [name, value] : choices) {
            if (s == name) return value;
            list += (list.empty() ? "" : ", ") + std::string(name);
        }
        fail("'" + excerpt(s) + "' is not one of: " + list);
    }

    // Shorthands for required/optional keys.
    double quantity(const std::string& key, const units::Dimension& d, const char* example) const {
        return at(key).as_quantity(d, example);
    }
    std::optional<double> opt_quantity(const std::string& key, const units::Dimension& d, const char* example) const {
        auto n = get(key);
        if (!n) return std::nullopt;
        return n->as_quantity(d, example);
    }
    double positive_quantity(const std::string& key, const units::Dimension& d, const char* example) const;

private:
    double as_kind(const units::Dimension& expected, units::Kind kind, const char* example) const;
    std::string key_name(const YAML::Node& key) const;
    YAML::Node node_;
    std::string file_;
    std::string path_;
};

}  // namespace gearloss::io
