// A REXS planetary_stage as a gearloss planetary set (docs/rexs.md, "Planetary stages").
//
// REXS (data model 1.1 to 1.6) names the parts of a planetary stage by relations from the
// planetary_stage component to shafts: `central_shaft` (the sun's and the ring's shafts),
// `planet_carrier_shaft` (the carrier), `planet_shaft` (one per planet, carrying its gear) and
// `planet_pin` (the pins the planets turn on). Every planet is a cylindrical_gear of its own, with
// its own cylindrical_stage to the sun and to the ring; the ring is a `ring_gear` (or a
// cylindrical_gear with a negative number of teeth, ISO 21771). gearloss's planetary set
// (docs/config.md) is one planet gear on the carrier with a count of identical, equally spaced
// planets, so the planets are checked to be that and the first is written for all.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "gearloss/core/errors.hpp"
#include "gearloss/rexs/mapper_internal.hpp"

namespace gearloss::rexs::detail {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::max(std::abs(a), std::abs(b))); }

}  // namespace

std::string Mapper::shaft_entry(size_t i) const {
    return shafts[i].held ? "{name: " + shafts[i].name + ", fixed: true}" : shafts[i].name;
}

// A carrier of several shafts: FVA-Workbench writes a two-cheek carrier as coaxial shafts, each
// a planet_carrier_shaft of the stage, joined through couplings and side plates. They turn as
// one, so gearloss's carrier is the one that is supported or loaded (a bearing, an external
// load); the others are parts of it, written as comments. A gear or bearing on such a part, or
// a part off the carrier's axis, is refused at the shaft.
int Mapper::carrier_of(const Component& st, const std::vector<int>& carriers) {
    const auto is_bearing = [](const Component& c) {
        return c.type == "rolling_bearing_with_catalog_geometry" || c.type == "rolling_bearing_with_detailed_geometry" ||
               c.type == "concept_bearing";
    };
    const auto bearings_on = [&](int i) {
        std::vector<const Component*> out;
        const std::int64_t id = shafts[static_cast<size_t>(i)].comp->id;
        for (const char* role : {"inner_part", "outer_part"})
            for (const Relation* r : m.relations_with("side", role, id))
                if (const auto b = r->ref("assembly"); b && is_bearing(m.at(*b))) out.push_back(&m.at(*b));
        return out;
    };
    const auto loaded = [&](int i) {
        for (const Relation* r : m.relations_with("assembly", "assembly", shafts[static_cast<size_t>(i)].comp->id))
            if (const auto p = r->ref("part"); p && m.at(*p).type == "external_load") return true;
        return false;
    };
    if (carriers.size() == 1) return carriers.front();
    int carrier = -1;
    for (int i : carriers)
        if (carrier < 0 && (!bearings_on(i).empty() || loaded(i))) carrier = i;
    if (carrier < 0) carrier = carriers.front();
    const Shaft& cs = shafts[static_cast<size_t>(carrier)];
    for (int i : carriers) {
        if (i == carrier) continue;
        Shaft& s = shafts[static_cast<size_t>(i)];
        if (std::hypot(s.x - cs.x, s.y - cs.y) > 1e-6)
            m.fail(*s.comp, fmt::format("a planet_carrier_shaft of planetary stage {} off the axis of its carrier shaft {}", st.id,
                                        cs.comp->id));
        for (const auto& g : gears)
            if (g.shaft == i)
                m.fail(*s.comp, fmt::format("the second carrier shaft of planetary stage {} carries gear {}: gearloss's carrier "
                                            "is one shaft",
                                            st.id, g.comp->id));
        if (const auto b = bearings_on(i); !b.empty())
            m.fail(*s.comp, fmt::format("the second carrier shaft of planetary stage {} sits in bearing {}: gearloss's carrier "
                                        "is one shaft (its bearings on shaft {})",
                                        st.id, b.front()->id, cs.comp->id));
        s.role = ShaftRole::carrier_part;
        s.held_reason = fmt::format("a part of the carrier of planetary stage {} (REXS planet_carrier_shaft), turning with "
                                    "shaft {}",
                                    st.id, cs.comp->id);
    }
    return carrier;
}

void Mapper::read_planetary() {
    // The gear pairs of every cylindrical_stage (gear indices), to find what each planet meshes.
    std::vector<std::pair<const Component*, std::pair<int, int>>> pairs;
    for (const Component* st : m.of_type("cylindrical_stage"))
        for (const Relation* r : m.relations_with("stage", "stage", st->id)) {
            const auto g1 = r->ref("gear_1"), g2 = r->ref("gear_2");
            if (g1 && g2 && gear_of_id.count(*g1) && gear_of_id.count(*g2))
                pairs.push_back({st, {gear_of_id.at(*g1), gear_of_id.at(*g2)}});
        }
    // A planet shaft or pin belongs to one stage; within a stage a shaft has one part. (A carrier
    // may be the next stage's sun shaft: two sets on one shaft.)
    std::set<int> planet_or_pin;
    for (const Component* st : m.of_type("planetary_stage")) {
        PlanetarySet ps;
        ps.stage = st;
        std::set<int> claimed;
        const auto shafts_of = [&](const char* rel) {
            std::vector<int> out;
            for (const Relation* r : m.relations_with(rel, "planetary_stage", st->id)) {
                const auto id = r->ref("shaft");
                if (!id) m.fail(*r, std::string("a ") + rel + " relation names the stage and a shaft (role 'shaft')");
                const int i = shaft_index_of(*id);
                if (i < 0) m.fail(*st, fmt::format("its {} relation names component {}, which is not a shaft", rel, *id));
                if (!claimed.insert(i).second)
                    m.fail(*shafts[static_cast<size_t>(i)].comp,
                           fmt::format("the shaft is named twice as a part of planetary stage {} (again as its {})", st->id, rel));
                out.push_back(i);
            }
            return out;
        };
        const auto central = shafts_of("central_shaft");
        const auto carriers = shafts_of("planet_carrier_shaft");
        const auto planet_shafts = shafts_of("planet_shaft");
        const auto pins = shafts_of("planet_pin");
        if (carriers.empty())
            m.fail(*st, "no planet_carrier_shaft relation names the stage's carrier: its planets are carried by nothing");
        if (central.size() > 2) m.fail(*st, "more than two central_shaft relations: a stage has one sun and one ring");
        ps.carrier = carrier_of(*st, carriers);
        for (const auto* list : {&planet_shafts, &pins})
            for (int i : *list)
                if (!planet_or_pin.insert(i).second)
                    m.fail(*shafts[static_cast<size_t>(i)].comp, fmt::format("the planet shaft or pin of planetary stage {} is one of "
                                                                             "another stage too",
                                                                             st->id));
        for (int i : planet_shafts) shafts[static_cast<size_t>(i)].role = ShaftRole::planet;
        for (int i : pins) shafts[static_cast<size_t>(i)].role = ShaftRole::pin;
        for (int i : central)
            if (planet_or_pin.count(i) || std::find(carriers.begin(), carriers.end(), i) != carriers.end())
                m.fail(*shafts[static_cast<size_t>(i)].comp, fmt::format("a central shaft of planetary stage {} is its carrier or a planet's too", st->id));
        const auto is_central = [&](int s) { return std::find(central.begin(), central.end(), s) != central.end(); };

        // The planets: the gear on each planet shaft, and a gear sitting on a pin itself.
        for (int s : planet_shafts) {
            std::vector<int> on;
            for (size_t g = 0; g < gears.size(); ++g)
                if (gears[g].shaft == s) on.push_back(static_cast<int>(g));
            const Component& sc = *shafts[static_cast<size_t>(s)].comp;
            if (on.empty()) m.fail(sc, fmt::format("the planet shaft of planetary stage {} carries no gear", st->id));
            if (on.size() > 1)
                m.fail(sc, fmt::format("the planet shaft of planetary stage {} carries {} gears (a stepped planet): gearloss's "
                                       "planetary set has one gear per planet",
                                       st->id, on.size()));
            ps.planets.push_back(on.front());
        }
        for (int s : pins)
            for (size_t g = 0; g < gears.size(); ++g)
                if (gears[g].shaft == s) {
                    if (std::count_if(gears.begin(), gears.end(), [&](const Gear& x) { return x.shaft == s; }) > 1)
                        m.fail(*shafts[static_cast<size_t>(s)].comp, "the planet pin carries several gears (a stepped planet): not represented");
                    ps.planets.push_back(static_cast<int>(g));
                }
        if (ps.planets.empty()) m.fail(*st, "no planet: no planet_shaft or planet_pin relation names a shaft carrying a gear");
        if (ps.planets.size() > 12) m.fail(*st, fmt::format("{} planets: gearloss's planetary set takes 1 to 12", ps.planets.size()));
        const std::set<int> planet_set(ps.planets.begin(), ps.planets.end());

        // Sun and ring: the gears on central shafts the planets mesh; nothing else may mesh a planet.
        std::vector<int> externals;
        for (int p : ps.planets) {
            int partners = 0;
            for (const auto& [stc, gp] : pairs) {
                if (gp.first != p && gp.second != p) continue;
                const int q = gp.first == p ? gp.second : gp.first;
                ++partners;
                if (planet_set.count(q) || gears[static_cast<size_t>(q)].carrier >= 0)
                    m.fail(*stc, fmt::format("it meshes two planets ({} and {}): a stage whose planets mesh each other (double "
                                             "planets) is not represented",
                                             gears[static_cast<size_t>(p)].comp->id, gears[static_cast<size_t>(q)].comp->id));
                const Gear& gq = gears[static_cast<size_t>(q)];
                if (!is_central(gq.shaft))
                    m.fail(*stc, fmt::format("planet {} of planetary stage {} meshes gear {} on shaft {}, which the stage names no "
                                             "central_shaft",
                                             gears[static_cast<size_t>(p)].comp->id, st->id, gq.comp->id,
                                             shafts[static_cast<size_t>(gq.shaft)].comp->id));
                if (gq.internal) {
                    if (ps.ring >= 0 && ps.ring != q)
                        m.fail(*gq.comp, fmt::format("a second internal gear meshing the planets of planetary stage {} (the ring is {})",
                                                     st->id, gears[static_cast<size_t>(ps.ring)].comp->id));
                    ps.ring = q;
                } else if (std::find(externals.begin(), externals.end(), q) == externals.end()) {
                    externals.push_back(q);
                }
            }
            if (partners == 0)
                m.fail(*gears[static_cast<size_t>(p)].comp,
                       fmt::format("the planet of planetary stage {} meshes nothing (no cylindrical_stage names it)", st->id));
        }
        if (externals.size() > 1) {
            // Two external central gears: the larger sits outside the planets where the ring must be.
            std::sort(externals.begin(), externals.end(), [&](int a, int b) { return gears[static_cast<size_t>(a)].z < gears[static_cast<size_t>(b)].z; });
            const Gear& r = gears[static_cast<size_t>(externals.back())];
            m.fail(*r.comp, fmt::format("meshes the planets of planetary stage {} as a second central gear beside the sun {} but is "
                                        "an external gear (number_of_teeth {}): a ring is internal (a REXS ring_gear, or a "
                                        "negative number of teeth, ISO 21771)",
                                        st->id, gears[static_cast<size_t>(externals.front())].comp->id, r.z));
        }
        if (!externals.empty()) ps.sun = externals.front();
        // Equally spaced identical planets mesh sun and ring in phase only when (z_s + z_r) / N is whole.
        const int n_planets = static_cast<int>(ps.planets.size());
        if (ps.sun >= 0 && ps.ring >= 0 && n_planets >= 2) {
            const int z_sum = gears[static_cast<size_t>(ps.sun)].z + gears[static_cast<size_t>(ps.ring)].z;
            if (z_sum % n_planets != 0)
                m.fail(*st, fmt::format("{} planets cannot be equally spaced: z_sun + z_ring = {} is not a multiple of {}", n_planets,
                                        z_sum, n_planets));
        }

        // Identical planets, equally spaced on one circle about the carrier's axis.
        const Gear& g0 = gears[static_cast<size_t>(ps.planets.front())];
        for (int p : ps.planets) {
            const Gear& g = gears[static_cast<size_t>(p)];
            if (g.z != g0.z || !same(g.mn, g0.mn) || !same(g.b, g0.b) || !same(g.beta, g0.beta) || !same(g.x, g0.x) ||
                !same(g.alpha_n, g0.alpha_n))
                m.fail(*g.comp, fmt::format("the planet differs from planet {} of planetary stage {} (teeth, module, face width, helix, "
                                            "pressure angle or profile shift): planets of different gears are not represented",
                                            g0.comp->id, st->id));
        }
        const Shaft& cs = shafts[static_cast<size_t>(ps.carrier)];
        for (int s : central) {
            const Shaft& c = shafts[static_cast<size_t>(s)];
            if (std::hypot(c.x - cs.x, c.y - cs.y) > 1e-5)
                m.fail(*c.comp, fmt::format("the central shaft of planetary stage {} is not coaxial with its carrier shaft {} ({:.4g} mm "
                                            "apart)",
                                            st->id, cs.comp->id, std::hypot(c.x - cs.x, c.y - cs.y) * 1e3));
        }
        std::vector<double> angles;
        const Shaft& s0 = shafts[static_cast<size_t>(g0.shaft)];
        const double r0 = std::hypot(s0.x - cs.x, s0.y - cs.y);
        for (int p : ps.planets) {
            const Shaft& s = shafts[static_cast<size_t>(gears[static_cast<size_t>(p)].shaft)];
            const double r = std::hypot(s.x - cs.x, s.y - cs.y);
            if (std::abs(r - r0) > 1e-3 * r0 + 1e-6)
                m.fail(*s.comp, fmt::format("the planet's axis is {:.6g} mm from the carrier axis, planet {}'s {:.6g} mm: the planets of "
                                            "planetary stage {} are not on one circle",
                                            r * 1e3, g0.comp->id, r0 * 1e3, st->id));
            angles.push_back(std::atan2(s.y - cs.y, s.x - cs.x));
        }
        std::sort(angles.begin(), angles.end());
        const size_t n = angles.size();
        for (size_t i = 0; i < n && n > 1; ++i) {
            const double gap = i + 1 < n ? angles[i + 1] - angles[i] : angles.front() + 2 * std::numbers::pi - angles.back();
            if (std::abs(gap - 2 * std::numbers::pi / static_cast<double>(n)) > 0.5 * kDeg)
                m.fail(*st, fmt::format("its {} planets are not equally spaced (a gap of {:.2f} deg, not {:.2f} deg): gearloss's "
                                        "planetary set has equally spaced planets",
                                        n, gap / kDeg, 360.0 / static_cast<double>(n)));
        }
        for (size_t i = 0; i < ps.planets.size(); ++i) {
            Gear& g = gears[static_cast<size_t>(ps.planets[i])];
            g.carrier = ps.carrier;
            g.planets = static_cast<int>(ps.planets.size());
            if (i > 0) g.written_as = ps.planets.front();
        }
        ps.members = central;
        ps.members.push_back(ps.carrier);
        sets.push_back(std::move(ps));
    }
    // A planet, planet shaft or pin with no planetary stage: a planet_carrier without its stage's relations.
    for (const Component* c : m.of_type("planet_carrier"))
        if (sets.empty())
            m.fail(*c, "a planet carrier without a planetary_stage naming its shafts (central_shaft, planet_carrier_shaft, "
                       "planet_shaft relations)");
}

// The member of each planetary set that the housing holds: one whose speed REXS gives as zero,
// else the one member that is neither the input nor the output and carries nothing else (no
// other gear, no torque-transmitting load, no other stage): with the other two members driven,
// a single-degree-of-freedom train needs it held (Willis 1841: one relation among three speeds).
void Mapper::hold_planetary_members() {
    for (const PlanetarySet& ps : sets) {
        const Component& st = *ps.stage;
        std::vector<int> zero;
        for (int s : ps.members) {
            const Component& c = *shafts[static_cast<size_t>(s)].comp;
            bool given = false, all_zero = true;
            if (const auto v = quantity(m, c, "rotational_speed", Quantity::rotational_speed)) {
                given = true;
                all_zero = all_zero && *v == 0;
            }
            for (const auto& lc : m.load_cases)
                if (const Component* l = lc.find(c.id))
                    if (const auto v = quantity(m, *l, "rotational_speed", Quantity::rotational_speed)) {
                        given = true;
                        all_zero = all_zero && *v == 0;
                    }
            if (given && all_zero) zero.push_back(s);
        }
        const auto connected = [&](int s) {
            if (s == input || s == output) return true;
            for (size_t g = 0; g < gears.size(); ++g)
                if (gears[g].shaft == s && static_cast<int>(g) != ps.sun && static_cast<int>(g) != ps.ring) return true;
            for (const PlanetarySet& other : sets)
                if (&other != &ps && std::find(other.members.begin(), other.members.end(), s) != other.members.end()) return true;
            for (const Relation* r : m.relations_with("assembly", "assembly", shafts[static_cast<size_t>(s)].comp->id))
                if (const auto p = r->ref("part"))
                    if (const Component& l = m.at(*p); l.type == "external_load" && boolean(m, l, "transmits_torque").value_or(false))
                        return true;
            return false;
        };
        std::string names;
        for (int s : ps.members) names += (names.empty() ? "" : ", ") + std::to_string(shafts[static_cast<size_t>(s)].comp->id);
        if (!zero.empty()) {
            for (int s : zero) {
                Shaft& sh = shafts[static_cast<size_t>(s)];
                if (s == input || s == output)
                    m.fail(*sh.comp, "rotational_speed 0, but it is the gearbox's input or output shaft");
                sh.held = true;
                sh.held_reason = fmt::format("REXS {} rotational_speed 0: held by the housing", sh.comp->id);
            }
            continue;
        }
        std::vector<int> free;
        for (int s : ps.members)
            if (!connected(s)) free.push_back(s);
        if (free.empty())
            m.fail(st, "none of its members (shafts " + names + ") is held by the housing (rotational_speed 0) or free of other "
                       "connections: a stage with three driven members (summing or splitting power) is not represented");
        if (free.size() > 1 || ps.members.size() < 3)
            m.fail(st, fmt::format("members (shafts {}) are connected to nothing else; gearloss needs the two others driven and "
                                   "one held: the stage transmits no power as modelled",
                                   names));
        Shaft& sh = shafts[static_cast<size_t>(free.front())];
        sh.held = true;
        sh.held_reason = fmt::format("assumed: the member of planetary stage {} that is neither input nor output nor connected to "
                                     "anything else is held by the housing (REXS names no fixed member)",
                                     st.id);
    }
}

int Mapper::planet_of_bearing(const Component& bearing, const Relation& side) const {
    const auto inner = side.ref("inner_part"), outer = side.ref("outer_part");
    int planet_side = -1, other = -1;
    for (const auto& id : {inner, outer}) {
        const int s = id ? shaft_index_of(*id) : -1;
        const ShaftRole role = s >= 0 ? shafts[static_cast<size_t>(s)].role : ShaftRole::plain;
        if (role == ShaftRole::planet || role == ShaftRole::pin) (planet_side < 0 ? planet_side : other) = s;
        else if (s >= 0) other = s;
    }
    if (planet_side < 0) return -1;
    // The planet gear on either side (a gear on the planet shaft, or on the pin itself).
    int planet = -1;
    for (const auto& id : {inner, outer}) {
        const int s = id ? shaft_index_of(*id) : -1;
        for (size_t g = 0; s >= 0 && g < gears.size(); ++g)
            if (gears[g].shaft == s && (gears[g].carrier >= 0 || gears[g].written_as >= 0)) planet = static_cast<int>(g);
    }
    if (planet < 0) m.fail(bearing, "the bearing sits on a planet pin or planet shaft but carries no planet gear");
    const Gear& g = gears[static_cast<size_t>(planet)];
    const int first = g.written_as >= 0 ? g.written_as : planet;
    const int carrier = gears[static_cast<size_t>(first)].carrier;
    if (other >= 0 && other != carrier && shafts[static_cast<size_t>(other)].role == ShaftRole::plain)
        m.fail(bearing, fmt::format("the bearing runs between planet shaft {} and shaft {}, which is neither a planet pin nor the "
                                    "carrier: a planet turning in another shaft is not represented",
                                    shafts[static_cast<size_t>(planet_side)].comp->id, shafts[static_cast<size_t>(other)].comp->id));
    return g.written_as >= 0 ? -2 : planet;
}

}  // namespace gearloss::rexs::detail
