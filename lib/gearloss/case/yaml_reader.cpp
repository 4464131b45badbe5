#include "gearloss/case/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <fmt/format.h>

#include "gearloss/io/csv_read.hpp"

namespace gearloss::io::detail {
// A key looked up in a mapping by YAML::Node's const operator[] (value_of below), found as a
// std::string key is (the first scalar key equal to it) without two costs of that one, which
// made up a quarter of the time of building a parsed case (a sweep variant): each key compared
// is not copied out of the document (convert<std::string> would copy it), and a key that is
// absent is not turned into text for the invalid node yaml-cpp then returns (key_to_string
// writes a key that can be streamed into a std::stringstream; this one cannot, and an
// optional key is most often absent).
struct KeyRef {
    std::string_view text;
    bool operator==(const KeyRef& other) const { return text == other.text; }
};
}  // namespace gearloss::io::detail

template <>
struct YAML::convert<gearloss::io::detail::KeyRef> {
    static bool decode(const Node& node, gearloss::io::detail::KeyRef& key) {
        if (!node.IsScalar()) return false;
        key.text = node.Scalar();  // the document's own text, alive while the comparison runs
        return true;
    }
};

namespace gearloss::io {

namespace {
// The value of `key` in `map` (a mapping), invalid (IsDefined() false) when absent.
YAML::Node value_of(const YAML::Node& map, const std::string& key) { return map[detail::KeyRef{key}]; }
}  // namespace

YamlNode::YamlNode(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

YamlNode& YamlNode::operator=(const YamlNode& other) {
    if (this != &other) {
        node_.reset(other.node_);
        file_ = other.file_;
        path_ = other.path_;
    }
    return *this;
}

YamlNode YamlNode::load_file(const std::string& file) { return load_text(read_input_file(file, kMaxYamlFileBytes), file); }

namespace {

int line_of(const YAML::Mark& m) { return m.is_null() || m.line < 0 ? 0 : m.line + 1; }
int column_of(const YAML::Mark& m) { return m.is_null() || m.column < 0 ? 0 : m.column + 1; }

// A key as it may appear in a message or a key path: a plain name (letters, digits,
// '_', '-', '.', '+', '/', blanks, printable UTF-8) of at most kExcerptChars, as written;
// anything else (a line of a password file read as a YAML key, say) is not quoted at all.
bool plain_key(const std::string& k) {
    if (k.empty() || k.size() > kExcerptChars || !is_printable_utf8(k)) return false;
    for (unsigned char c : k)
        if (!(std::isalnum(c) || c >= 0x80 || c == '_' || c == '-' || c == '.' || c == '+' || c == '/' || c == ' ' ||
              c == '%' || c == '(' || c == ')'))
            return false;
    return true;
}
std::string key_for_path(const std::string& k) { return plain_key(k) ? k : std::string("<key>"); }

// The structure of the text, from parser events before any node is built: one document,
// at most kMaxDepth nested collections, at most kMaxNodes nodes once every alias is
// expanded (64 levels of `b: &b [*a, *a]` make 2^64 of them in a few kilobytes, which
// any walk over the tree, such as the duplicate-key check, would visit), and no alias
// inside the node it names (a cycle).
class StructureCheck : public YAML::EventHandler {
public:
    static constexpr std::size_t kMaxDepth = 64;
    static constexpr std::uint64_t kMaxNodes = 1000000;

    explicit StructureCheck(const std::string& file) : file_(file) {}

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark& m, YAML::anchor_t a) override { leaf(m, a); }
    void OnScalar(const YAML::Mark& m, const std::string& tag, YAML::anchor_t a, const std::string& value) override {
        check_tag(m, tag);
        check_text(m, value);
        leaf(m, a);
    }
    void OnAlias(const YAML::Mark& m, YAML::anchor_t a) override {
        const auto it = anchors_.find(a);
        if (it == anchors_.end() || !it->second.complete)
            fail(m, "an alias refers to a node that contains it (a cycle)");
        add(m, it->second.count, it->second.height);
    }
    void OnSequenceStart(const YAML::Mark& m, const std::string& tag, YAML::anchor_t a, YAML::EmitterStyle::value) override {
        check_tag(m, tag);
        open(m, a);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& m, const std::string& tag, YAML::anchor_t a, YAML::EmitterStyle::value) override {
        check_tag(m, tag);
        open(m, a);
    }
    void OnMapEnd() override { close(); }

private:
    struct Frame {
        std::uint64_t count;  // nodes in the collection so far, itself included, aliases expanded
        std::size_t height;   // levels of collections in it, itself included
        YAML::anchor_t anchor;
    };
    struct Anchored {
        std::uint64_t count = 0;
        std::size_t height = 0;
        bool complete = false;
    };
    const std::string& file_;
    std::vector<Frame> stack_;
    std::unordered_map<YAML::anchor_t, Anchored> anchors_;
    std::uint64_t total_ = 0;

    [[noreturn]] void fail(const YAML::Mark& m, const std::string& what) const {
        throw InputError(file_, line_of(m), column_of(m), "", what);
    }
    // A tag ("!!binary", "!unit") would change what a value means, and gearloss reads every value
    // by its key: refused rather than dropped. "?" and "!" are the untagged plain and quoted nodes.
    void check_tag(const YAML::Mark& m, const std::string& tag) const {
        if (tag.empty() || tag == "?" || tag == "!") return;
        fail(m, "a YAML tag ('" + excerpt(tag) + "') is not read by gearloss; write the value without it");
    }
    // A value with a control character (a NUL or ESC written as an escape in a quoted string)
    // would be cut short in a path or print raw in a message. A tab and a line break are text.
    void check_text(const YAML::Mark& m, const std::string& value) const {
        for (unsigned char c : value)
            if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7F)
                fail(m, fmt::format("a control character (U+{:04X}) in a value; write printable UTF-8 text", c));
        // C1 controls (U+0080..U+009F, C2 80..C2 9F in UTF-8); bytes that are not UTF-8 at all are
        // refused where the value is read as a name or a title, with its key.
        for (std::size_t i = 0; i + 1 < value.size(); ++i)
            if (static_cast<unsigned char>(value[i]) == 0xC2 && static_cast<unsigned char>(value[i + 1]) >= 0x80 &&
                static_cast<unsigned char>(value[i + 1]) <= 0x9F)
                fail(m, fmt::format("a control character (U+{:04X}) in a value; write printable UTF-8 text",
                                    static_cast<unsigned char>(value[i + 1])));
    }
    // A node of `count` nodes and `height` levels at the current position.
    void add(const YAML::Mark& m, std::uint64_t count, std::size_t height) {
        total_ += count;  // no overflow: every count is at most the total so far, itself at most kMaxNodes
        if (total_ > kMaxNodes)
            fail(m, "too many nodes after alias expansion (more than " + std::to_string(kMaxNodes) +
                        "); a case file is far smaller");
        if (stack_.size() + height > kMaxDepth)
            fail(m, "YAML nested too deeply (more than " + std::to_string(kMaxDepth) + " levels" +
                        (height > 1 ? ", aliases expanded)" : ")"));
        if (!stack_.empty()) {
            stack_.back().count += count;
            stack_.back().height = std::max(stack_.back().height, height + 1);
        }
    }
    void leaf(const YAML::Mark& m, YAML::anchor_t a) {
        add(m, 1, 0);
        if (a != YAML::NullAnchor) anchors_[a] = {1, 0, true};
    }
    void open(const YAML::Mark& m, YAML::anchor_t a) {
        add(m, 1, 1);
        if (!stack_.empty()) stack_.back().count -= 1;  // counted again when the collection closes
        stack_.push_back({1, 1, a});
        if (a != YAML::NullAnchor) anchors_[a] = {};  // open: an alias to it now would be a cycle
    }
    void close() {
        const Frame f = stack_.back();
        stack_.pop_back();
        if (!stack_.empty()) {
            stack_.back().count += f.count;
            stack_.back().height = std::max(stack_.back().height, f.height + 1);
        }
        if (f.anchor != YAML::NullAnchor) anchors_[f.anchor] = {f.count, f.height, true};
    }
};

// Records where a document starts.
class DocumentStart : public YAML::EventHandler {
public:
    std::optional<YAML::Mark> start;
    void OnDocumentStart(const YAML::Mark& m) override { start = m; }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
};

// Line (1-based) of the first document marker ("---" or "...") at the start of a line
// after line `after`, 0 if there is none.
int marker_line_after(const std::string& text, int after) {
    int line = 1;
    for (std::size_t i = 0; i < text.size(); i = text.find('\n', i) + 1, ++line) {
        if (line > after && (text.compare(i, 3, "---") == 0 || text.compare(i, 3, "...") == 0) &&
            (i + 3 >= text.size() || text[i + 3] == ' ' || text[i + 3] == '\t' || text[i + 3] == '\n' ||
             text[i + 3] == '\r'))
            return line;
        if (text.find('\n', i) == std::string::npos) break;
    }
    return 0;
}

// Parses the text once for its structure (see StructureCheck) and for a second document,
// which is an error at its first line even when it is broken or empty: yaml-cpp would
// silently read the first one only.
void check_structure(const std::string& text, const std::string& file) {
    std::istringstream in(text);
    YAML::Parser parser(in);
    StructureCheck first(file);
    if (!parser.HandleNextDocument(first)) return;  // empty: the caller says what is missing
    DocumentStart second;
    int line = 0, column = 0;
    try {
        if (!parser.HandleNextDocument(second)) return;
    } catch (const YAML::Exception& e) {
        if (!second.start) {
            line = marker_line_after(text, 0);
            if (line == 0) line = line_of(e.mark), column = column_of(e.mark);
        }
    }
    if (second.start) line = line_of(*second.start), column = column_of(*second.start);
    throw InputError(file, line, column, "",
                     "a second YAML document starts here; a gearloss file holds exactly one document (remove the "
                     "'---' line and what follows it)");
}

// yaml-cpp keeps the first of two equal keys and drops the second without a word; a
// repeated key in a case file is almost always an edit that did not take effect. The
// walk visits every node as the reader will, aliases expanded, so it counts them and
// stops at kMaxNodes (check_structure has already bounded them; this keeps the walk
// itself bounded whatever built the tree).
void reject_duplicate_keys(const YAML::Node& n, const std::string& file, const std::string& path, std::uint64_t& visited,
                           std::size_t depth = 0) {
    if (++visited > StructureCheck::kMaxNodes) {
        const YAML::Mark m = n.Mark();
        throw InputError(file, line_of(m), column_of(m), path,
                         "too many nodes after alias expansion (more than " + std::to_string(StructureCheck::kMaxNodes) +
                             ")");
    }
    if (depth > StructureCheck::kMaxDepth) {
        const YAML::Mark m = n.Mark();
        throw InputError(file, line_of(m), column_of(m), path,
                         "YAML nested too deeply (more than " + std::to_string(StructureCheck::kMaxDepth) + " levels)");
    }
    if (n.IsMap()) {
        std::unordered_set<std::string> seen;
        for (const auto& kv : n) {
            const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
            const std::string p = path.empty() ? key_for_path(k) : path + "." + key_for_path(k);
            if (kv.first.IsScalar()) {
                if (!seen.insert(k).second) {
                    const YAML::Mark m = kv.first.Mark();
                    throw InputError(file, line_of(m), column_of(m), p,
                                     (plain_key(k) ? "duplicate key '" + k + "'" : std::string("duplicate key")) +
                                         " (an earlier one in the same mapping would win)");
                }
            }
            reject_duplicate_keys(kv.second, file, p, visited, depth + 1);
        }
    } else if (n.IsSequence()) {
        size_t i = 0;
        for (const auto& item : n)
            reject_duplicate_keys(item, file, path + "[" + std::to_string(i++) + "]", visited, depth + 1);
    }
}
}  // namespace

YamlNode YamlNode::load_text(const std::string& text, const std::string& name) {
    check_input_text(text, name, kMaxYamlFileBytes);
    try {
        check_structure(text, name);
        YAML::Node n = YAML::Load(text);
        if (!n.IsMap()) throw InputError(name, 1, 1, "", "expected a YAML mapping at the top level");
        std::uint64_t visited = 0;
        reject_duplicate_keys(n, name, "", visited);
        return YamlNode(n, name, "");
    } catch (const YAML::Exception& e) {
        throw InputError(name, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, "",
                         "YAML syntax error: " + e.msg);
    }
}

SourceLocation YamlNode::location() const {
    const YAML::Mark m = node_.Mark();
    const bool known = !m.is_null() && m.line >= 0;
    return {file_, known ? m.line + 1 : 0, known ? m.column + 1 : 0};
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

bool YamlNode::has(const std::string& key) const {
    if (!node_.IsMap()) return false;
    const YAML::Node c = value_of(node_, key);
    return c.IsDefined() && !c.IsNull();
}

YamlNode YamlNode::at(const std::string& key) const {
    if (!node_.IsMap()) fail("expected a mapping with key '" + key + "'");
    const YAML::Node c = value_of(node_, key);
    const std::string p = path_.empty() ? key : path_ + "." + key;
    if (!c.IsDefined() || c.IsNull()) {
        YamlNode(node_, file_, path_).fail("missing required key '" + key + "'");
    }
    return YamlNode(c, file_, p);
}

std::optional<YamlNode> YamlNode::get(const std::string& key) const {
    if (!node_.IsMap()) return std::nullopt;
    const YAML::Node c = value_of(node_, key);
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
        v.emplace_back(k, YamlNode(kv.second, file_, path_.empty() ? key_for_path(k) : path_ + "." + key_for_path(k)));
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
    const auto known = [&](const std::string& k) {
        return std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; });
    };
    if (path_.empty() && node_.size() > 0) {
        // A file none of whose top-level keys is known is not a gearloss file at all (say
        // /etc/shadow, whose lines read as YAML keys): say so without quoting any of it.
        bool any = false;
        for (const auto& kv : node_) any = any || (kv.first.IsScalar() && known(kv.first.Scalar()));
        if (!any) {
            std::string list;
            for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            fail("none of the top-level keys is a gearloss key; this does not look like a gearloss file (expected "
                 "keys among: " + list + ")");
        }
    }
    for (const auto& kv : node_) {
        const std::string k = key_name(kv.first);
        if (known(k)) continue;
        std::string best;
        size_t bd = 99;
        for (const char* a : allowed) {
            const size_t dd = edit_distance(k, a);
            if (dd < bd) {
                bd = dd;
                best = a;
            }
        }
        std::string msg = plain_key(k) ? "unknown key '" + k + "'" : std::string("unknown key (not a plain name)");
        if (bd <= 3) msg += " (did you mean '" + best + "'?)";
        else {
            msg += "; allowed keys: ";
            bool first = true;
            for (const char* a : allowed) {
                msg += (first ? "" : ", ") + std::string(a);
                first = false;
            }
        }
        YamlNode(kv.first, file_, path_.empty() ? key_for_path(k) : path_ + "." + key_for_path(k)).fail(msg);
    }
}

std::string YamlNode::as_string() const {
    if (!node_.IsScalar()) fail("expected a single value");
    return node_.Scalar();
}

std::string YamlNode::as_name() const {
    const std::string s = as_string();
    if (const std::string why = name_problem(s, kMaxNameBytes); !why.empty()) fail("'" + excerpt(s) + "': " + why);
    return s;
}

std::string YamlNode::as_title() const {
    const std::string s = as_string();
    if (s.empty()) fail("a name cannot be empty");
    if (!is_printable_utf8(s))
        fail("'" + excerpt(s) + "': a name must be printable UTF-8 text without control characters (nor direction controls such as U+202E) or line breaks");
    if (s.size() > kMaxTitleBytes)
        fail("'" + excerpt(s) + "': a name is at most " + std::to_string(kMaxTitleBytes) + " bytes long");
    return s;
}

double YamlNode::as_number() const {
    const std::string s = as_string();
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
        fail("expected a plain number, got '" + excerpt(s) + "'");
    return v;
}

int YamlNode::as_int() const {
    const std::string s = as_string();
    int v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc::result_out_of_range && ptr == s.data() + s.size())
        fail(fmt::format("whole number '{}' out of range (at most {} in magnitude)", excerpt(s), INT_MAX));
    if (ec != std::errc() || ptr != s.data() + s.size()) fail("expected a whole number, got '" + excerpt(s) + "'");
    return v;
}

bool YamlNode::as_bool() const {
    const std::string s = as_string();
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
    fail("expected true or false, got '" + excerpt(s) + "'");
}

double YamlNode::as_quantity(const units::Dimension& expected, const char* example) const {
    return as_kind(expected, units::Kind::plain, example);
}

double YamlNode::as_angle(const char* example) const { return as_kind(units::dim::angle, units::Kind::angle, example); }

double YamlNode::as_kind(const units::Dimension& expected, units::Kind kind, const char* example) const {
    const std::string s = as_string();
    try {
        return units::checked_value(units::parse_quantity(s), expected, s, kind);
    } catch (const units::UnitError& e) {
        fail(e.message + std::string(" (expected e.g. '") + example + "')");
    }
}

double YamlNode::as_temperature() const {
    const std::string s = as_string();
    try {
        return units::absolute_temperature(units::parse_quantity(s), s);
    } catch (const units::UnitError& e) {
        fail(e.message + " (expected e.g. '40 degC')");
    }
}

double YamlNode::positive_quantity(const std::string& key, const units::Dimension& d, const char* example) const {
    const YamlNode n = at(key);
    const double v = n.as_quantity(d, example);
    if (!(v > 0.0)) n.fail("must be positive, got '" + excerpt(n.as_string()) + "'");
    return v;
}

}  // namespace gearloss::io
