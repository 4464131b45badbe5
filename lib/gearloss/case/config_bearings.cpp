// Case loader: bearings (SKF constants, seals, oil bath), shaft seals and wet clutch packs (docs/config.md).
#include <fmt/format.h>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>
#include <string>

#include "gearloss/bearings/designation.hpp"
#include "gearloss/bearings/skf_constants.hpp"
#include "gearloss/case/config_internal.hpp"
#include "gearloss/io/csv_read.hpp"

namespace gearloss::io::detail {

namespace dim = units::dim;
using lubricant::BaseOil;

// SKF sliding friction pair of a bearing from the oil (or the SKF defaults by type and base oil).
void set_bearing_friction(bearings::BearingSpec& s, const lubricant::Oil& oil) {
    const bool synthetic = oil.base != BaseOil::mineral && oil.base != BaseOil::transmission_fluid;
    const auto& pair = bearings::is_roller(s.type) ? oil.bearing_roller : oil.bearing_ball;
    s.mu_bl = pair.mu_bl;
    s.mu_ehl = pair.mu_ehl ? *pair.mu_ehl
                           : bearings::default_mu_ehl(s.type, synthetic, oil.base == BaseOil::transmission_fluid);
}

namespace {
std::string located_at(const YamlNode& n) {
    const auto l = n.location();
    return l.known() ? fmt::format("{}:{}:{}", l.file.empty() ? n.file() : l.file, l.line, l.column) : n.file();
}

// The catalogue a case reads: the shipped one, then its `bearing_catalogue` files (a name or a
// list, relative to the case's folder) overriding rows of the same designation.
const BearingCatalogue& case_catalogue(const YamlNode& root, const std::string& base_dir, const YamlNode& asking,
                                       std::optional<BearingCatalogue>& own) {
    const BearingCatalogue& shipped = shipped_bearing_catalogue(asking.path());
    const auto files = root.get("bearing_catalogue");
    if (!files) return shipped;
    if (own) return *own;
    own = shipped;
    std::vector<YamlNode> names = files->is_sequence() ? files->items() : std::vector<YamlNode>{*files};
    for (const auto& f : names) {
        const std::filesystem::path p = std::filesystem::path(base_dir) / f.as_string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(p, ec))
            f.fail("bearing catalogue '" + excerpt(p.string(), 200) + "' does not exist or is not a file");
        own->load_file(p.string(), f.as_string());  // shown as written, relative to the case
    }
    return *own;
}
}  // namespace

void Loader::load_bearings() {
    if (!root.has("bearings")) return;
    std::set<std::string> names;
    std::optional<BearingCatalogue> own_catalogue;
    for (const auto& n : root.at("bearings").items()) {
        n.allow_keys({"name", "type", "series", "designation", "d", "D", "B", "C0", "Y", "shaft", "position",
                      "under_gear", "outer_shaft", "outer_position", "locating", "lubrication", "seals", "seal_counterface", "constants", "oil_bath",
                      "note", "count"});
        gearbox::Bearing b;
        b.name = n.at("name").as_name();
        if (!names.insert(b.name).second) n.at("name").fail("duplicate bearing name '" + b.name + "'");
        auto& s = b.spec;
        BearingResolution res;
        res.bearing = b.name;
        // designation: the catalogue row gives type, sizes, ratings and the SKF series; explicit keys override.
        const CatalogueEntry* cat = nullptr;
        if (auto dn = n.get("designation")) {
            res.designation = dn->as_string();
            const auto key = bearings::designation_key(res.designation);
            if (!key) dn->fail("'" + excerpt(res.designation) + "' is not a bearing designation (e.g. 6307, NJ 309 E, 32306, 7308 BE, QJ 308, K 38x43x27)");
            if (const auto why = bearings::suffix_contradiction(*key)) dn->fail(*why);
            res.suffix = key->suffix;
            const BearingCatalogue& catalogue = case_catalogue(root, base_dir, *dn, own_catalogue);
            cat = catalogue.find(key->key);
            if (!cat) {
                std::string near;
                for (const auto& c : catalogue.closest(key->key, 5)) near += (near.empty() ? "" : ", ") + c;
                dn->fail(fmt::format("no bearing '{}' in the catalogue (key {}; {}); closest: {}. Give type, d, D, B "
                                     "(and C0, series) explicitly, or add a catalogue file with 'bearing_catalogue'",
                                     excerpt(res.designation), key->key, catalogue.summary(), near));
            }
            res.entry = cat->designation;
            res.entry_location = cat->location;
            res.verified = cat->verified;
            res.ratings = cat->ratings;
        }
        const std::string from_cat = cat ? "catalogue " + cat->location : "";
        if (cat && !n.has("type")) {
            s.type = cat->type;
            res.type_source = from_cat;
        } else {
            const YamlNode tn = n.at("type");
            const auto t = bearings::bearing_type_from_string(tn.as_string());
            if (!t) {
                std::string all;
                for (const auto& x : bearings::bearing_type_names()) all += (all.empty() ? "" : ", ") + x;
                tn.fail("unknown bearing type '" + excerpt(tn.as_string()) + "'; known: " + all);
            }
            if (cat && *t != cat->type)
                tn.fail(fmt::format("type {} contradicts the catalogue's {} for '{}' ({})", bearings::to_string(*t),
                                    bearings::to_string(cat->type), cat->designation, cat->location));
            s.type = *t;
            res.type_source = "explicit " + located_at(tn);
        }
        res.type = bearings::to_string(s.type);
        // A length or load: explicit key, else the catalogue's value; records where it came from.
        auto pick = [&](const char* key, const units::Dimension& dim, const char* example, std::optional<double> catalogue,
                        double unit, const char* unit_name) -> std::optional<double> {
            std::optional<double> v;
            std::string src;
            if (n.has(key)) {
                v = n.positive_quantity(key, dim, example);
                src = "explicit " + located_at(n.at(key));
            } else if (catalogue) {
                v = catalogue;
                src = from_cat;
            }
            if (v) res.values.push_back({key, fmt::format("{:g} {}", *v / unit, unit_name), *v, src});
            return v;
        };
        const bool tapered_row = cat && cat->T;
        if (auto v = pick("d", dim::length, "35 mm", cat ? std::optional<double>(cat->d) : std::nullopt, 1e-3, "mm")) s.d = *v;
        else s.d = n.positive_quantity("d", dim::length, "35 mm");
        if (auto v = pick("D", dim::length, "80 mm", cat ? std::optional<double>(cat->D) : std::nullopt, 1e-3, "mm")) s.D = *v;
        else s.D = n.positive_quantity("D", dim::length, "80 mm");
        if (s.d >= s.D)
            (n.has("D") ? n.at("D") : n).fail(fmt::format("outer diameter D = {:.6g} mm must exceed bore d = {:.6g} mm", s.D * 1e3, s.d * 1e3));
        const std::string key = "bearings." + b.name + ".";
        if (auto v = pick("B", dim::length, "21 mm", cat ? std::optional<double>(cat->B) : std::nullopt, 1e-3, "mm")) {
            s.B = *v;
            if (tapered_row && !n.has("B")) res.values.back().name = "B (= T, total width)";
        } else {
            s.B = 0.25 * (s.D - s.d);
            res.values.push_back({"B", fmt::format("{:g} mm", s.B * 1e3), s.B, "estimate 0.25 (D - d) (no B given)"});
            assume(assumed, n, key + "B", number_text(s.B * 1e3) + " mm", "width estimated as (D - d) / 4");
        }
        if (tapered_row && cat->cone_width)
            res.values.push_back({"cone width", fmt::format("{:g} mm", *cat->cone_width * 1e3), *cat->cone_width, from_cat});
        if (!n.has("B") && !cat && bearings::is_roller(s.type) && n.has("oil_bath"))
            n.fail("give the width 'B' for roller bearings in an oil bath (drag depends on it)");
        if (cat && cat->C) res.values.push_back({"C", fmt::format("{:g} kN", *cat->C / 1e3), *cat->C, from_cat});
        if (auto v = pick("C0", dim::force, "18.3 kN", cat ? cat->C0 : std::nullopt, 1e3, "kN")) s.C0 = *v;
        if (n.has("Y")) {
            // SKF (2004) uses Y in the rolling and sliding terms of tapered roller bearings only:
            // on any other type it would be shown by `check` and change nothing.
            if (s.type != bearings::BearingType::tapered_roller)
                n.at("Y").fail(fmt::format("the axial load factor Y enters the SKF (2004) friction model of tapered roller "
                                           "bearings only; a {} bearing takes its axial load through its series constants",
                                           bearings::to_string(s.type)));
            s.Y = n.at("Y").as_number();
            if (!(s.Y > 0 && s.Y < 5)) n.at("Y").fail("axial load factor Y outside (0, 5)");
            res.values.push_back({"Y", fmt::format("{:g}", s.Y), s.Y, "explicit " + located_at(n.at("Y"))});
        } else if (cat && cat->Y) {
            s.Y = *cat->Y;
            res.values.push_back({"Y", fmt::format("{:g}", s.Y), s.Y, from_cat});
        } else if (s.type == bearings::BearingType::tapered_roller) {
            res.values.push_back({"Y", fmt::format("{:g}", s.Y), s.Y, "default (no Y given)"});
        }
        if (cat && cat->e) res.values.push_back({"e", fmt::format("{:g}", *cat->e), *cat->e, from_cat});
        if (cat && cat->contact_angle)
            res.values.push_back({"contact angle", fmt::format("{:g} deg", *cat->contact_angle * 180 / std::numbers::pi),
                                  *cat->contact_angle, from_cat});
        std::string series = n.has("series") ? n.at("series").as_string() : "";
        std::string series_source = n.has("series") ? "explicit " + located_at(n.at("series")) : "default ('other' row)";
        if (!n.has("series") && cat) {
            series = cat->skf_series;
            series_source = from_cat;
        }
        auto k = bearings::skf_constants(s.type, series);
        if (!k && !n.has("constants")) {
            std::string all;
            for (const auto& x : bearings::series_names(s.type)) all += (all.empty() ? "" : ", ") + x;
            (n.has("series") ? n.at("series") : n)
                .fail(fmt::format("no SKF constants for a {} bearing of series '{}'; known series: {} (or give "
                                  "'constants')",
                                  bearings::to_string(s.type), excerpt(series), all));
        }
        if (k) s.k = *k;
        res.values.push_back({"series", series.empty() ? "other" : series, 0.0,
                              n.has("constants") ? series_source + "; constants from 'constants'" : series_source});
        if (k && !cat && !n.has("series") && !n.has("constants"))
            assume(assumed, n, key + "series", "(none)",
                   fmt::format("SKF (2004) constants of the type's default series for a {} bearing", bearings::to_string(s.type)));
        if (auto c = n.get("constants")) {
            c->allow_keys({"R1", "R2", "R3", "R4", "S1", "S2", "S3", "S4", "K_Z", "K_L", "rows"});
            auto set = [&](const char* key, double& v) {
                if (auto x = c->get(key)) v = x->as_number();
            };
            set("R1", s.k.R1); set("R2", s.k.R2); set("R3", s.k.R3); set("R4", s.k.R4);
            set("S1", s.k.S1); set("S2", s.k.S2); set("S3", s.k.S3); set("S4", s.k.S4);
            set("K_Z", s.k.K_Z); set("K_L", s.k.K_L);
            if (auto x = c->get("rows")) s.k.rows = x->as_int();
            if (!(s.k.R1 > 0 && s.k.S1 > 0)) c->fail("R1 and S1 must be positive");
        }
        if (s.type == bearings::BearingType::deep_groove_ball && s.C0 <= 0)
            n.fail("deep groove ball bearings need the static load rating 'C0' (for the axial-load terms)");
        if (!n.has("lubrication"))
            assume(assumed, n, key + "lubrication", "splash",
                   "SKF (2004) replenishment/starvation constant K_rs = 3e-8 (oil bath at low level, splash)");
        if (auto l = n.get("lubrication"))
            s.K_rs = l->as_enum<double>({{"splash", 3e-8}, {"oil_bath_low", 3e-8}, {"oil_jet", 3e-8},
                                        {"oil_bath", 0.0}, {"grease", 6e-8}, {"oil_air", 6e-8}});
        set_bearing_friction(s, model.oil);
        // Integral seals: the `seals` key, else what the designation's suffix says (6307-2RS1).
        const auto se = n.get("seals");
        std::string st = se ? se->as_string() : "none";
        double seal_sides = 2;
        if (!se && !res.suffix.empty()) {
            const auto seal = bearings::suffix_seal(res.suffix);
            const bool known = !seal.code.empty() && bearings::skf_seal_constants(s.type, seal.code, s.D * 1e3);
            // One contact seal (RS1, RSH, RS: no leading 2, not NTN/NSK LL../DD.. pairs) rubs on one side.
            const bool one_side = seal.token == "RS1" || seal.token == "RSH" || seal.token == "RS";
            const std::string from = fmt::format("designation suffix '{}' ({})", seal.token, located_at(n.at("designation")));
            if (seal.kind == bearings::SuffixSeal::contact && known) {
                st = seal.code;
                seal_sides = one_side ? 1 : 2;
                res.values.push_back({"seals", fmt::format("{} ({})", st, one_side ? "one side" : "both sides"), 0.0, from});
            } else if (seal.kind == bearings::SuffixSeal::contact) {
                assume(assumed, n, key + "seals", "none",
                       fmt::format("the contact seals '{}' of the designation have no SKF (2004) seal constants for a {} "
                                   "bearing: their friction is not counted (give 'seals' and 'constants' to count it)",
                                   seal.token, bearings::to_string(s.type)));
            } else if (seal.kind == bearings::SuffixSeal::shield) {
                res.values.push_back({"seals", "no contact (" + seal.token + ")", 0.0, from});
            }
        }
        if (st != "none") {
            // M_seal = K_S1 d_s^beta + K_S2 (SKF 2004 seal moment, both sides sealed).
            const auto sc = bearings::skf_seal_constants(s.type, st, s.D * 1e3);  // the table is by D in mm
            if (!sc)
                se.value_or(n).fail(fmt::format("no seal constants for '{}' on a {} bearing (known: DGBB RS1, ACBB/SABB RS1, "
                                                "CRB LS, SRB CS/CS2/CS5, shields Z/RZ)",
                                                st, bearings::to_string(s.type)));
            s.seal_beta = sc->beta;
            s.seal_KS1 = sc->K_S1;
            s.seal_KS2 = sc->K_S2;
            // SKF (2004): M_seal is for a bearing sealed on both sides; one seal gives half of it.
            s.seal_KS1 *= seal_sides / 2;
            s.seal_KS2 *= seal_sides / 2;
            // Unset: the inner-ring shoulder estimate d + 0.2 (D - d) (gearloss/bearings/skf_model.hpp).
            if (n.has("seal_counterface"))
                s.seal_ds = n.positive_quantity("seal_counterface", dim::length, "30 mm");
        }
        if (auto ob = n.get("oil_bath")) {
            ob->allow_keys({"level", "V_M"});
            const double H = ob->quantity("level", dim::length, "10 mm");
            if (H < 0) ob->at("level").fail("oil level cannot be negative");
            s.bath_H = H;
            s.bath_VM = ob->at("V_M").as_number();
            if (!(s.bath_VM >= 0 && s.bath_VM < 0.01)) ob->at("V_M").fail("drag factor V_M outside 0..0.01 (SKF diagram)");
        }
        b.shaft = shaft_ref(n.at("shaft"));
        if (auto ug = n.get("under_gear")) {
            b.under_gear = gear_ref(*ug);
            const auto& g = model.gearbox.gears[b.under_gear];
            if (!g.free && !g.is_planet())
                ug->fail("bearing under gear '" + g.spec.name + "', which is neither 'mount: free' nor a planet");
            if (g.shaft != b.shaft)
                ug->fail("gear '" + g.spec.name + "' is not on shaft '" + n.at("shaft").as_string() + "'" +
                         (g.is_planet() ? " (a planet bearing names the carrier as its shaft)" : ""));
            b.position = g.position;
            if (g.is_planet()) b.multiplicity = g.planets;  // listed once, runs in every planet
        } else {
            b.position = n.quantity("position", dim::length, "20 mm");
        }
        // A pilot bearing: its outer ring in another shaft, so it runs at the two shafts' relative speed.
        if (auto os = n.get("outer_shaft")) {
            if (n.has("under_gear"))
                os->fail("a bearing has 'outer_shaft' (a pilot bearing between two shafts) or 'under_gear' (under a "
                         "free gear or planet), not both");
            b.outer_shaft = shaft_ref(*os);
            if (b.outer_shaft == b.shaft)
                os->fail("outer_shaft names the bearing's own shaft '" + n.at("shaft").as_string() +
                         "': a bearing in the housing has no 'outer_shaft'");
            // Each shaft's positions are along that shaft (REXS writes every shaft's own u coordinate),
            // so the pilot's place on the outer shaft is given in the outer shaft's frame.
            if (!n.has("outer_position"))
                os->fail("a pilot bearing needs 'outer_position' (its axial position along the outer shaft '" +
                         os->as_string() + "', in that shaft's frame) to carry its reaction to that shaft's bearings");
            b.outer_position = n.quantity("outer_position", dim::length, "60 mm");
        } else if (auto op = n.get("outer_position")) {
            op->fail("'outer_position' is the position of a pilot bearing along its 'outer_shaft', which is not given");
        }
        if (auto lc = n.get("locating")) b.locating = lc->as_bool();
        int count = 1;
        if (auto c = n.get("count")) {
            count = c->as_int();
            if (count < 1 || count > 8) c->fail("count must be 1..8 (identical bearings side by side)");
        }
        if (resolved) resolved->push_back(res);
        for (int i = 0; i < count; ++i) {
            gearbox::Bearing bi = b;
            if (count > 1) {
                bi.name = b.name + "." + std::to_string(i + 1);
                if (!names.insert(bi.name).second)
                    n.at("count").fail("bearing name '" + bi.name + "' (of 'count' side by side) is already taken");
            }
            model.gearbox.bearings.push_back(bi);
        }
    }
    // A free gear or a planet needs bearings under it (its speed differs from the shaft's).
    for (size_t g = 0; g < model.gearbox.gears.size(); ++g) {
        if (!model.gearbox.gears[g].free && !model.gearbox.gears[g].is_planet()) continue;
        bool any = false;
        for (const auto& b : model.gearbox.bearings) any = any || b.under_gear == static_cast<int>(g);
        if (!any)
            root.at("gears").items()[g].fail("gear '" + model.gearbox.gears[g].spec.name +
                                             "' turns on its own bearings ('mount: free' or a planet) but no bearing "
                                             "has 'under_gear' naming it");
    }
}

void Loader::load_seals() {
    if (!root.has("seals")) return;
    std::set<std::string> names;
    for (const auto& n : root.at("seals").items()) {
        n.allow_keys({"name", "shaft", "diameter", "note"});
        gearbox::Seal s;
        s.name = n.at("name").as_name();
        if (!names.insert(s.name).second) n.at("name").fail("duplicate seal name '" + s.name + "'");
        s.shaft = shaft_ref(n.at("shaft"));
        s.diameter = n.positive_quantity("diameter", dim::length, "40 mm");
        model.gearbox.seals.push_back(s);
    }
}

void Loader::load_clutches() {
    if (!root.has("clutches")) return;
    std::set<std::string> names;
    for (const auto& n : root.at("clutches").items()) {
        n.allow_keys({"name", "engages", "interfaces", "r_inner", "r_outer", "clearance", "roughness", "oil_supply",
                      "note"});
        gearbox::ClutchPack c;
        c.pack.name = n.at("name").as_name();
        if (!names.insert(c.pack.name).second) n.at("name").fail("duplicate clutch name '" + c.pack.name + "'");
        c.gear = gear_ref(n.at("engages"));
        if (!model.gearbox.gears[c.gear].free)
            n.at("engages").fail("a clutch engages a 'mount: free' gear (it locks that gear to its shaft)");
        c.pack.interfaces = n.at("interfaces").as_int();
        if (c.pack.interfaces < 1 || c.pack.interfaces > 100) n.at("interfaces").fail("must be 1-100");
        c.pack.r_inner = n.positive_quantity("r_inner", dim::length, "55 mm");
        c.pack.r_outer = n.positive_quantity("r_outer", dim::length, "72 mm");
        if (c.pack.r_outer <= c.pack.r_inner) n.at("r_outer").fail("r_outer must exceed r_inner");
        c.pack.clearance = n.positive_quantity("clearance", dim::length, "0.15 mm");
        if (auto r = n.get("roughness")) c.pack.roughness = r->as_quantity(dim::length, "1 um");
        if (c.pack.roughness > 0 && c.pack.clearance / c.pack.roughness < 3)
            n.at("clearance").fail("clearance below 3x the roughness: the open-pack drag model (full film, "
                                   "Patir & Cheng shear factor for H >= 3) does not apply");
        if (auto q = n.get("oil_supply")) {
            c.pack.oil_supply = q->as_quantity(units::make_dim(3, 0, -1, 0), "0.4 L/min");
            if (c.pack.oil_supply < 0) q->fail("must not be negative");
        }
        model.gearbox.clutches.push_back(c);
    }
}

}  // namespace gearloss::io::detail
