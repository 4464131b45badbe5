#pragma once
// Design-space sweeps: `sweep:` in a case lists named parameters (paths into the case
// document: `oil`, `housing.oil_level`, `gears.w1.face_width` with list items picked by
// their `name`) and the values each takes; `map` runs the cartesian product of all
// axes, each variant the case with its values set (Sweep: one at a time, from the case
// parsed once).
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"

namespace gearloss::io {

// Reads and checks the `sweep` block of a case document (every path must exist). Empty
// when there is none.
std::vector<SweepAxis> read_sweep(const YamlNode& root);

// The variants of a case's sweep, loaded one at a time from the case parsed once: each
// variant's values are set in the parsed document (keeping the line of every node of the
// user's file; a swept value carries the line of that value in the sweep's `values:` list)
// and the case is built and checked from the nodes, never from re-emitted text. A variant
// costs the same whatever the size of the sweep (the sweep block is taken out of the
// document the variants are built from), and each oil file is read once per Sweep.
class Sweep {
public:
    // Reads and parses the file once; `ratio` as load_case. Errors of the file or of its
    // sweep block are InputErrors, as load_case gives them.
    Sweep(const std::string& file, const std::optional<std::string>& ratio);
    // The same from a case's text (io::load_case_text): `name` appears in messages, relative oil
    // files resolve against `base_dir`.
    static Sweep from_text(const std::string& text, const std::string& name, const std::string& base_dir,
                           const std::optional<std::string>& ratio);
    // One Sweep owns its parsed document and edits it: copies would share it.
    Sweep(const Sweep&) = delete;
    Sweep& operator=(const Sweep&) = delete;
    Sweep(Sweep&&) = default;

    size_t size() const { return size_; }                        // variants (1 when the case has no sweep)
    const std::vector<SweepAxis>& axes() const { return axes_; }  // empty without a sweep
    std::vector<std::string> values(size_t v) const;             // the value of each axis, first axis slowest
    std::string tag(size_t v) const;  // "housing.oil_level=-5 mm, oil=oils/X.yaml" (empty without a sweep)
    // Variant v (< size()) loaded and checked exactly as load_case checks a case (every check
    // still applies). An InputError points at the file and line of the user's case (or its oil
    // file): at the value in the sweep's list when the error is about the swept value. Its
    // message names the variant ("... (sweep variant housing.oil_level=-5 mm, oil=oils/X.yaml)").
    // Not thread-safe (it edits the parsed document). The Case has file = the case file and an
    // empty `sweep`. Callers looping over many variants check io::throw_if_interrupted.
    Case variant(size_t v);
    // The case as written (no variant's values set), without its sweep block, and the sweep
    // block: a job's fingerprint walks them instead of parsing the file again.
    std::pair<YAML::Node, YAML::Node> as_written();

private:
    Sweep(YamlNode document, const std::string& file, const std::string& base_dir, const std::optional<std::string>& ratio);
    std::vector<size_t> indices(size_t v) const;  // the value of each axis by its index
    YAML::Node own_node();                        // a new node of pool_
    void restore();                               // the document as the user wrote it again
    YamlNode oil_file(const std::string& path);   // the parsed oil file, read on first use

    std::string file_, base_dir_;
    std::optional<std::string> ratio_;
    YamlNode root_;  // the case as parsed, without its sweep block: variants are built from it
    YAML::Node sweep_block_;  // the sweep block taken out of it
    std::vector<SweepAxis> axes_;
    size_t size_ = 1;
    std::vector<YamlNode> parameters_;  // each axis's `parameter:` node (errors)
    // Nodes that belong to no document (sweep.cpp says why the variants need them).
    YAML::Node pool_;
    std::vector<std::vector<YAML::Node>> values_;  // per axis and value: a pool node sharing the value's data
    std::vector<YAML::Node> slots_;    // the document's nodes the current variant rebound, in order
    std::vector<YAML::Node> before_;   // per binding: a pool node sharing the data its slot held before
    size_t bound_ = 0;                 // bindings made by the current variant
    std::map<std::string, YamlNode> oil_files_;  // by path (base directory joined with the value)
};

struct SweepVariant {
    std::vector<std::string> values;  // one per axis
    Case c;
};

// Every combination (first axis slowest), each loaded as a case (Sweep::variant), all held
// at once; `ratio` as load_case. Stops with an IoError after SIGINT / SIGTERM.
std::vector<SweepVariant> expand_sweep(const std::string& file, const std::optional<std::string>& ratio);

// CSV cell for a value (quoted when it holds a comma or a quote).
std::string csv_cell(const std::string& s);

}  // namespace gearloss::io
