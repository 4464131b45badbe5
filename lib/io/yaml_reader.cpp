#include "io/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace gearloss::io {

YamlNode::YamlNode(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

YamlNode YamlNode::load_file(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file, 0, 0, "", "cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return load_text(ss.str(), file);
}

namespace {
// yaml-cpp keeps the first of two equal keys and drops the second without a word; a
// repeated key in a case file is almost always an edit that did not take effect.
void reject_duplicate_keys(const YAML::Node& n, const std::string& file, const std::string& path, int depth = 0) {
    if (depth > 64) return;  // the reader's own nesting limits apply further down
    if (n.IsMap()) {
        std::vector<std::string> seen;
        for (const auto& kv : n) {
            const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
            const std::string p = path.empty() ? k : path + "." + k;
            if (kv.first.IsScalar()) {
                if (std::find(seen.begin(), seen.end(), k) != seen.end()) {
                    const YAML::Mark m = kv.first.Mark();
                    throw InputError(file, m.is_null() ? 0 : m.line + 1, m.is_null() ? 0 : m.column + 1, p,
                                     "duplicate key '" + k + "' (an earlier one in the same mapping would win)");
                }
                seen.push_back(k);
            }
            reject_duplicate_keys(kv.second, file, p, depth + 1);
        }
    } else if (n.IsSequence()) {
        size_t i = 0;
        for (const auto& item : n) reject_duplicate_keys(item, file, path + "[" + std::to_string(i++) + "]", depth + 1);
    }
}
}  // namespace

YamlNode YamlNode::load_text(const std::string& text, const std::string& name) {
    try {
        YAML::Node n = YAML::Load(text);
        if (!n.IsMap()) throw InputError(name, 1, 1, "", "expected a YAML mapping at the top level");
        reject_duplicate_keys(n, name, "");
        return YamlNode(n, name, "");
    } catch (const YAML::Exception& e) {
        throw InputError(name, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, "",
                         "YAML syntax error: " + e.msg);
    }
}

void YamlNode::fail(const std::string& message) const {
    const YAML::Mark m = node_.Mark();
    const bool known = !m.is_null() && m.line >= 0;
    throw InputError(file_, known ? m.line + 1 : 0, known ? m.column + 1 : 0, path_, message);
}

std::string YamlNode::located(const std::string& message) const {
    const YAML::Mark m = node_.Mark();
    const bool known = !m.is_null() && m.line >= 0;
    return InputError::format(file_, known ? m.line + 1 : 0, known ? m.column + 1 : 0, path_, message);
}

bool YamlNode::has(const std::string& key) const { return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull(); }

YamlNode YamlNode::at(const std::string& key) const {
    if (!node_.IsMap()) fail("expected a mapping with key '" + key + "'");
    const YAML::Node c = node_[key];
    const std::string p = path_.empty() ? key : path_ + "." + key;
    if (!c.IsDefined() || c.IsNull()) {
        YamlNode(node_, file_, path_).fail("missing required key '" + key + "'");
    }
    return YamlNode(c, file_, p);
}

std::optional<YamlNode> YamlNode::get(const std::string& key) const {
    if (!node_.IsMap()) return std::nullopt;
    const YAML::Node c = node_[key];
    if (!c.IsDefined() || c.IsNull()) return std::nullopt;
    return YamlNode(c, file_, path_.empty() ? key : path_ + "." + key);
}

std::vector<YamlNode> YamlNode::items() const {
    if (!node_.IsSequence()) fail("expected a list");
    std::vector<YamlNode> v;
    size_t i = 0;
    for (const auto& c : node_) v.emplace_back(c, file_, path_ + "[" + std::to_string(i++) + "]");
    return v;
}

std::string YamlNode::key_name(const YAML::Node& key) const {
    if (!key.IsScalar()) YamlNode(key, file_, path_).fail("keys must be plain names, not lists or mappings");
    return key.Scalar();
}

std::vector<std::pair<std::string, YamlNode>> YamlNode::entries() const {
    if (!node_.IsMap()) fail("expected a mapping");
    std::vector<std::pair<std::string, YamlNode>> v;
    for (const auto& kv : node_) {
        const std::string k = key_name(kv.first);
        v.emplace_back(k, YamlNode(kv.second, file_, path_.empty() ? k : path_ + "." + k));
    }
    return v;
}

namespace {
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> d(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t prev = d[0];
        d[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t cur = d[j];
            d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
            prev = cur;
        }
    }
    return d[b.size()];
}
}  // namespace

void YamlNode::allow_keys(std::initializer_list<const char*> allowed) const {
    if (!node_.IsMap()) fail("expected a mapping");
    for (const auto& kv : node_) {
        const std::string k = key_name(kv.first);
        if (std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; })) continue;
        std::string best;
        size_t bd = 99;
        for (const char* a : allowed) {
            const size_t dd = edit_distance(k, a);
            if (dd < bd) {
                bd = dd;
                best = a;
            }
        }
        std::string msg = "unknown key '" + k + "'";
        if (bd <= 3) msg += " (did you mean '" + best + "'?)";
        else {
            msg += "; allowed keys: ";
            bool first = true;
            for (const char* a : allowed) {
                msg += (first ? "" : ", ") + std::string(a);
                first = false;
            }
        }
        YamlNode(kv.first, file_, path_.empty() ? k : path_ + "." + k).fail(msg);
    }
}

std::string YamlNode::as_string() const {
    if (!node_.IsScalar()) fail("expected a single value");
    return node_.Scalar();
}

double YamlNode::as_number() const {
    const std::string s = as_string();
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
        fail("expected a plain number, got '" + s + "'");
    return v;
}

int YamlNode::as_int() const {
    const std::string s = as_string();
    int v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size()) fail("expected a whole number, got '" + s + "'");
    return v;
}

bool YamlNode::as_bool() const {
    const std::string s = as_string();
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
    fail("expected true or false, got '" + s + "'");
}

double YamlNode::as_quantity(const units::Dimension& expected, const char* example) const {
    const std::string s = as_string();
    units::Quantity q;
    try {
        q = units::parse_quantity(s);
    } catch (const units::UnitError& e) {
        fail(e.msg + std::string(" (expected e.g. '") + example + "')");
    }
    if (q.dim != expected) {
        if (q.dim == units::dim::none && expected != units::dim::none)
            fail("'" + s + "' has no unit; write it with a unit, e.g. '" + example + "'");
        fail("'" + s + "' has dimension " + units::to_string(q.dim) + ", expected " + units::to_string(expected) +
             " (e.g. '" + example + "')");
    }
    if (q.absolute_temperature)
        fail("'" + s + "' is a temperature; a temperature difference or rate was expected (e.g. '" + example + "')");
    try {
        return units::as_rotational_speed(q, s);
    } catch (const units::UnitError& e) {
        fail(e.msg + std::string(" (expected e.g. '") + example + "')");
    }
}

double YamlNode::as_temperature() const {
    const std::string s = as_string();
    units::Quantity q;
    try {
        q = units::parse_quantity(s);
    } catch (const units::UnitError& e) {
        fail(e.msg + " (expected e.g. '40 degC')");
    }
    if (!q.absolute_temperature) fail("'" + s + "' is not a temperature; write e.g. '40 degC' or '313.15 K'");
    if (!(q.value > 0.0)) fail("'" + s + "' is below absolute zero");
    return q.value;
}

double YamlNode::positive_quantity(const std::string& key, const units::Dimension& d, const char* example) const {
    const YamlNode n = at(key);
    const double v = n.as_quantity(d, example);
    if (!(v > 0.0)) n.fail("must be positive, got '" + n.as_string() + "'");
    return v;
}

}  // namespace gearloss::io
