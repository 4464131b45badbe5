// A REXS model as a gearloss case: shafts, gears and stages (case_mapper.hpp); planetary stages
// are in planetary.cpp; bearings, seals, housing, operating points and oil in mapper_support.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "gearloss/core/errors.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/rexs/mapper_internal.hpp"

namespace gearloss::rexs {
namespace detail {

void YamlOut::line(int indent, const std::string& text, const std::string& comment) {
    std::string s(static_cast<size_t>(indent), ' ');
    s += text;
    if (!comment.empty()) {
        if (s.size() < 44) s.resize(44, ' ');
        else s += "  ";
        s += "# " + comment;
    }
    text_ += s + "\n";
}

void YamlOut::comment(int indent, const std::string& text) {
    text_ += std::string(static_cast<size_t>(indent), ' ') + "# " + text + "\n";
}

std::string num(double v) {
    if (v == 0) return "0";
    return fmt::format("{:.10g}", v);
}

std::string safe_name(const Component& c) { return io::excerpt(c.name, 60); }

std::string quoted(const std::string& s, size_t max) {
    std::string out = "\"";
    for (const char ch : io::excerpt(s, max)) {
        if (ch == '"' || ch == '\\') out += '\\';
        out += ch;
    }
    return out + "\"";
}

std::string src(const Component& c, const std::string& attribute) {
    const Attribute* a = c.find(attribute);
    std::string s = "REXS " + std::to_string(c.id) + " " + attribute;
    if (a && !a->unit.empty() && a->unit != "none") s += " [" + io::excerpt(a->unit, 20) + "]";
    return s;
}

double Shaft::length() const {
    double l = 0;
    for (const auto& s : sections) l = std::max(l, s.u1);
    return l;
}

std::optional<double> Shaft::diameter_at(double u) const {
    for (const auto& s : sections)
        if (u >= s.u0 - 1e-9 && u <= s.u1 + 1e-9) {
            const double t = s.u1 > s.u0 ? std::clamp((u - s.u0) / (s.u1 - s.u0), 0.0, 1.0) : 0.0;
            return s.d_begin + t * (s.d_end - s.d_begin);
        }
    return std::nullopt;
}

double Shaft::min_diameter() const {
    double d = 0;
    for (const auto& s : sections) {
        const double x = std::min(s.d_begin, s.d_end);
        if (x > 0 && (d == 0 || x < d)) d = x;
    }
    return d;
}

// Tip radius for the housing box only: r_a = (d + 2 m_n (1 + x)) / 2, d = z m_n / cos beta
// (ISO 21771 reference diameter and the ISO 53 addendum); an internal gear's outer edge is
// taken as its root circle plus a rim of one module, r = d / 2 + 2.25 m_n.
double Gear::tip_radius_estimate() const {
    if (internal) return 0.5 * z * mn / std::cos(beta) + 2.25 * mn;
    return 0.5 * (z * mn / std::cos(beta) + 2 * mn * (1 + x));
}

void Mapper::warn(const Component& c, const std::string& text) {
    result.warnings.push_back(fmt::format("{}: component {} ({} '{}'): {}", m.file, c.id, c.type, safe_name(c), text));
}

int Mapper::shaft_index_of(std::int64_t id) const {
    const auto it = shaft_of_id.find(id);
    return it == shaft_of_id.end() ? -1 : it->second;
}

// Component types of gear stages the loss model cannot represent: worm, bevel, hypoid and
// crossed-axis stages. Planetary stages are mapped (planetary.cpp).
void Mapper::refuse_unsupported() {
    static const char* const refused[] = {"worm", "bevel", "hypoid", "crossed", "spiral", "face_gear"};
    // The stage is named first (the worm_stage rather than its gear data), then any other part.
    for (const bool stages_only : {true, false})
        for (const auto& c : m.components)
            for (const char* r : refused)
                if (c.type.find(r) != std::string::npos && (!stages_only || c.type.ends_with("_stage")))
                    m.fail(c, "a " + c.type + " is not represented by gearloss's loss model (cylindrical gear stages "
                                  "only); the model is not imported (docs/rexs.md)");
    // Couplings, clutches and synchronisers carry losses the imported case does not count: said, not dropped.
    static const char* const unmapped[] = {"coupling", "clutch", "synchron"};
    for (const auto& c : m.components)
        for (const char* u : unmapped)
            if (c.type.find(u) != std::string::npos) {
                warn(c, "not mapped: its losses are not counted in the imported case");
                break;
            }
}

void Mapper::read_shafts() {
    const auto list = m.of_type("shaft");
    if (list.size() < 2) m.fail("the model has " + std::to_string(list.size()) + " shafts; a gearbox needs at least two");
    std::optional<std::vector<double>> axis0;
    for (const Component* c : list) {
        Shaft s;
        s.comp = c;
        s.name = "shaft_" + std::to_string(c->id);
        const auto axis = numbers(m, *c, "u_axis_vector");
        const auto support = numbers(m, *c, "support_vector");
        if (!axis || axis->size() != 3) m.fail(*c, "the shaft has no u_axis_vector of three numbers");
        if (!support || support->size() != 3) m.fail(*c, "the shaft has no support_vector of three numbers");
        const auto& a = *axis;
        const double na = std::hypot(a[0], a[1], a[2]);
        if (!(na > 0)) m.fail(*c, "u_axis_vector is zero");
        // Parallel shafts along the gear unit's x axis (either direction) are mapped; the housing
        // frame is the gear unit's (y, z), z taken as up.
        if (std::abs(std::abs(a[0]) / na - 1) > 1e-6)
            m.fail(*c, "the shaft's u axis is not along the gear unit's x axis; only parallel shafts along x are "
                       "mapped (crossed or inclined axes are not represented)");
        const Attribute* sv = c->find("support_vector");
        const auto to_m = [&](double v) {
            const auto si = to_si(v, sv->unit, Quantity::length);
            if (!si) m.fail(*c, *sv, "unit '" + sv->unit + "' is not a length");
            return *si;
        };
        s.u_start = to_m((*support)[0]);
        s.x = to_m((*support)[1]);
        s.y = to_m((*support)[2]);
        (void)axis0;
        for (const Relation* r : m.relations_with("assembly", "assembly", c->id)) {
            const auto part = r->ref("part");
            if (!part) continue;
            const Component& p = m.at(*part);
            if (p.type != "shaft_section") continue;
            ShaftSection sec;
            sec.comp = &p;
            sec.u0 = quantity(m, p, "u_coordinate_on_shaft", Quantity::length).value_or(0.0);
            sec.u1 = sec.u0 + required_quantity(m, p, "length", Quantity::length);
            sec.d_begin = required_quantity(m, p, "outer_diameter_begin", Quantity::length);
            sec.d_end = quantity(m, p, "outer_diameter_end", Quantity::length).value_or(sec.d_begin);
            s.sections.push_back(sec);
        }
        std::sort(s.sections.begin(), s.sections.end(), [](const auto& p, const auto& q) { return p.u0 < q.u0; });
        shaft_of_id[c->id] = static_cast<int>(shafts.size());
        shafts.push_back(std::move(s));
    }
}

void Mapper::read_gears() {
    // Cylindrical gears and (REXS 1.1 on) ring gears, an internal gear type of its own.
    for (const auto& cc : m.components) {
        if (cc.type != "cylindrical_gear" && cc.type != "ring_gear") continue;
        const Component* c = &cc;
        Gear g;
        g.comp = c;
        g.name = "gear_" + std::to_string(c->id);
        for (const Relation* r : m.relations_with("assembly", "part", c->id))
            if (const auto a = r->ref("assembly"); a && shaft_index_of(*a) >= 0) g.shaft = shaft_index_of(*a);
        if (g.shaft < 0) m.fail(*c, "the gear is on no shaft (no assembly relation from a shaft)");
        const auto z = integer(m, *c, "number_of_teeth");
        if (!z) m.fail(*c, "attribute 'number_of_teeth' is missing");
        // A ring_gear is internal; a cylindrical_gear with a negative number of teeth too (ISO 21771
        // sign convention, written by some tools although the REXS data model gives z > 0).
        g.internal = *z < 0 || c->type == "ring_gear";
        if (std::abs(*z) < 3 || std::abs(*z) > 10000) m.fail(*c, "number_of_teeth " + std::to_string(*z) + " is not a gear's");
        g.z = static_cast<int>(std::abs(*z));
        g.mn = required_quantity(m, *c, "normal_module", Quantity::length);
        g.b = required_quantity(m, *c, "face_width", Quantity::length);
        g.beta = quantity(m, *c, "helix_angle_reference_diameter", Quantity::angle).value_or(0.0);
        g.u = required_quantity(m, *c, "u_coordinate_on_shaft", Quantity::length);
        // Flank data: the gear's own attribute, else its left and right flanks, which must agree.
        std::vector<const Component*> flanks;
        for (const Relation* r : m.relations_with("flank", "gear", c->id))
            for (const char* side : {"left", "right"})
                if (const auto f = r->ref(side)) flanks.push_back(&m.at(*f));
        const auto flank_value = [&](const std::string& attr, Quantity q) -> std::optional<double> {
            if (auto v = quantity(m, *c, attr, q)) return v;
            std::optional<double> v;
            for (const Component* f : flanks)
                if (auto x = quantity(m, *f, attr, q)) {
                    if (v && std::abs(*v - *x) > 1e-9 * std::max(1.0, std::abs(*x)))
                        m.fail(*f, "its " + attr + " differs from the other flank's; asymmetric teeth are not represented");
                    v = x;
                }
            return v;
        };
        g.alpha_n = flank_value("normal_pressure_angle", Quantity::angle).value_or(20.0 * std::numbers::pi / 180);
        g.x = flank_value("addendum_modification_coefficient", Quantity::dimensionless).value_or(0.0);
        gear_of_id[c->id] = static_cast<int>(gears.size());
        gears.push_back(g);
    }
    if (gears.size() < 2) m.fail("the model has fewer than two cylindrical gears; nothing to map");
}

void Mapper::choose_input_output() {
    // Input: the shaft that defines the speed; output: another shaft with an external load that
    // transmits torque (REXS external_load on the shaft).
    for (size_t i = 0; i < shafts.size(); ++i)
        if (boolean(m, *shafts[i].comp, "defines_speed").value_or(false)) input = static_cast<int>(i);
    for (size_t i = 0; i < shafts.size(); ++i) {
        if (static_cast<int>(i) == input) continue;
        for (const Relation* r : m.relations_with("assembly", "assembly", shafts[i].comp->id))
            if (const auto p = r->ref("part"))
                if (const Component& l = m.at(*p); l.type == "external_load" && boolean(m, l, "transmits_torque").value_or(false))
                    output = static_cast<int>(i);
    }
    const auto plain = [&](int s) { return shafts[static_cast<size_t>(s)].role == ShaftRole::plain; };
    if (input < 0)
        for (const auto& g : gears)
            if (plain(g.shaft)) {
                input = g.shaft;
                break;
            }
    if (input < 0) m.fail("no shaft of the model carries a gear outside a planetary stage's planets");
    if (!plain(input)) m.fail(*shafts[static_cast<size_t>(input)].comp, "the input shaft is a planet shaft or pin");
    if (output < 0 || output == input) {
        for (auto it = gears.rbegin(); it != gears.rend(); ++it)
            if (it->shaft != input && plain(it->shaft)) {
                output = it->shaft;
                break;
            }
    }
}

// A shaft on bearings at more than two axial positions (a three-bearing shaft: valid REXS and
// common in industrial gear units) is statically indeterminate, while gearloss finds its bearing
// loads by the two-support lever rule (gearbox/statics.hpp). The two outermost positions are
// kept and a bearing between them is written at the nearer one, paired with its bearings there:
// its friction is counted, its load is the pair's share rather than the elastic split (a warning
// names it and the case line says it is assumed).
void Mapper::plan_support_positions() {
    std::map<int, std::vector<std::pair<double, const Component*>>> on_shaft;
    for (const auto& c : m.components) {
        if (c.type != "rolling_bearing_with_catalog_geometry" && c.type != "rolling_bearing_with_detailed_geometry" &&
            c.type != "concept_bearing")
            continue;
        const auto sides = m.relations_with("side", "assembly", c.id);
        if (sides.empty() || planet_of_bearing(c, *sides.front()) != -1) continue;
        const auto inner = sides.front()->ref("inner_part"), outer = sides.front()->ref("outer_part");
        int si = inner ? shaft_index_of(*inner) : -1;
        std::string u_attr = "u_coordinate_on_shaft_inner_side";
        if (si < 0 && outer) {
            si = shaft_index_of(*outer);
            u_attr = "u_coordinate_on_shaft_outer_side";
        }
        if (si < 0) continue;
        if (const auto u = quantity(m, c, u_attr, Quantity::length)) on_shaft[si].emplace_back(*u, &c);
    }
    for (const auto& [si, list] : on_shaft) {
        std::set<double> positions;
        for (const auto& [u, c] : list) positions.insert(u);
        if (positions.size() <= 2) continue;
        const double lo = *positions.begin(), hi = *positions.rbegin();
        for (const auto& [u, c] : list) {
            if (u == lo || u == hi) continue;
            const double to = u - lo <= hi - u ? lo : hi;
            support_moved[c->id] = to;
            warn(*c, fmt::format("shaft {} has bearings at {} axial positions (statically indeterminate): the bearing at "
                                 "{:g} mm is written at the nearer outer support, {:g} mm, and shares its load",
                                 shafts[static_cast<size_t>(si)].comp->id, positions.size(), u * 1e3, to * 1e3));
        }
    }
}

// A shaft that carries no gear and sits in no bearing (FVA-Workbench joins the two cheeks of a
// carrier through such a shaft and couplings) has no loss in gearloss's model and no speed the
// gear train fixes: it is written as a comment, with a warning, not as a shaft of the case.
void Mapper::set_aside_unconnected_shafts() {
    for (size_t i = 0; i < shafts.size(); ++i) {
        Shaft& s = shafts[i];
        if (s.role != ShaftRole::plain || static_cast<int>(i) == input || static_cast<int>(i) == output) continue;
        if (std::any_of(gears.begin(), gears.end(), [&](const Gear& g) { return g.shaft == static_cast<int>(i) || g.carrier == static_cast<int>(i); }))
            continue;
        bool in_bearing = false;
        for (const char* role : {"inner_part", "outer_part"})
            for (const Relation* r : m.relations_with("side", role, s.comp->id))
                if (const auto b = r->ref("assembly")) {
                    const std::string& t = m.at(*b).type;
                    in_bearing = in_bearing || t == "rolling_bearing_with_catalog_geometry" ||
                                 t == "rolling_bearing_with_detailed_geometry" || t == "concept_bearing";
                }
        if (in_bearing) continue;
        if (std::any_of(sets.begin(), sets.end(), [&](const PlanetarySet& ps) {
                return std::find(ps.members.begin(), ps.members.end(), static_cast<int>(i)) != ps.members.end();
            }))
            continue;
        s.role = ShaftRole::unconnected;
        s.held_reason = "carries no gear and sits in no bearing: no loss of its own, not a shaft of the case";
        warn(*s.comp, "the shaft " + s.held_reason);
    }
}

void Mapper::write_shafts_gears_meshes(YamlOut& y) {
    y.comment(0, "Shafts: REXS shaft components (axis positions from their support vectors).");
    std::string list;
    for (size_t i = 0; i < shafts.size(); ++i) {
        const Shaft& s = shafts[i];
        if (s.role == ShaftRole::carrier_part || s.role == ShaftRole::unconnected) {
            y.comment(0, s.name + " (REXS " + std::to_string(s.comp->id) + "): " + s.held_reason);
            continue;
        }
        if (s.role != ShaftRole::plain) {
            y.comment(0, s.name + " (REXS " + std::to_string(s.comp->id) + "): a planet " + (s.role == ShaftRole::pin ? "pin" : "shaft") +
                             ", part of the planet gear on its carrier");
            continue;
        }
        if (s.held) y.comment(0, s.name + " fixed: " + s.held_reason);
        list += (list.empty() ? "" : ", ") + shaft_entry(i);
    }
    y.line(0, "shafts: [" + list + "]");
    y.blank();
    y.line(0, "gears:");
    for (const auto& g : gears) {
        const Component& c = *g.comp;
        if (g.written_as >= 0) {
            y.comment(2, "REXS " + std::to_string(c.id) + " cylindrical_gear '" + safe_name(c) + "': a planet like " +
                             gears[static_cast<size_t>(g.written_as)].name + " (its 'planets')");
            continue;
        }
        y.line(2, "- name: " + g.name, "REXS " + std::to_string(c.id) + " " + c.type + " '" + safe_name(c) + "'");
        const Shaft& on = shafts[static_cast<size_t>(g.shaft)];
        if (g.carrier >= 0) {
            // A planet: on the carrier, at its axial place (gear-unit x) measured from the carrier's u = 0.
            const Shaft& cs = shafts[static_cast<size_t>(g.carrier)];
            y.line(4, "carrier: " + cs.name, "REXS planet_carrier_shaft " + std::to_string(cs.comp->id) + " of the planet's stage");
            y.line(4, "planets: " + std::to_string(g.planets), "REXS: the stage's planet gears, identical and equally spaced");
            y.line(4, "position: " + num((on.u_start + g.u - cs.u_start) * 1e3) + " mm",
                   src(c, "u_coordinate_on_shaft") + " on planet shaft " + std::to_string(on.comp->id) + ", from the carrier's u = 0");
        } else {
            y.line(4, "shaft: " + on.name, "REXS assembly relation to shaft " + std::to_string(on.comp->id));
            y.line(4, "position: " + num(g.u * 1e3) + " mm", src(c, "u_coordinate_on_shaft"));
        }
        y.line(4, "teeth: " + std::to_string(g.z), src(c, "number_of_teeth"));
        if (g.internal)
            y.line(4, "internal: true", c.type == "ring_gear" ? "REXS " + std::to_string(c.id) + " ring_gear"
                                                               : src(c, "number_of_teeth") + " < 0 (ISO 21771)");
        y.line(4, "module: " + num(g.mn * 1e3) + " mm", src(c, "normal_module"));
        y.line(4, "face_width: " + num(g.b * 1e3) + " mm", src(c, "face_width"));
        const bool own_alpha = c.find("normal_pressure_angle") != nullptr;
        const bool own_x = c.find("addendum_modification_coefficient") != nullptr;
        std::string flank_ids;
        for (const Relation* r : m.relations_with("flank", "gear", c.id))
            for (const char* side : {"left", "right"})
                if (const auto f = r->ref(side)) flank_ids += (flank_ids.empty() ? "" : "/") + std::to_string(*f);
        bool flank_alpha = false;
        for (const Relation* r : m.relations_with("flank", "gear", c.id))
            for (const char* side : {"left", "right"})
                if (const auto f = r->ref(side); f && m.at(*f).find("normal_pressure_angle")) flank_alpha = true;
        // No pressure angle in REXS: the case omits it and the case loader assumes the ISO 53 rack (listed by check).
        if (own_alpha || flank_alpha)
            y.line(4, "pressure_angle: " + num(g.alpha_n * 180 / std::numbers::pi) + " deg",
                   own_alpha ? src(c, "normal_pressure_angle") : "REXS flanks " + flank_ids + " normal_pressure_angle");
        y.line(4, "profile_shift: " + num(g.x),
               own_x ? src(c, "addendum_modification_coefficient")
                     : (flank_ids.empty() ? "REXS gives none: 0" : "REXS flanks " + flank_ids + " addendum_modification_coefficient"));
        const double beta_deg = g.beta * 180 / std::numbers::pi;
        if (std::abs(beta_deg) > 1e-9) {
            y.line(4, "helix_angle: " + num(std::abs(beta_deg)) + " deg", src(c, "helix_angle_reference_diameter"));
            // ISO 21771 / DIN 3960, as REXS: a positive helix angle is a right-hand helix.
            y.line(4, std::string("hand: ") + (beta_deg > 0 ? "right" : "left"),
                   "sign of REXS " + std::to_string(c.id) + " helix_angle_reference_diameter (positive: right hand)");
        }
        if (const auto da = quantity(m, c, "tip_diameter", Quantity::length)) {
            const double d = g.z * g.mn / std::cos(g.beta);
            const bool plausible = g.internal ? *da < d : *da > d;
            if (plausible) y.line(4, "tip_diameter: " + num(*da * 1e3) + " mm", src(c, "tip_diameter"));
            else
                warn(c, fmt::format("tip_diameter {:g} mm is {} the reference diameter {:.4g} mm: not imported "
                                    "(the tip follows from the profile shift)",
                                    *da * 1e3, g.internal ? "not below" : "not above", d * 1e3));
        }
        for (const Relation* r : m.relations_with("flank", "gear", c.id))
            for (const char* side : {"left", "right"})
                if (const auto f = r->ref(side))
                    if (const auto ra = quantity(m, m.at(*f), "arithmetic_average_roughness_flank", Quantity::length)) {
                        y.line(4, "Ra: " + num(*ra * 1e6) + " um", src(m.at(*f), "arithmetic_average_roughness_flank"));
                        goto roughness_done;
                    }
        if (const auto ra = quantity(m, c, "arithmetic_average_roughness_flank", Quantity::length))
            y.line(4, "Ra: " + num(*ra * 1e6) + " um", src(c, "arithmetic_average_roughness_flank"));
    roughness_done:
        for (const Relation* r : m.relations_with("reference", "origin", c.id))
            if (const auto mat = r->ref("referenced"); mat && m.at(*mat).type == "material") {
                y.line(4, "material: material_" + std::to_string(*mat), "REXS reference relation to material " + std::to_string(*mat));
                break;
            }
    }
    y.blank();
    y.line(0, "meshes:");
    const auto stages = m.of_type("cylindrical_stage");
    if (stages.empty()) m.fail("the model has no cylindrical_stage: no gear mesh to map");
    for (const Component* st : stages) {
        const auto rels = m.relations_with("stage", "stage", st->id);
        if (rels.empty()) m.fail(*st, "the stage has no stage relation naming its gears");
        const auto g1 = rels.front()->ref("gear_1");
        const auto g2 = rels.front()->ref("gear_2");
        if (!g1 || !g2) m.fail(*rels.front(), "a stage relation names gear_1 and gear_2");
        if (!gear_of_id.count(*g1) || !gear_of_id.count(*g2))
            m.fail(*st, "its gears are not both cylindrical gears");
        if (*g1 == *g2) m.fail(*st, "its stage relation names the same gear twice");
        // gearloss names an internal gear second in its mesh.
        const bool swap = gears[static_cast<size_t>(gear_of_id[*g1])].internal;
        const Gear& a = gears[static_cast<size_t>(gear_of_id[swap ? *g2 : *g1])];
        const Gear& b = gears[static_cast<size_t>(gear_of_id[swap ? *g1 : *g2])];
        if (a.internal && b.internal) m.fail(*st, "both its gears are internal");
        const Shaft& sa = shafts[static_cast<size_t>(a.shaft)];
        const Shaft& sb = shafts[static_cast<size_t>(b.shaft)];
        const double dx = sb.x - sa.x, dy = sb.y - sa.y;
        const double axes = std::hypot(dx, dy);
        const auto ad = quantity(m, *st, "center_distance", Quantity::length);
        // The two shafts must stand the centre distance apart (data that contradicts itself is refused).
        if (ad && std::abs(axes - *ad) > 1e-3 * *ad + 1e-6)
            m.fail(*st, fmt::format("center_distance {:g} mm, but the axes of shafts {} and {} are {:.6g} mm apart",
                                    *ad * 1e3, sa.comp->id, sb.comp->id, axes * 1e3));
        if (a.written_as >= 0 || b.written_as >= 0) {
            y.comment(2, "REXS " + std::to_string(st->id) + " cylindrical_stage '" + safe_name(*st) + "': a mesh of another planet (" +
                             (a.written_as >= 0 ? gears[static_cast<size_t>(a.written_as)] : gears[static_cast<size_t>(b.written_as)]).name +
                             "'s 'planets')");
            continue;
        }
        y.line(2, "- name: stage_" + std::to_string(st->id), "REXS " + std::to_string(st->id) + " cylindrical_stage '" + safe_name(*st) + "'");
        y.line(4, "gears: [" + a.name + ", " + b.name + "]",
               "REXS stage relation " + std::to_string(rels.front()->id) + (swap ? " gear_2, gear_1 (internal gear second)" : " gear_1, gear_2"));
        // A planetary mesh is laid out by gearloss (planet on the carrier); a fixed-axis one by the shafts.
        if (a.carrier < 0 && b.carrier < 0)
            y.line(4, "angle: " + num(std::atan2(dy, dx) * 180 / std::numbers::pi) + " deg",
                   "from the shafts' support vectors (gear unit y, z; z taken as up: assumed)");
        if (ad) y.line(4, "centre_distance: " + num(*ad * 1e3) + " mm", src(*st, "center_distance"));
    }
    y.blank();
}

}  // namespace detail

ImportResult map_to_case(const Model& m, const ImportOptions& options) {
    detail::Mapper mp{m, options, {}, {}, {}, -1, -1, {}, {}, {}, {}};
    mp.refuse_unsupported();
    mp.read_shafts();
    mp.read_gears();
    mp.read_planetary();
    mp.choose_input_output();
    mp.hold_planetary_members();
    mp.plan_support_positions();
    mp.set_aside_unconnected_shafts();
    detail::YamlOut y;
    y.comment(0, "Imported from the REXS model " + io::excerpt(m.file, 120) + " (REXS " + m.version + ", " +
                     io::excerpt(m.application_id, 40) + " " + io::excerpt(m.application_version, 40) + ") by gearloss import.");
    y.comment(0, "Each value names the REXS component id and attribute it came from; 'assumed' marks what REXS does not");
    y.comment(0, "carry and the loss model needs (docs/rexs.md). Check with: gearloss check THIS_FILE");
    const auto units = m.of_type("gear_unit");
    y.line(0, "name: " + detail::quoted((units.empty() ? std::string("REXS gearbox") : units.front()->name) + " (REXS)"),
           units.empty() ? "" : "REXS " + std::to_string(units.front()->id) + " gear_unit name");
    y.line(0, "oil: " + detail::quoted(options.oil_reference, 4096),
           options.write_oil ? "the REXS lubricant, written beside this file" : "given with --oil (the REXS lubricant is not used)");
    y.blank();
    // Materials of the gears that reference one (REXS reference relation gear -> material).
    bool any_material = false;
    std::set<std::int64_t> written;
    for (const auto& g : mp.gears)
        for (const Relation* r : m.relations_with("reference", "origin", g.comp->id))
            if (const auto mat = r->ref("referenced"); mat && m.at(*mat).type == "material" && written.insert(*mat).second) {
                const Component& c = m.at(*mat);
                if (!any_material) y.line(0, "materials:");
                any_material = true;
                y.line(2, "material_" + std::to_string(c.id) + ":", "REXS " + std::to_string(c.id) + " material '" + detail::safe_name(c) + "'");
                y.line(4, "E: " + detail::num(required_quantity(m, c, "elastic_modulus", Quantity::pressure) * 1e-9) + " GPa",
                       detail::src(c, "elastic_modulus"));
                y.line(4, "poisson: " + detail::num(required_quantity(m, c, "poisson_ratio", Quantity::dimensionless)), detail::src(c, "poisson_ratio"));
                y.line(4, "density: " + detail::num(required_quantity(m, c, "density", Quantity::density)) + " kg/m^3", detail::src(c, "density"));
            }
    if (any_material) y.blank();
    mp.write_shafts_gears_meshes(y);
    mp.write_bearings(y);
    mp.write_seals(y);
    mp.write_housing_thermal(y);
    y.line(0, "gearbox:");
    y.line(2, "input: " + mp.shafts[static_cast<size_t>(mp.input)].name, "REXS shaft with defines_speed true");
    y.line(2, "output: " + mp.shafts[static_cast<size_t>(mp.output)].name, "REXS shaft with an external load transmitting torque");
    y.blank();
    mp.write_operating(y);
    y.write_assumed_list();
    mp.result.case_yaml = y.str();
    if (options.write_oil) mp.result.oil_yaml = mp.oil_yaml();
    return mp.result;
}

}  // namespace gearloss::rexs
