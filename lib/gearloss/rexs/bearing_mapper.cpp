// A REXS bearing as the data of a gearloss bearing (case_mapper.hpp): the catalogue row of its
// designation, with every suffix code either resolved (seals) or named in a warning and in the
// case's comments; else a bearing of the type and size the model gives (detailed geometry: bore,
// outer diameter, width, static rating; concept bearing: the bore), the rest from the catalogue
// row of that type and size, declared assumed.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "gearloss/bearings/designation.hpp"
#include "gearloss/bearings/designation_suffix.hpp"
#include "gearloss/bearings/skf_constants.hpp"
#include "gearloss/case/bearing_catalogue.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/rexs/mapper_internal.hpp"

namespace gearloss::rexs::detail {
namespace {

// REXS bearing_type enum values -> gearloss bearing types (those the SKF (2004) model has).
std::optional<bearings::BearingType> type_of_rexs(const std::string& t) {
    using B = bearings::BearingType;
    if (t == "radial_grooved_ball_bearing") return B::deep_groove_ball;
    if (t == "angular_contact_ball_bearing") return B::angular_contact_ball;
    if (t == "four_point_contact_ball_bearing") return B::four_point_contact;
    if (t == "radial_self_aligning_ball_bearing") return B::self_aligning_ball;
    if (t == "radial_roller_bearing") return B::cylindrical_roller;
    if (t == "radial_needle_roller_bearing") return B::needle_roller;
    if (t == "radial_tapered_roller_bearing") return B::tapered_roller;
    if (t == "radial_self_aligning_roller_bearing") return B::spherical_roller;
    if (t == "axial_grooved_ball_bearing") return B::thrust_ball;
    if (t == "axial_roller_bearing") return B::cylindrical_roller_thrust;
    return std::nullopt;
}

// A catalogue series name as compared with a designation: upper case, no blanks ("NU 22" -> "NU22").
std::string series_spelling(const std::string& series) {
    std::string out;
    for (const char ch : series)
        if (ch != ' ') out += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return out;
}

// A catalogue row of the series a designation names when its own row is not in the catalogue
// (of type `t` when given): an ISO 15 basic designation is the series (type and dimension series
// digits) followed by the two-digit bore code, d = 5 x code mm from 04 on (ISO 15:2017; ISO 355
// for tapered roller bearings), so "6299-2RS1" is of the 62 series, "NU 2299" of NU 22, "7299 B"
// of 72 B; a designation that gives only the series ("62", "NU 22") names it as well. Null when
// no series matches (the bearing then takes the lightest row, and says so).
const io::CatalogueEntry* series_row_of_designation(const io::BearingCatalogue& cat, std::optional<bearings::BearingType> t,
                                                    const bearings::DesignationKey& k) {
    std::string number = k.number;
    const auto slash = number.find('/');  // "62/28": the bore after the slash
    const std::string rest = k.key.size() >= k.prefix.size() + k.number.size() ? k.key.substr(k.prefix.size() + k.number.size()) : "";
    const std::string whole = k.prefix + number + rest;
    std::string without_bore;
    if (slash != std::string::npos) without_bore = k.prefix + number.substr(0, slash) + rest;
    else if (number.size() >= 3) without_bore = k.prefix + number.substr(0, number.size() - 2) + rest;
    for (const auto& [key, e] : cat.entries()) {
        if ((t && e.type != *t) || e.series.empty()) continue;
        const std::string s = series_spelling(e.series);
        if (s == without_bore || s == whole) return &e;
    }
    return nullptr;
}

// The catalogue row of a type and bore nearest the given outer diameter and width; when the model
// gives neither, the row of `series` (the designation's) if the catalogue has one of this bore,
// else the lightest.
const io::CatalogueEntry* nearest_row(const io::BearingCatalogue& cat, bearings::BearingType t, double d,
                                      std::optional<double> D, std::optional<double> B, const std::string& series) {
    const io::CatalogueEntry* best = nullptr;
    double best_score = 0;
    for (const auto& [key, e] : cat.entries()) {
        if (e.type != t || std::abs(e.d - d) > 1e-6) continue;
        if (!D && !series.empty() && e.series != series) continue;
        const double score = D ? std::abs(e.D - *D) + (B ? 0.5 * std::abs(e.B - *B) : 0.0) : e.D;
        if (!best || score < best_score) {
            best = &e;
            best_score = score;
        }
    }
    return best;
}

// A bearing of a bore the catalogue has no row of this type for (a concept bearing on a 43.2 mm
// planet pin): the row of the type at the nearest bore, scaled to this bore; of `series` (the
// designation's) when given, else the lightest row there. Within one dimension series the
// boundary dimensions grow about in proportion to the bore (ISO 15:2017's diameter and width
// series), and the static rating C0 = f0 i Z Dw^2 cos(alpha) (ISO 76:2006) with the ball
// diameter, i.e. with the square of the scale; the SKF (2004) friction constants are those of the
// series, kept as they are.
std::optional<io::CatalogueEntry> scaled_row(const io::BearingCatalogue& cat, bearings::BearingType t, double d,
                                             const std::string& series) {
    const io::CatalogueEntry* best = nullptr;
    for (const auto& [key, e] : cat.entries()) {
        if (e.type != t || !(e.d > 0)) continue;
        if (!series.empty() && e.series != series) continue;
        const double gap = std::abs(std::log(e.d / d)), best_gap = best ? std::abs(std::log(best->d / d)) : 0.0;
        if (!best || gap < best_gap - 1e-12 || (std::abs(gap - best_gap) <= 1e-12 && e.D < best->D)) best = &e;
    }
    if (!best) return std::nullopt;
    io::CatalogueEntry row = *best;
    const double k = d / best->d;
    row.designation = fmt::format("{} x {:.4g} (bore {:g} mm)", best->designation, k, best->d * 1e3);
    row.d = d;
    row.D = best->D * k;
    row.B = best->B * k;
    if (row.C0) row.C0 = *best->C0 * k * k;
    if (row.C) row.C = std::nullopt;  // the dynamic rating is not used by the loss model
    return row;
}

// Components placed in `owner` by an assembly or ordered_assembly relation, of `type`.
std::vector<const Component*> parts_of(const Model& m, std::int64_t owner, const std::string& type) {
    std::vector<const Component*> out;
    for (const char* rel : {"assembly", "ordered_assembly"})
        for (const Relation* r : m.relations_with(rel, "assembly", owner))
            if (const auto p = r->ref("part"); p && m.at(*p).type == type) out.push_back(&m.at(*p));
    return out;
}

}  // namespace

void Mapper::report_suffix(YamlOut& y, const Component& c, const bearings::DesignationKey& key, bearings::BearingType type,
                           double D, bool designation_written) {
    const auto codes = bearings::decode_suffix(key);
    if (codes.empty()) return;
    std::vector<std::string> dropped;
    bool seals_written = false;
    for (const auto& code : codes) {
        std::string effect;
        bool drop = false;
        switch (code.kind) {
            case bearings::SuffixCode::contact_seal: {
                const auto seal = bearings::suffix_seal(code.code);
                // SKF (2004) seal moment M_seal = K_S1 d_s^beta + K_S2: constants by type and seal code.
                const bool known = !seal.code.empty() && bearings::skf_seal_constants(type, seal.code, D * 1e3);
                if (known) {
                    effect = "the seal friction term of SKF (2004) applies (seals " + seal.code + ")";
                    if (!designation_written && !seals_written) {
                        y.line(4, "seals: " + seal.code, src(c, designation_attribute(m)) + " suffix " + code.code + " (both sides counted)");
                        seals_written = true;
                    }
                } else {
                    effect = std::string("no SKF (2004) seal constants for a ") + bearings::to_string(type) +
                             " bearing: its friction is not counted";
                    drop = true;
                }
                break;
            }
            case bearings::SuffixCode::shield: effect = "no contact: no seal friction (SKF 2004)"; break;
            case bearings::SuffixCode::unknown:
                effect = "not understood: dropped";
                drop = true;
                break;
            default:
                effect = std::string(bearings::to_string(code.kind)) + ": no term in the SKF (2004) friction model, dropped";
                drop = true;
        }
        const std::string what = code.meaning.empty() ? "" : code.meaning + "; ";
        y.comment(4, "suffix " + code.code + ": " + what + effect);
        if (drop) dropped.push_back(code.code + (code.meaning.empty() ? " (not understood)" : " (" + code.meaning + ")"));
    }
    if (!dropped.empty()) {
        std::string list;
        for (const auto& d : dropped) list += (list.empty() ? "" : ", ") + d;
        warn(c, fmt::format("designation suffix codes not represented in the loss model: {} (listed in the case's comments)", list));
    }
}

void Mapper::write_bearing_data(YamlOut& y, const Component& c, const Shaft& s, double u, bool locating,
                                const std::string& name) {
    const io::BearingCatalogue& cat = io::shipped_bearing_catalogue("bearings (REXS import)");
    const std::string key_prefix = "bearings." + name + ".";
    const bool detailed = c.type == "rolling_bearing_with_detailed_geometry";
    const auto bore_given = quantity(m, c, "inner_diameter", Quantity::length);
    const auto bore_shaft = s.diameter_at(u);
    const auto D_given = quantity(m, c, "outer_diameter", Quantity::length);
    const auto B_given = quantity(m, c, "width", Quantity::length);
    if (bore_given && D_given && !(*D_given > *bore_given))
        m.fail(c, fmt::format("outer_diameter {:g} mm is not above inner_diameter {:g} mm", *D_given * 1e3, *bore_given * 1e3));
    if (B_given && !(*B_given > 0)) m.fail(c, "width must be positive");

    const auto designation = text(m, c, designation_attribute(m));
    std::optional<bearings::DesignationKey> key;
    if (designation && (key = bearings::designation_key(*designation)))
        if (const auto why = bearings::suffix_contradiction(*key))
            m.fail(c, std::string(designation_attribute(m)) + " '" + io::excerpt(*designation, 40) + "': " + *why);
    const io::CatalogueEntry* e = key ? cat.find(key->key) : nullptr;
    // Detailed geometry is the model's own: its designation's row is used only when it has that size.
    bool other_size = false;
    if (e && detailed && ((bore_given && std::abs(*bore_given - e->d) > 5e-4) || (D_given && std::abs(*D_given - e->D) > 5e-4))) {
        warn(c, fmt::format("catalogue row {} ({:g} x {:g} mm) is not the size of the detailed geometry: the geometry is imported",
                            e->designation, e->d * 1e3, e->D * 1e3));
        e = nullptr;
        other_size = true;
    }
    if (e) {
        y.line(4, "designation: " + quoted(*designation), src(c, designation_attribute(m)) + " (catalogue row " + e->designation + ")");
        const double d = bore_given ? *bore_given : bore_shaft.value_or(e->d);
        if (std::abs(d - e->d) > 1e-6)
            warn(c, fmt::format("catalogue bore {:g} mm of {} differs from the {:g} mm the model gives", e->d * 1e3,
                                e->designation, d * 1e3));
        report_suffix(y, c, *key, e->type, e->D, true);
        return;
    }
    if (designation && !other_size)
        warn(c, "designation '" + io::excerpt(*designation, 40) + "' is not in the bearing catalogue (" + cat.summary() +
                    "): imported as a bearing of the " + (detailed ? "geometry the model gives" : "bore the model gives"));

    // The bore: inner_diameter, else the shaft's diameter at the bearing.
    if (!bore_given && !bore_shaft) m.fail(c, "no inner_diameter and no shaft section at the bearing: its bore is unknown");
    const double d = bore_given ? *bore_given : *bore_shaft;
    // The rolling elements (rows and elements of a detailed bearing): a roller has a length.
    const auto rows = parts_of(m, c.id, "rolling_bearing_row");
    std::vector<const Component*> elements = parts_of(m, c.id, "rolling_element");
    for (const Component* r : rows)
        for (const Component* el : parts_of(m, r->id, "rolling_element")) elements.push_back(el);
    bool roller = false;
    for (const Component* el : elements)
        if (quantity(m, *el, "length_of_rolling_element", Quantity::length).value_or(0.0) > 0) roller = true;

    std::optional<bearings::BearingType> type;
    std::string type_reason;
    const io::CatalogueEntry* series_row = nullptr;  // a row of the series the designation names
    if (const auto t = text(m, c, "bearing_type")) {
        type = type_of_rexs(*t);
        if (!type) m.fail(c, "bearing_type '" + io::excerpt(*t, 40) + "' has no SKF (2004) friction model in gearloss");
        y.line(4, std::string("type: ") + bearings::to_string(*type), src(c, "bearing_type") + " " + *t);
    } else if (key && (series_row = series_row_of_designation(cat, std::nullopt, *key))) {
        type = series_row->type;
        type_reason = "REXS gives no bearing_type; the designation's series " + series_row->series + " is of this type";
    } else if (!elements.empty()) {
        type = roller ? bearings::BearingType::cylindrical_roller : bearings::BearingType::deep_groove_ball;
        type_reason = roller ? "REXS gives no bearing_type; its rolling elements have a length: a cylindrical roller bearing"
                             : "REXS gives no bearing_type; its rolling elements are balls: a deep groove ball bearing";
    } else {
        type = locating ? bearings::BearingType::deep_groove_ball : bearings::BearingType::cylindrical_roller;
        type_reason = std::string("REXS gives no bearing_type; ") +
                      (locating ? "it takes axial load: a deep groove ball bearing" : "radial only: a cylindrical roller bearing");
    }
    if (!type_reason.empty()) assumed_line(y, 4, std::string("type: ") + bearings::to_string(*type), key_prefix + "type", type_reason);
    y.line(4, "d: " + num(d * 1e3) + " mm", bore_given ? src(c, "inner_diameter") : fmt::format("shaft {} outer diameter at the bearing", s.comp->id));
    // The series the model gives: that of a designation the catalogue has no row of ("6299-2RS1":
    // 62, "NU 22"), else none, and the lightest row stands in (said in each assumed value's reason).
    if (key && !series_row) series_row = series_row_of_designation(cat, *type, *key);
    const std::string series = series_row && series_row->type == *type ? series_row->series : std::string();
    const std::string no_series = designation ? "the designation names no catalogue series of the type" : "REXS gives no designation";
    const io::CatalogueEntry* row = nearest_row(cat, *type, d, D_given, B_given, series);
    std::string row_how = D_given            ? " (same type and bore, nearest outer diameter)"
                          : !series.empty() ? " (same type and bore, series " + series + " of the designation)"
                                            : " (same type and bore, lightest series: " + no_series + ")";
    std::optional<io::CatalogueEntry> scaled;
    if (!row && (scaled = scaled_row(cat, *type, d, series))) {
        row = &*scaled;
        row_how = series.empty() ? " (no row of this bore: the nearest bore's lightest row, " + no_series +
                                       "; D and B scaled with d, C0 with d^2)"
                                 : " (no row of this bore: the nearest bore's row of series " + series +
                                       " of the designation, D and B scaled with d, C0 with d^2)";
        warn(c, fmt::format("no catalogue {} bearing of bore {:g} mm: assumed as {} ({})", bearings::to_string(*type), d * 1e3,
                            scaled->designation,
                            series.empty() ? "the lightest row at the nearest bore: " + no_series : "series " + series + " of the designation"));
    }
    if (D_given) y.line(4, "D: " + num(*D_given * 1e3) + " mm", src(c, "outer_diameter"));
    else if (row) assumed_line(y, 4, "D: " + num(row->D * 1e3) + " mm", key_prefix + "D", "catalogue row " + row->designation + row_how);
    else assumed_line(y, 4, "D: " + num(d * 1.5e3) + " mm", key_prefix + "D", "1.5 d (no catalogue row of this type and bore)");
    if (B_given) y.line(4, "B: " + num(*B_given * 1e3) + " mm", src(c, "width"));
    else if (row) assumed_line(y, 4, "B: " + num(row->B * 1e3) + " mm", key_prefix + "B", "catalogue row " + row->designation + row_how);
    const double D = D_given ? *D_given : row ? row->D : 1.5 * d;
    // The rolling elements as REXS gives them: the SKF (2004) model takes the mean diameter
    // dm = (d + D) / 2 (SKF 2004, "Estimating the frictional moment"), not the pitch diameter.
    for (const Component* r : rows) {
        const auto z = integer(m, *r, "number_of_rolling_elements");
        const auto dpw = quantity(m, *r, "reference_diameter", Quantity::length);
        std::optional<double> dw;
        for (const Component* el : parts_of(m, r->id, "rolling_element"))
            if (!dw) dw = quantity(m, *el, "diameter_of_rolling_element", Quantity::length);
        y.comment(4, fmt::format("REXS row {}: {} rolling elements{}{}; the friction model takes dm = (d + D)/2 = {} mm", r->id,
                                 z ? std::to_string(*z) : "?", dw ? ", diameter " + num(*dw * 1e3) + " mm" : "",
                                 dpw ? ", pitch diameter " + num(*dpw * 1e3) + " mm" : "", num(0.5 * (d + D) * 1e3)));
        if (dpw && std::abs(*dpw - 0.5 * (d + D)) > 0.05 * 0.5 * (d + D))
            warn(c, fmt::format("pitch diameter {:g} mm of row {} is more than 5 % from dm = (d + D)/2 = {:g} mm the friction "
                                "model uses",
                                *dpw * 1e3, r->id, 0.5 * (d + D) * 1e3));
    }
    if (row) assumed_line(y, 4, "series: \"" + row->skf_series + "\"", key_prefix + "series",
                          "SKF (2004) series of catalogue row " + row->designation + row_how);
    const bool thrust = *type == bearings::BearingType::thrust_ball || *type == bearings::BearingType::cylindrical_roller_thrust;
    const char* c0_attr = thrust ? "axial_static_load_rating" : "radial_static_load_rating";
    if (const auto c0 = quantity(m, c, c0_attr, Quantity::force); c0 && *c0 > 0)
        y.line(4, "C0: " + num(*c0 * 1e-3) + " kN", src(c, c0_attr));
    else if (row && row->C0)
        assumed_line(y, 4, "C0: " + num(*row->C0 * 1e-3) + " kN", key_prefix + "C0", "catalogue row " + row->designation + row_how);
    else if (*type == bearings::BearingType::deep_groove_ball)
        m.fail(c, fmt::format("no catalogue deep groove ball bearing of bore {:g} mm gives the static rating C0 the friction "
                              "model needs (REXS gives no {})",
                              d * 1e3, c0_attr));
    if (*type == bearings::BearingType::tapered_roller) {
        if (const auto yf = quantity(m, c, "axial_factor_y_1", Quantity::dimensionless); yf && *yf > 0)
            y.line(4, "Y: " + num(*yf), src(c, "axial_factor_y_1"));
        else if (row && row->Y)
            assumed_line(y, 4, "Y: " + num(*row->Y), key_prefix + "Y", "catalogue row " + row->designation + row_how);
    }
    if (key) report_suffix(y, c, *key, *type, D, false);
}

}  // namespace gearloss::rexs::detail
