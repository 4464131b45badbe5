// Churning of dip-lubricated gears as a loss mechanism: Changenet & Velex (2007, 2008)
// per immersed gear (gearloss/churning/changenet_velex.hpp), with a calibration factor. The
// torque is the running minimum over Re_c of the published curve (regime 'capped' beyond
// its minimum), precomputed per gear in prepare(): the hot path adds one comparison. (The drag of
// the air/oil mist is the windage mechanism's, gearloss/windage/gear_windage.cpp.)
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/churning/changenet_velex.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::churning {
namespace {

constexpr double rad_s_to_rpm = 30.0 / std::numbers::pi;

struct ChurningPoint : losses::MechanismPointOf<ChurningPoint> {
    std::vector<ChurningAtSpeed> gears;  // per gear (zero coefficients: not immersed)
};

class Churning final : public losses::LossMechanism {
public:
    enum : size_t { kFactor };
    enum : size_t { kPower, kRegime, kQuantities };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<Churning>(*this); }
    std::string_view name() const override { return "churning"; }
    std::string_view label() const override { return "churning"; }
    std::string_view column() const override { return "P_churn_W"; }
    std::vector<std::string> components(const solver::Model& m) const override {
        return losses::names_of(m.gearbox.gears, [](const auto& g) { return g.spec.name; });
    }
    std::vector<losses::DetailQuantity> quantities() const override { return {{"P_churn_{}_W", 1.0}, {"", 1.0}}; }
    std::vector<losses::Parameter> parameters() const override {
        return {{"factor", "scales every churning loss", nullptr, "1.3", 1.0, 0.0, 100.0, true, "churning",
                 "churning level of the dipping gears (immersion or oil level) differs from the description"}};
    }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<ChurningPoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        auto& p = static_cast<ChurningPoint&>(out);
        p.gears.assign(gb.gears.size(), ChurningAtSpeed{});
        if (!enabled()) return;
        for (size_t g = 0; g < gb.gears.size(); ++g) {
            const double h = L.gear_immersion[g];
            if (h <= 0.0) continue;
            const auto& spec = gb.gears[g].spec;
            DippingGear dg;
            dg.Rp = 0.5 * spec.d();
            dg.b = spec.b;
            dg.z = spec.z;
            dg.tooth_height = spec.mn * (spec.ha_star + spec.hf_star);
            dg.alpha = spec.alpha_t();
            dg.h = h;
            const double w = L.body_speed_ratio[L.body_of_gear[g]] * in.omega_in;
            p.gears[g] = ChurningAtSpeed::make(dg, w, gb.oil_volume);
        }
    }

    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const ChurningPoint&>(pt);
        for (size_t g = 0; g < p.gears.size(); ++g) {
            const auto& c = p.gears[g];
            if (!std::isfinite(c.omega) || !std::isfinite(c.coef_low) || !std::isfinite(c.coef_high) ||
                !std::isfinite(c.ReC_times_nu))
                return "churning gear " + m.gearbox.gears[g].spec.name;
        }
        return {};
    }

    double power(const solver::Model&, const losses::MechanismPoint& pt, losses::Evaluation& e,
                 losses::MechanismDetail* d) const override {
        const auto& p = static_cast<const ChurningPoint&>(pt);
        if (d) {
            d->reset(p.gears.size(), kQuantities);
            for (size_t g = 0; g < p.gears.size(); ++g) d->at(g, kRegime) = double(Regime::none);
        }
        double total = 0.0;
        if (!p.gears.empty()) {
            // Re = Omega Rp^2 / nu with nu in m^2/s (SI, as folded in ChurningAtSpeed).
            const double nu021 = std::exp(0.21 * std::log(e.oil.nu));
            for (size_t g = 0; g < p.gears.size(); ++g) {
                const auto& c = p.gears[g];
                if (c.coef_low == 0.0 && c.coef_high == 0.0) continue;
                Regime reg;
                const double P = param(kFactor) * c.torque(e.oil.rho, e.oil.nu, nu021, &reg) * c.omega;
                total += P;
                if (d) {
                    d->at(g, kPower) = P;
                    d->at(g, kRegime) = double(reg);
                }
            }
        }
        return total;
    }

    std::string loss_fault(const solver::Model& m, const losses::MechanismPoint&,
                           const losses::MechanismDetail& d) const override {
        for (size_t g = 0; g < m.gearbox.gears.size(); ++g)
            if (!(std::isfinite(d.at(g, kPower)) && d.at(g, kPower) >= 0)) return "churning gear " + m.gearbox.gears[g].spec.name;
        return {};
    }

    std::string report(const solver::Model& m, const losses::PointInput& in, const losses::MechanismPoint& pt,
                       const losses::MechanismDetail& d) const override {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        const auto& p = static_cast<const ChurningPoint&>(pt);
        std::string s = "churning              immersion [mm]  speed [rpm]  P [W]     regime\n";
        std::string capped;
        for (size_t g = 0; g < gb.gears.size(); ++g) {
            const auto regime = Regime(int(d.at(g, kRegime)));
            s += fmt::format("  {:<18} {:14.2f} {:12.1f} {:9.2f}  {}\n", gb.gears[g].spec.name, L.gear_immersion[g] * 1e3,
                             std::abs(L.body_speed_ratio[L.body_of_gear[g]] * in.omega_in) * rad_s_to_rpm,
                             d.at(g, kPower), to_string(regime));
            if (regime == Regime::capped && g < p.gears.size())
                capped += fmt::format("  capped '{}': the high-Re form is {:.2f} x the low-Re one at Re_c = 6000; held at the "
                                      "minimum of the published curve over Re_c (reached at Re_c = {:.0f})\n",
                                      gb.gears[g].spec.name, p.gears[g].transition_excess(), p.gears[g].ReC_cap);
        }
        return s + capped;
    }
};

}  // namespace
}  // namespace gearloss::churning

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_churning() { return make_mechanism<churning::Churning>(); }
}  // namespace gearloss::losses
