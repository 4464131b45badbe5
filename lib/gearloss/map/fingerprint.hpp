#pragma once
// The fingerprint of a map job, component by component. The first line of every shard
// carries it, so `gearloss merge` joins only shards of one job and, when they differ,
// says in what (the case text, a file it reads, an override, the program version...).
// Files are hashed by content, never by path: the same job run from another directory,
// or with the case named by another relative path, still merges; an oil file edited
// under the same name does not.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <yaml-cpp/yaml.h>

namespace gearloss::map {

// FNV-1a, 64 bit: small, and the same on every build and platform (std::hash is
// neither), so shards written on different machines or by different builds compare.
struct Fnv1a {
    uint64_t h = 14695981039346656037ull;
    Fnv1a& add(std::string_view s);  // s, then a separator ("ab","c" and "a","bc" differ)
    std::string hex() const;         // 16 lowercase hex digits
};

// What a map job is computed from besides its rows' keys (the CLI fills it in).
struct JobInputs {
    std::string config = {};                 // case file: its text and every file it names
    std::string oil_file = {};               // --oil ("" = none): its content
    std::optional<double> oil_temperature = {};  // --oil-temp as resolved [K]
    std::string ratio = {};                  // --ratio ("" = none)
    std::string format = "csv";              // --format
    bool detail = false;                     // --detail
    std::string version = GEARLOSS_VERSION;  // another release may compute other rows
    // The case already parsed, as (key path, node) pairs to walk for the files it names
    // (io::Sweep::as_written: the case, then its sweep block under "sweep"); empty: the
    // file is parsed here.
    std::vector<std::pair<std::string, YAML::Node>> parsed = {};
    // named_files(...) when the caller has it already (it costs a file lookup per value).
    std::optional<std::vector<std::pair<std::string, std::string>>> files = {};
};

class Fingerprint {
public:
    // Keys and values hold no blanks and no '=' (values are hashes, numbers or names).
    void add(const std::string& key, const std::string& value);
    const std::vector<std::pair<std::string, std::string>>& parts() const { return parts_; }
    uint64_t total() const;    // one hash of every component (the shard line's `job`)
    std::string text() const;  // "key=value key=value ..."
    // Inverse of text(); tokens that are not key=value are ignored.
    static Fingerprint parse(std::string_view text);
    // The components that differ from `other`, in words, with both values where they are
    // readable: "oil temperature override (--oil-temp): 333.15K in a.csv, 393.15K in b.csv".
    std::vector<std::string> differences(const Fingerprint& other, const std::string& name,
                                         const std::string& other_name) const;

private:
    std::vector<std::pair<std::string, std::string>> parts_;
};

// The files the case names (its oil file, files given as sweep values...), as the loader
// resolves them: (key path, file path) pairs. From `in.parsed` when given, else the file.
std::vector<std::pair<std::string, std::string>> named_files(const JobInputs& in);

// Reads the case file, every file it names (relative to its directory, as the loader
// resolves them: its oil file, files given as sweep values, ...) and the --oil file.
// Throws InputError when one cannot be read.
Fingerprint input_fingerprint(const JobInputs& in);

}  // namespace gearloss::map
