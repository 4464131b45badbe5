#include "gearloss/case/bearing_catalogue.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <mutex>
#include <numbers>

#include "gearloss/bearings/designation.hpp"
#include "gearloss/io/data_dir.hpp"
#include "gearloss/case/yaml_reader.hpp"

namespace gearloss::io {

namespace {
constexpr double mm = 1e-3, kN = 1e3;

// One row of a series block, read by its block's column names.
void read_row(const YamlNode& row, const std::vector<std::string>& cols, CatalogueEntry& e) {
    const auto cells = row.items();
    if (cells.size() != cols.size())
        row.fail(fmt::format("a row has {} values, the series' columns are {}", cells.size(), cols.size()));
    std::map<std::string, double> v;
    for (size_t i = 1; i < cols.size(); ++i) {
        const double x = cells[i].as_number();
        if (!(x > 0)) cells[i].fail("'" + cols[i] + "' must be a positive number");
        v[cols[i]] = x;
    }
    e.designation = cells[0].as_string();
    const auto k = bearings::designation_key(e.designation);
    if (!k) cells[0].fail("'" + excerpt(e.designation) + "' is not a bearing designation (letters, then digits)");
    e.key = k->key;
    e.d = v.at("d") * mm;
    e.D = v.at("D") * mm;
    if (e.D <= e.d) row.fail(fmt::format("D = {} mm must exceed d = {} mm", v.at("D"), v.at("d")));
    if (v.count("T")) {
        e.T = v.at("T") * mm;
        e.B = *e.T;
        if (v.count("B")) e.cone_width = v.at("B") * mm;
    } else {
        e.B = v.at("B") * mm;
    }
    if (v.count("C")) e.C = v.at("C") * kN;
    if (v.count("C0")) e.C0 = v.at("C0") * kN;
    // The static rating against the dynamic one: C0/C lies near 0.4-0.8 for ball bearings and
    // 1-3 for needle and roller bearings (the shipped rows: 0.40-2.9); outside 0.2-6 a digit or a
    // decimal point was lost (three shipped needle rows had one).
    if (e.C && e.C0 && !(*e.C0 / *e.C >= 0.2 && *e.C0 / *e.C <= 6))
        row.fail(fmt::format("C0 = {} kN against C = {} kN (C0/C = {:.3g}): rolling bearings have C0/C between about 0.2 "
                             "and 6; a digit or a decimal point is likely lost",
                             v.at("C0"), v.at("C"), *e.C0 / *e.C));
    if (v.count("e")) e.e = v.at("e");
    if (v.count("Y")) {
        e.Y = v.at("Y");
        if (!(*e.Y < 5)) cells.back().fail("axial load factor Y outside (0, 5)");
    }
    // A needle roller and cage assembly's designation is its size: the row must say the same.
    if (k->prefix == "K") {
        const std::string want = fmt::format("K{}X{}X{}", v.at("d"), v.at("D"), v.at("B"));
        if (want != k->key) row.fail("the dimensions differ from the designation's Fw x Ew x Bc");
    }
}
}  // namespace

void BearingCatalogue::load_file(const std::string& path, const std::string& shown) {
    const std::string name = shown.empty() ? path : shown;
    const YamlNode root = YamlNode::load_file(path);
    std::map<std::string, std::string> in_this_file;  // key -> "line N" of its row here
    root.allow_keys({"format", "sources", "series"});
    if (root.at("format").as_string() != "gearloss-bearing-catalogue/1")
        root.at("format").fail("expected 'gearloss-bearing-catalogue/1'");
    for (const auto& s : root.at("series").items()) {
        s.allow_keys({"series", "type", "skf_series", "contact_angle", "note", "dimensions", "ratings", "verified",
                      "columns", "bearings"});
        const std::string series = s.at("series").as_string();
        const YamlNode tn = s.at("type");
        const auto t = bearings::bearing_type_from_string(tn.as_string());
        if (!t) tn.fail("unknown bearing type '" + excerpt(tn.as_string()) + "'");
        const std::string skf = s.at("skf_series").as_string();
        if (!bearings::skf_constants(*t, skf)) {
            std::string all;
            for (const auto& x : bearings::series_names(*t)) all += (all.empty() ? "" : ", ") + x;
            s.at("skf_series").fail("no SKF constants for series '" + excerpt(skf) + "' of a " + bearings::to_string(*t) +
                                    " bearing; known: " + all);
        }
        std::vector<std::string> cols;
        for (const auto& c : s.at("columns").items()) cols.push_back(c.as_string());
        static const std::vector<std::string> known = {"designation", "d", "D", "B", "T", "C", "C0", "e", "Y"};
        for (size_t i = 0; i < cols.size(); ++i) {
            if (std::find(known.begin(), known.end(), cols[i]) == known.end())
                s.at("columns").items()[i].fail("unknown column '" + excerpt(cols[i]) + "'; known: designation, d, D, B, T, C, C0, e, Y");
            if (std::count(cols.begin(), cols.end(), cols[i]) > 1) s.at("columns").fail("column '" + cols[i] + "' twice");
        }
        if (cols.empty() || cols[0] != "designation" || !std::count(cols.begin(), cols.end(), "d") ||
            !std::count(cols.begin(), cols.end(), "D") ||
            !(std::count(cols.begin(), cols.end(), "B") || std::count(cols.begin(), cols.end(), "T")))
            s.at("columns").fail("columns start with 'designation' and include d, D and B (or T)");
        std::optional<double> angle;
        if (auto a = s.get("contact_angle")) angle = a->as_angle("40 deg");
        const std::string ratings = s.has("ratings") ? s.at("ratings").as_string() : "";
        const std::string verified = s.has("verified") ? s.at("verified").as_string() : "not stated";
        for (const auto& row : s.at("bearings").items()) {
            CatalogueEntry e;
            read_row(row, cols, e);
            e.type = *t;
            e.series = series;
            e.skf_series = skf;
            e.contact_angle = angle;
            e.ratings = ratings;
            e.verified = verified;
            const auto loc = row.location();
            e.location = fmt::format("{}:{}", name, loc.line);
            // A later file replaces a row on purpose; twice in one file is a slip (which row is meant?).
            if (const auto [it, fresh] = in_this_file.emplace(e.key, fmt::format("line {}", loc.line)); !fresh)
                row.fail(fmt::format("bearing '{}' is listed twice in this file (first at {}; key {})", e.designation,
                                     it->second, e.key));
            by_key_[e.key] = e;
        }
    }
    files_.push_back(name);
    paths_.push_back(path);
}

std::string BearingCatalogue::summary() const {
    std::string from;
    for (size_t i = 0; i < files_.size(); ++i)
        from += (i == 0 ? "" : i + 1 == files_.size() ? " and " : ", ") + files_[i];
    return fmt::format("{} rows from {}", by_key_.size(), from.empty() ? "no file" : from);
}

const CatalogueEntry* BearingCatalogue::find(const std::string& key) const {
    const auto it = by_key_.find(key);
    return it == by_key_.end() ? nullptr : &it->second;
}

std::vector<std::string> BearingCatalogue::closest(const std::string& key, size_t n) const {
    std::vector<std::pair<int, std::string>> d;
    for (const auto& [k, e] : by_key_) d.emplace_back(bearings::key_distance(key, k), e.designation);
    std::sort(d.begin(), d.end());
    std::vector<std::string> r;
    for (size_t i = 0; i < d.size() && i < n; ++i) r.push_back(d[i].second);
    return r;
}

const BearingCatalogue& shipped_bearing_catalogue(const std::string& key) {
    static std::mutex mu;
    static std::optional<BearingCatalogue> cat;
    std::lock_guard<std::mutex> lock(mu);
    if (!cat) {
        const auto dir = data_dir(key, "bearing designations are looked up in the shipped catalogue bearings/catalogue.yaml");
        BearingCatalogue c;
        // Shown relative to the data folder: the build or install path differs between machines.
        c.load_file((dir / "bearings" / "catalogue.yaml").string(), kShippedCatalogueName);
        cat = std::move(c);
    }
    return *cat;
}

}  // namespace gearloss::io
