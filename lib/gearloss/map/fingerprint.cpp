#include "gearloss/map/fingerprint.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <sstream>
#include <yaml-cpp/yaml.h>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::map {

namespace fs = std::filesystem;

Fnv1a& Fnv1a::add(std::string_view s) {
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    h ^= 0xff;
    h *= 1099511628211ull;
    return *this;
}

std::string Fnv1a::hex() const { return fmt::format("{:016x}", h); }

namespace {

// One token of the shard line each: blanks and '=' would split it.
std::string token(std::string s) {
    for (char& c : s)
        if (c == '=' || static_cast<unsigned char>(c) <= ' ') c = '_';
    return s.empty() ? "-" : s;
}

// Every scalar of the case that names a regular file next to the case (as the loader
// resolves it) is an input, `found` with its key path and file path.
void walk_named_files(const YAML::Node& n, const std::string& path, const fs::path& base,
                      const std::function<void(const std::string&, const fs::path&)>& found, int depth) {
    // The operating grid holds speeds and torques, never files: a grid of 10^4 values would
    // cost a file lookup each when a shard starts.
    if (depth > 64 || path == "operating") return;
    if (n.IsScalar()) {
        const std::string& v = n.Scalar();
        std::error_code ec;
        const fs::path p = base / v;
        if (!v.empty() && v.size() < 4096 && fs::is_regular_file(p, ec)) found(path, p);
    } else if (n.IsMap()) {
        for (const auto& kv : n) {
            const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "?";
            walk_named_files(kv.second, path.empty() ? k : path + "." + k, base, found, depth + 1);
        }
    } else if (n.IsSequence()) {
        for (size_t i = 0; i < n.size(); ++i) walk_named_files(n[i], path + "[" + std::to_string(i) + "]", base, found, depth + 1);
    }
}

// Components whose values are short and readable (not hashes): messages show them.
bool readable(const std::string& key) {
    return key == "version" || key == "format" || key == "detail" || key == "thermal" || key == "oil-temp";
}

std::string describe(const std::string& key) {
    if (key == "version") return "program version";
    if (key == "format") return "output format (--format)";
    if (key == "detail") return "per-component columns (--detail)";
    if (key == "thermal") return "thermal mode (fixed oil temperature or stabilised)";
    if (key == "oil-temp") return "oil temperature override (--oil-temp)";
    if (key == "oil-file") return "oil file content (--oil)";
    if (key == "ratio") return "ratio override (--ratio)";
    if (key == "case") return "case file text";
    if (key == "points") return "operating points (--speed, --torque, the case's grid or sweep values)";
    if (key == "file:oil") return "oil file content (the case's 'oil' file)";
    if (key.rfind("file:sweep", 0) == 0) return "content of a file named in the sweep (" + key.substr(5) + ")";
    if (key.rfind("file:", 0) == 0) return "content of the file the case names at '" + key.substr(5) + "'";
    return key;
}

}  // namespace

void Fingerprint::add(const std::string& key, const std::string& value) { parts_.emplace_back(token(key), token(value)); }

uint64_t Fingerprint::total() const {
    Fnv1a f;
    for (const auto& [k, v] : parts_) f.add(k).add(v);
    return f.h;
}

std::string Fingerprint::text() const {
    std::string s;
    for (const auto& [k, v] : parts_) s += (s.empty() ? "" : " ") + k + "=" + v;
    return s;
}

Fingerprint Fingerprint::parse(std::string_view text) {
    Fingerprint fp;
    size_t i = 0;
    while (i < text.size()) {
        const size_t end = std::min(text.find(' ', i), text.size());
        const std::string_view tok = text.substr(i, end - i);
        const size_t eq = tok.find('=');
        if (eq != std::string_view::npos && eq > 0)
            fp.parts_.emplace_back(std::string(tok.substr(0, eq)), std::string(tok.substr(eq + 1)));
        i = end + 1;
    }
    return fp;
}

std::vector<std::string> Fingerprint::differences(const Fingerprint& other, const std::string& name,
                                                  const std::string& other_name) const {
    auto find = [](const Fingerprint& f, const std::string& key) -> const std::string* {
        for (const auto& [k, v] : f.parts_)
            if (k == key) return &v;
        return nullptr;
    };
    // Keys in the order they appear in this fingerprint, then those only the other has.
    std::vector<std::string> keys;
    for (const auto* f : {this, &other})
        for (const auto& kv : f->parts_)
            if (std::find(keys.begin(), keys.end(), kv.first) == keys.end()) keys.push_back(kv.first);
    std::vector<std::string> out;
    for (const auto& key : keys) {
        const std::string* a = find(*this, key);
        const std::string* b = find(other, key);
        if (a && b && *a == *b) continue;
        std::string d = describe(key);
        if (!a || !b)
            d += fmt::format(": in {} only", a ? name : other_name);
        else if (readable(key))
            d += fmt::format(": {} in {}, {} in {}", *a == "-" ? "none" : *a, name, *b == "-" ? "none" : *b, other_name);
        else if (*a == "-" || *b == "-")
            d += fmt::format(": given for {} only", *a == "-" ? other_name : name);
        out.push_back(d);
    }
    return out;
}

std::vector<std::pair<std::string, std::string>> named_files(const JobInputs& in) {
    std::vector<std::pair<std::string, std::string>> out;
    const auto found = [&out](const std::string& path, const fs::path& p) { out.emplace_back(path, p.string()); };
    const fs::path base = fs::path(in.config).parent_path();
    try {
        if (in.parsed.empty()) walk_named_files(YAML::Load(io::read_input_file(in.config, io::kMaxYamlFileBytes)), "", base, found, 0);
        for (const auto& [path, node] : in.parsed) walk_named_files(node, path, base, found, 0);
    } catch (const YAML::Exception& e) {
        throw InputError(in.config, 0, 0, "", "unexpected YAML structure: " + e.msg);
    }
    return out;
}

Fingerprint input_fingerprint(const JobInputs& in) {
    Fingerprint fp;
    fp.add("version", in.version);
    fp.add("format", in.format);
    fp.add("detail", in.detail ? "1" : "0");
    fp.add("oil-temp", in.oil_temperature ? fmt::format("{}K", *in.oil_temperature) : "-");
    fp.add("oil-file", in.oil_file.empty() ? "-" : Fnv1a().add(io::read_input_file(in.oil_file, io::kMaxYamlFileBytes)).hex());
    fp.add("ratio", in.ratio.empty() ? "-" : Fnv1a().add(in.ratio).hex());
    const std::string text = io::read_input_file(in.config, io::kMaxYamlFileBytes);
    fp.add("case", Fnv1a().add(text).hex());
    // Files are hashed by content under the key path that names them, so neither the working
    // directory nor the path used for the case enters the fingerprint.
    for (const auto& [path, file] : in.files ? *in.files : named_files(in))
        fp.add("file:" + token(path), Fnv1a().add(io::read_regular_file(file, io::kMaxCsvFileBytes)).hex());
    return fp;
}

}  // namespace gearloss::map
