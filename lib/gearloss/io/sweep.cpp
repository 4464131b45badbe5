#include "gearloss/io/sweep.hpp"

#include "gearloss/io/interrupt.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
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

// The node at `path` (map keys; in a list the item whose `name` is the segment, or an index).
// Rebinds with reset(): assigning a yaml-cpp node would overwrite the node it refers to.
bool locate(const YAML::Node& root, const std::string& path, YAML::Node& parent, std::string& key, long& index) {
    YAML::Node cur;
    cur.reset(root);
    const auto segs = split_path(path);
    if (segs.empty()) return false;
    for (size_t i = 0; i < segs.size(); ++i) {
        const std::string& s = segs[i];
        const bool last = i + 1 == segs.size();
        if (cur.IsMap()) {
            if (!cur[s].IsDefined()) return false;
            if (last) {
                parent.reset(cur);
                key = s;
                index = -1;
                return true;
            }
            YAML::Node next = cur[s];
            cur.reset(next);
        } else if (cur.IsSequence()) {
            long found = -1;
            for (size_t k = 0; k < cur.size(); ++k) {
                const YAML::Node item = cur[k];
                if (item.IsMap() && item["name"].IsDefined() && item["name"].IsScalar() && item["name"].Scalar() == s) {
                    found = static_cast<long>(k);
                    break;
                }
            }
            if (found < 0) {
                try {
                    size_t pos = 0;
                    const long n = std::stol(s, &pos);
                    if (pos == s.size() && n >= 0 && static_cast<size_t>(n) < cur.size()) found = n;
                } catch (const std::exception&) {
                }
            }
            if (found < 0) return false;
            if (last) {
                parent.reset(cur);
                key.clear();
                index = found;
                return true;
            }
            YAML::Node next = cur[static_cast<size_t>(found)];
            cur.reset(next);
        } else {
            return false;
        }
    }
    return false;
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
            YAML::Node parent;
            std::string key;
            long index = 0;
            if (!locate(root.raw(), path, parent, key, index))
                p.fail("'" + excerpt(path) + "' names no value of this case (use keys separated by '.', list items by name)");
        }
        a.label = a.paths.front();
        for (const auto& v : item.at("values").items()) {
            if (!v.is_scalar()) v.fail("sweep values are single values (a number with its unit, a name or a file)");
            a.values.push_back(v.as_string());
        }
        if (a.values.empty()) item.at("values").fail("empty list");
        variants *= a.values.size();
        if (variants > 100000) item.fail("more than 100 000 sweep variants");
        axes.push_back(a);
    }
    return axes;
}

std::vector<SweepVariant> expand_sweep(const std::string& file, const std::optional<std::string>& ratio) {
    const YamlNode root = YamlNode::load_file(file);
    const auto axes = read_sweep(root);
    const std::string base_dir = std::filesystem::path(file).parent_path().string();
    std::vector<SweepVariant> out;
    size_t n = 1;
    for (const auto& a : axes) n *= a.values.size();
    for (size_t v = 0; v < n; ++v) {
        throw_if_interrupted();  // gearloss/io/interrupt.hpp: SIGINT / SIGTERM stop the expansion
        YAML::Node doc = YAML::Clone(root.raw());
        doc.remove("sweep");
        SweepVariant sv;
        std::string tag;
        size_t rest = v;
        std::vector<size_t> idx(axes.size());
        for (size_t k = axes.size(); k-- > 0;) {  // first axis slowest
            idx[k] = rest % axes[k].values.size();
            rest /= axes[k].values.size();
        }
        for (size_t k = 0; k < axes.size(); ++k) {
            const std::string& value = axes[k].values[idx[k]];
            sv.values.push_back(value);
            tag += (tag.empty() ? "" : ", ") + axes[k].label + "=" + value;
            for (const auto& path : axes[k].paths) {
                YAML::Node parent;
                std::string key;
                long index = 0;
                locate(doc, path, parent, key, index);
                if (index < 0) parent[key] = value;
                else parent[static_cast<size_t>(index)] = value;
            }
        }
        YAML::Emitter em;
        em << doc;
        sv.c = load_case_text(em.c_str(), file + " (sweep " + tag + ")", base_dir, ratio);
        sv.c.file = file;
        out.push_back(std::move(sv));
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
