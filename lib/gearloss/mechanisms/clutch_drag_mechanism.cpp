// Drag of open wet clutch packs as a loss mechanism (gearloss/clutch/wet_clutch.hpp): its heat goes
// to the clutch-pack node of a thermal network, not straight into the oil.
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/clutch/film_heating.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::clutch {
namespace {

constexpr double rad_s_to_rpm = 30.0 / std::numbers::pi;

struct ClutchPoint : losses::MechanismPointOf<ClutchPoint> {
    std::vector<double> slip;  // per pack [rad/s] (0 when engaged)
};

class ClutchDragMechanism final : public losses::LossMechanism {
public:
    // Per pack: its drag and, for the point report only, the state of its film (FilmRegime as a
    // number, NaN when engaged): the drag of an open pack peaks and falls with speed once the
    // supply cannot fill the gap (the film breaks up into streaks beyond the wetted radius of
    // Yuan et al. 2007), a regime the report names.
    enum : size_t { kPower, kRegime, kQuantities };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<ClutchDragMechanism>(*this); }
    std::string_view name() const override { return "clutch_drag"; }
    std::string_view label() const override { return "clutch drag"; }
    std::string_view column() const override { return "P_clutch_W"; }
    bool heats_oil() const override { return false; }
    std::vector<std::string> components(const solver::Model& m) const override {
        return losses::names_of(m.gearbox.clutches, [](const auto& c) { return c.pack.name; });
    }
    std::vector<losses::DetailQuantity> quantities() const override { return {{"P_clutch_{}_W", 1.0}, {"", 1.0}}; }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<ClutchPoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        auto& p = static_cast<ClutchPoint&>(out);
        const auto& gb = m.gearbox;
        p.slip.assign(gb.clutches.size(), 0.0);
        if (!enabled()) return;  // switched off: no pack slips, no drag
        for (size_t i = 0; i < gb.clutches.size(); ++i) p.slip[i] = m.layout.clutch_slip_ratio[i] * std::abs(in.omega_in);
    }
    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const ClutchPoint&>(pt);
        for (size_t i = 0; i < p.slip.size(); ++i)
            if (!std::isfinite(p.slip[i])) return "clutch " + m.gearbox.clutches[i].pack.name + " slip";
        return {};
    }
    double power(const solver::Model& m, const losses::MechanismPoint& pt, losses::Evaluation& e,
                 losses::MechanismDetail* d) const override {
        const auto& p = static_cast<const ClutchPoint&>(pt);
        if (d) {
            d->reset(p.slip.size(), kQuantities);
            for (size_t i = 0; i < p.slip.size(); ++i) d->at(i, kRegime) = std::nan("");
        }
        double total = 0.0;
        for (size_t i = 0; i < p.slip.size(); ++i) {
            if (p.slip[i] == 0.0) continue;
            const auto& pack = m.gearbox.clutches[i].pack;
            const ClutchDrag drag = open_pack_drag(pack, e.oil, p.slip[i]);
            total += drag.power;
            if (d) {
                d->at(i, kPower) = drag.power;
                d->at(i, kRegime) = double(drag.regime);
            }
        }
        return total;
    }
    std::string loss_fault(const solver::Model& m, const losses::MechanismPoint&,
                           const losses::MechanismDetail& d) const override {
        for (size_t i = 0; i < m.gearbox.clutches.size(); ++i)
            if (!(std::isfinite(d.at(i, kPower)) && d.at(i, kPower) >= 0)) return "clutch " + m.gearbox.clutches[i].pack.name + " drag";
        return {};
    }
    std::string report(const solver::Model& m, const losses::PointInput& in, const losses::MechanismPoint&,
                       const losses::MechanismDetail& d) const override {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        if (gb.clutches.empty()) return {};
        // The last column names the film's regime (engaged, or the FilmRegime of an open pack):
        // a step of the drag between two points is physics where it changes.
        std::string s = "clutch packs          slip [rpm]   P [W]     regime\n";
        for (size_t i = 0; i < gb.clutches.size(); ++i) {
            const double regime = d.at(i, kRegime);
            const bool engaged = L.clutch_slip_ratio[i] == 0.0;
            s += fmt::format("  {:<18} {:10.1f} {:8.2f}  {}\n", gb.clutches[i].pack.name,
                             L.clutch_slip_ratio[i] * std::abs(in.omega_in) * rad_s_to_rpm, d.at(i, kPower),
                             engaged                  ? std::string_view("engaged")
                             : std::isfinite(regime) ? to_string(FilmRegime(int(regime)))
                                                     : std::string_view("not_slipping"));
        }
        return s;
    }
};

}  // namespace
}  // namespace gearloss::clutch

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_clutch_drag() { return make_mechanism<clutch::ClutchDragMechanism>(); }
}  // namespace gearloss::losses
