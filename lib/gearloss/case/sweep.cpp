// Sweep variants from the case parsed once: the values are set by rebinding nodes of the
// parsed document, the case is built from the nodes (load_case_node), and the document is
// returned to the user's case before the next variant.
//
// How a value is set, and why a variant changes neither the values nor another variant.
// A yaml-cpp node (detail::node) refers to a node_ref that holds its data (scalar, children,
// Mark). YAML::Node::operator=(const Node&) calls set_ref: the node the handle names now
// refers to the other node's node_ref (data and Mark shared, nothing copied or written), and
// then the handle itself moves to the other node (so repoint() works on a copy of the handle).
// Apart from taking the `sweep` key out of the top-level mapping once, this file writes no data
// into the document (no scalar, tag, type or child is set; the loader reads through const
// YamlNode): it only re-points nodes, so every node_ref keeps what the parser gave it.
// A node re-pointed is re-pointed everywhere it appears: yaml-cpp makes an alias the very node
// of its anchor. That is wanted for a swept node with aliases in the case (they change with it,
// as they did in the copy the old expansion edited: yaml-cpp clones aliases as aliases). But an
// alias may also make a node of the case an item of a `values:` list (`values: [*fw, ...]`, or
// `ambient: *t` with `values: [&t 20 degC, ...]`), and re-pointing it would change that value
// for the later axes of the variant. So the values are taken from nodes of pool_, a sequence of
// our own that no path of the case reaches, each re-pointed once, when the Sweep is made, at a
// value's node_ref: they keep the value as written, and its Mark (its line in the user's file),
// whatever happens to the case's nodes. Likewise before_ (pool nodes too) keeps the node_ref
// each slot had before the variant re-pointed it, and restore() puts them back in reverse
// order: every variant starts from the document as parsed, as each variant of the old
// expansion started from a fresh copy, and a path is resolved as it was there (after the
// earlier axes of the same variant only).
#include "gearloss/case/sweep.hpp"

#include <algorithm>

#include "gearloss/io/interrupt.hpp"
#include "gearloss/units/ranges.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <yaml-cpp/yaml.h>

namespace gearloss::io {

namespace {
std::vector<std::string> split_path(const std::string& p) {
    std::vector<std::string> out;
    std::string seg;
    std::stringstream ss(p);
    while (std::getline(ss, seg, '.')) out.push_back(seg);
    return out;
}

// The node at `path` (map keys; in a list the item whose `name` is the segment, or an index),
// or nothing. Const lookups only: yaml-cpp's non-const operator[] adds an (undefined) entry to
// a mapping for a key it does not find, and a list item at index size().
std::optional<YAML::Node> find_node(const YAML::Node& root, const std::string& path) {
    const auto segs = split_path(path);
    if (segs.empty()) return std::nullopt;
    YAML::Node cur;
    cur.reset(root);  // reset, not operator=: that would re-point the node `cur` names
    for (const std::string& s : segs) {
        const YAML::Node& here = cur;
        YAML::Node next;
        if (here.IsMap()) {
            const YAML::Node child = here[s];  // an invalid node when absent (reset would throw)
            if (!child.IsDefined()) return std::nullopt;
            next.reset(child);
        } else if (here.IsSequence()) {
            long found = -1;
            for (size_t k = 0; k < here.size(); ++k) {
                const YAML::Node item = here[k];
                if (item.IsMap() && item["name"].IsDefined() && item["name"].IsScalar() && item["name"].Scalar() == s) {
                    found = static_cast<long>(k);
                    break;
                }
            }
            if (found < 0) {
                try {
                    size_t pos = 0;
                    const long n = std::stol(s, &pos);
                    if (pos == s.size() && n >= 0 && static_cast<size_t>(n) < here.size()) found = n;
                } catch (const std::exception&) {
                }
            }
            if (found < 0) return std::nullopt;
            next.reset(here[static_cast<size_t>(found)]);
        } else {
            return std::nullopt;
        }
        cur.reset(next);
    }
    return cur;
}

// Points `node` at the data of `data` (set_ref, see the top of this file), writing no data.
// Node::operator= then moves the handle it was called on to `data`'s node, so it is called on
// a copy: `node` keeps naming the same node for the next rebinding.
void repoint(const YAML::Node& node, const YAML::Node& data) {
    YAML::Node handle(node);
    handle = data;
}

// At most this many values on one axis (and variants in all): each variant is a case loaded.
constexpr size_t kMaxSweepVariants = 100000;

// The values of one axis: each item of its `values:` list as written, and a numeric range
// START:STOP:STEP ("2 mm:10 mm:2 mm", "40:100:20 degC"; units/ranges.hpp) as its values. `range`
// is false for an item taken as written (a name, a file, a number with its unit).
struct AxisValue {
    std::string text;
    YamlNode item;
    bool range = false;
};
std::vector<AxisValue> axis_values(const YamlNode& values) {
    std::vector<AxisValue> out;
    for (const auto& v : values.items()) {
        if (!v.is_scalar()) v.fail("sweep values are single values (a number with its unit, a name or a file)");
        const std::string text = v.as_string();
        if (!units::is_range(text)) {
            out.push_back({text, v, false});
            continue;
        }
        try {
            for (auto& t : units::expand_range(text, "", kMaxSweepVariants)) out.push_back({std::move(t), v, true});
        } catch (const units::UnitError& e) {
            v.fail(e.message);
        }
    }
    return out;
}
}  // namespace

std::vector<SweepAxis> read_sweep(const YamlNode& root) {
    std::vector<SweepAxis> axes;
    const auto sw = root.get("sweep");
    if (!sw) return axes;
    size_t variants = 1;
    for (const auto& item : sw->items()) {
        item.allow_keys({"parameter", "values", "note"});
        SweepAxis a;
        const YamlNode p = item.at("parameter");
        if (p.is_sequence())
            for (const auto& x : p.items()) a.paths.push_back(x.as_string());
        else
            a.paths.push_back(p.as_string());
        if (a.paths.empty()) p.fail("empty list of parameters");
        for (const auto& path : a.paths) {
            if (path.rfind("sweep", 0) == 0) p.fail("a sweep cannot vary itself");
            if (!find_node(root.raw(), path))
                p.fail("'" + excerpt(path) + "' names no value of this case (use keys separated by '.', list items by name)");
            // Set twice, one column would label values the other replaced.
            for (const auto& other : axes)
                if (std::find(other.paths.begin(), other.paths.end(), path) != other.paths.end())
                    p.fail("'" + excerpt(path) + "' is already set by the sweep's axis '" + excerpt(other.label) + "'");
            if (std::count(a.paths.begin(), a.paths.end(), path) > 1) p.fail("'" + excerpt(path) + "' is listed twice");
        }
        a.label = a.paths.front();
        for (const auto& v : axis_values(item.at("values"))) a.values.push_back(v.text);
        if (a.values.empty()) item.at("values").fail("empty list");
        if (a.values.size() > kMaxSweepVariants) item.fail("more than 100 000 sweep variants");
        variants *= a.values.size();
        if (variants > kMaxSweepVariants) item.fail("more than 100 000 sweep variants");
        axes.push_back(a);
    }
    return axes;
}

Sweep::Sweep(const std::string& file, const std::optional<std::string>& ratio)
    : Sweep(YamlNode::load_file(file), file, std::filesystem::path(file).parent_path().string(), ratio) {}

Sweep Sweep::from_text(const std::string& text, const std::string& name, const std::string& base_dir,
                       const std::optional<std::string>& ratio) {
    return Sweep(YamlNode::load_text(text, name), name, base_dir, ratio);
}

Sweep::Sweep(YamlNode document, const std::string& file, const std::string& base_dir, const std::optional<std::string>& ratio)
    : file_(file),
      base_dir_(base_dir),
      ratio_(ratio),
      root_(std::move(document)),
      axes_(read_sweep(root_)),
      pool_(YAML::NodeType::Sequence) {
    if (axes_.empty()) return;
    const std::vector<YamlNode> items = root_.at("sweep").items();
    for (size_t k = 0; k < axes_.size(); ++k) {
        size_ *= axes_[k].values.size();
        parameters_.push_back(items[k].at("parameter"));
        auto& held = values_.emplace_back();
        held.reserve(axes_[k].values.size());
        for (const auto& v : axis_values(items[k].at("values"))) {
            if (v.range) {
                // A value of a range is a scalar of its own (written nowhere in the file: an error
                // about it names the variant, "(sweep variant ...=310 rpm)", not a line).
                pool_.push_back(YAML::Node(v.text));
                held.push_back(pool_[pool_.size() - 1]);
                continue;
            }
            held.push_back(own_node());
            repoint(held.back(), v.item.raw());
        }
        for (size_t p = 0; p < axes_[k].paths.size(); ++p) before_.push_back(own_node());
    }
    slots_.resize(before_.size());
    // The variants are built without the sweep block, so that one costs the same whatever the
    // sweep's size; the values stay alive in pool_.
    YAML::Node root(root_.raw());
    sweep_block_.reset(root["sweep"]);
    root.remove("sweep");
}

std::pair<YAML::Node, YAML::Node> Sweep::as_written() {
    restore();
    return {root_.raw(), sweep_block_};
}

YAML::Node Sweep::own_node() {
    // Every node is created in pool_'s memory: a node of its own memory would merge the whole
    // document's memory into it when first re-pointed (yaml-cpp's memory_holder::merge), once
    // per node. pool_ absorbs the document's memory once, at the first re-pointing.
    pool_.push_back(YAML::Node(YAML::NodeType::Null));
    return pool_[pool_.size() - 1];
}

void Sweep::restore() {
    while (bound_ > 0) {
        --bound_;
        repoint(slots_[bound_], before_[bound_]);
    }
}

std::vector<size_t> Sweep::indices(size_t v) const {
    std::vector<size_t> idx(axes_.size());
    for (size_t k = axes_.size(); k-- > 0;) {  // first axis slowest
        idx[k] = v % axes_[k].values.size();
        v /= axes_[k].values.size();
    }
    return idx;
}

std::vector<std::string> Sweep::values(size_t v) const {
    if (v >= size_) throw std::out_of_range("sweep variant " + std::to_string(v) + " of " + std::to_string(size_));
    std::vector<std::string> out;
    const auto idx = indices(v);
    for (size_t k = 0; k < axes_.size(); ++k) out.push_back(axes_[k].values[idx[k]]);
    return out;
}

YamlNode Sweep::oil_file(const std::string& path) {
    auto it = oil_files_.find(path);
    if (it == oil_files_.end()) it = oil_files_.emplace(path, YamlNode::load_file(path)).first;
    return it->second;
}

Case Sweep::variant(size_t v) {
    const auto idx = indices(v);
    const std::string tag = this->tag(v);
    restore();
    try {
        for (size_t k = 0; k < axes_.size(); ++k)
            for (const auto& path : axes_[k].paths) {
                // Found anew after the earlier axes, as the old expansion did: an earlier axis
                // may have changed what the path names (a list item's `name`), or removed it.
                const auto slot = find_node(root_.raw(), path);
                if (!slot) parameters_[k].fail("'" + excerpt(path) + "' names no value once the earlier axes are set");
                repoint(before_[bound_], *slot);
                slots_[bound_].reset(*slot);
                ++bound_;
                repoint(*slot, values_[k][idx[k]]);
            }
        return load_case_node(root_, file_, base_dir_, ratio_, [this](const std::string& p) { return oil_file(p); });
    } catch (const InputError& e) {
        if (tag.empty()) throw;
        throw InputError(e.file, e.line, e.column, e.key, e.message + " (sweep variant " + tag + ")");
    }
}

std::string Sweep::tag(size_t v) const {
    const auto vals = values(v);
    std::string t;
    for (size_t k = 0; k < axes_.size(); ++k) t += (t.empty() ? "" : ", ") + axes_[k].label + "=" + vals[k];
    return t;
}

std::vector<SweepVariant> expand_sweep(const std::string& file, const std::optional<std::string>& ratio) {
    Sweep sweep(file, ratio);
    std::vector<SweepVariant> out;
    out.reserve(sweep.size());
    for (size_t v = 0; v < sweep.size(); ++v) {
        throw_if_interrupted();  // gearloss/io/interrupt.hpp: SIGINT / SIGTERM stop the expansion
        out.push_back({sweep.values(v), sweep.variant(v)});
    }
    return out;
}

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace gearloss::io
