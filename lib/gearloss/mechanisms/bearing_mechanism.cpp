// Rolling bearings as a loss mechanism: the SKF (2004) friction model per bearing with the
// loads from the gear forces and the weights (gearbox::Layout::bearing_load), times the planets it stands for, plus the
// calibration's no-load drag term after Palmgren (1959).
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/bearings/skf_model.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::bearings {
namespace {

constexpr double rad_s_to_rpm = 30.0 / std::numbers::pi;  // the report's speed column

struct BearingPoint : losses::MechanismPointOf<BearingPoint> {
    std::vector<SkfAtPoint> skf;     // per bearing
    // Per bearing: the powers of its dimensions, kept from point to point (this storage is
    // reused for the points a thread solves) and made again only when the bearing differs.
    std::vector<SkfGeometry> geometry;
    std::vector<double> omega;       // rad/s
    std::vector<double> Fr, Fa;      // N: gear forces and weights (Layout::bearing_load)
    std::vector<double> drag_coef;   // Palmgren drag, W per (nu_cSt)^(2/3)
    bool any_drag = false;           // a bearing with the SKF drag term
};

class Bearings final : public losses::LossMechanism {
public:
    enum : size_t { kDragF0, kDragExponent };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<Bearings>(*this); }
    std::string_view name() const override { return "bearings"; }
    std::string_view label() const override { return "bearings"; }
    std::string_view column() const override { return "P_bearing_W"; }
    std::vector<std::string> components(const solver::Model& m) const override {
        return losses::names_of(m.gearbox.bearings, [](const auto& b) { return b.name; });
    }
    // The loss of each bearing and its radial and axial load (at zero torque: the weights alone).
    std::vector<losses::DetailQuantity> quantities() const override {
        return {{"P_bearing_{}_W", 1.0}, {"Fr_{}_N", 1.0}, {"Fa_{}_N", 1.0}};
    }
    std::vector<losses::Parameter> parameters() const override {
        // Palmgren (1959) no-load moment M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 [N mm] per bearing.
        return {{"drag_f0", "Palmgren no-load factor f0 of an added bearing drag", nullptr, "1.5", 0.0, 0.0, 100.0, true,
                 "bearing_drag", "load-independent viscous drag in the bearings (oil bath), Palmgren M0 = 1e-7 f0 (nu n)^(2/3) d_m^3"},
                // Palmgren's (1959) 2/3 is one fit over his bearings, below nu n = 2000 he gives
                // no speed dependence at all, and the rolling moment of SKF (2004) grows as
                // (nu n)^0.6: the power of an added drag is not known beforehand, so the
                // diagnosis fits it with f0 on a grid from 0.45 to 0.85.
                {"drag_exponent", "power b of nu n in the added drag M0 = 1e-7 f0 2000^(2/3) (nu n/2000)^b d_m^3", nullptr,
                 "0.6", 2.0 / 3.0, 0.3, 1.0, true, "", "", false, "", "bearing_drag", {0.45, 0.55, 2.0 / 3.0, 0.75, 0.85}}};
    }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<BearingPoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        auto& p = static_cast<BearingPoint&>(out);
        const size_t n = gb.bearings.size();
        p.skf.assign(n, SkfAtPoint{});
        p.geometry.resize(n);
        p.omega.assign(n, 0.0);
        p.Fr.assign(n, 0.0);
        p.Fa.assign(n, 0.0);
        p.drag_coef.assign(n, 0.0);
        p.any_drag = false;
        const double f0 = param(kDragF0);
        for (size_t i = 0; i < n; ++i) {
            const double w = L.bearing_speed_ratio[i] * std::abs(in.omega_in);
            p.omega[i] = w;
            // Gear forces vector-added to the weights of gears and shafts (and a planet's centrifugal force).
            const auto load = L.bearing_load(i, in.torque_in, in.omega_in);
            p.Fr[i] = load.Fr;
            p.Fa[i] = load.Fa;
            if (!enabled()) continue;  // switched off: no SKF loss and no drag
            const auto& spec = gb.bearings[i].spec;
            if (!p.geometry[i].matches(spec)) p.geometry[i] = SkfGeometry::of(spec);
            p.skf[i] = SkfAtPoint::make(spec, p.geometry[i], load.Fr, load.Fa, w);
            // Palmgren (1959): M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 [N mm], P = M0 omega.
            if (f0 > 0.0) p.drag_coef[i] = palmgren_drag_coef(gb.bearings[i].spec, f0, w, param(kDragExponent));
            p.any_drag = p.any_drag || p.skf[i].drag_b != 0.0;
        }
    }

    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const BearingPoint&>(pt);
        // Called once per point: the message is built only for a fault.
        for (size_t i = 0; i < p.skf.size(); ++i) {
            const char* f = !std::isfinite(p.omega[i]) ? "speed" : p.skf[i].fault();
            if (!f && !std::isfinite(p.drag_coef[i])) f = "drag";
            if (f) return "bearing " + m.gearbox.bearings[i].name + " " + f;
            if (auto g = beyond_rolling_bearings(m.gearbox.bearings[i].spec, p.omega[i]); !g.empty())
                return "bearing " + m.gearbox.bearings[i].name + " " + g;
        }
        return {};
    }

    // A bearing driven past anything a rolling bearing survives: its speed factor n d_m above
    // kMaxSpeedFactor. The friction model is then evaluated far outside its data and the point is
    // not ok. (The load is not bounded here: the shipped cases' stress grids load bearings well
    // past their static rating, and the SKF model stays finite there.)
    static std::string beyond_rolling_bearings(const BearingSpec& b, double omega) {
        // n d_m in rpm*mm: the fastest oil-lubricated bearings of the product tables of SKF (2018)
        // stay below about 1e6 (their limiting speeds); 3e6 leaves room for special high-speed bearings.
        constexpr double kMaxSpeedFactor = 3e6;
        const double ndm = std::abs(omega) * rad_s_to_rpm * b.dm() * 1e3;
        if (ndm > kMaxSpeedFactor)
            return fmt::format("speed {:.4g} rpm: n d_m {:.3g} rpm*mm beyond the rolling-bearing range {:.0e}",
                               std::abs(omega) * rad_s_to_rpm, ndm, kMaxSpeedFactor);
        return {};
    }

    double power(const solver::Model& m, const losses::MechanismPoint& pt, losses::Evaluation& e,
                 losses::MechanismDetail* d) const override {
        const auto& gb = m.gearbox;
        const auto& p = static_cast<const BearingPoint&>(pt);
        if (d) {
            d->reset(p.skf.size(), 3);
            for (size_t i = 0; i < p.Fr.size(); ++i) {
                d->at(i, 1) = p.Fr[i];
                d->at(i, 2) = p.Fa[i];
            }
        }
        double total = 0.0;
        // The SKF and Palmgren correlations take nu in cSt (their catalogue unit): its powers are
        // computed here once per temperature, from the ln(nu/cSt) shared by every mechanism.
        const double nu = e.oil.nu_cSt;
        if (enabled() && !p.skf.empty()) {
            const double lnnu = e.ln_nu_cSt;
            const double nu06 = std::exp(0.6 * lnnu), nu064 = std::exp(0.64 * lnnu), nu14 = std::exp(1.4 * lnnu);
            const double nu1379 = p.any_drag ? std::exp(1.379 * lnnu) : 0.0;
            for (size_t i = 0; i < p.skf.size(); ++i) {
                const double M = p.skf[i].moment(nu, nu06, nu064, nu14, nu1379);  // N*m
                const double P = M * p.omega[i] * gb.bearings[i].multiplicity;      // x planets
                total += P;
                if (d) d->at(i) = P;
            }
        }
        if (param(kDragF0) > 0.0) {
            const double b = param(kDragExponent);
            const double nu23 = b == 2.0 / 3.0 ? std::cbrt(nu * nu) : std::pow(nu, b);
            for (size_t i = 0; i < p.drag_coef.size(); ++i) {
                const double P = p.drag_coef[i] * nu23 * gb.bearings[i].multiplicity;
                total += P;
                if (d) d->at(i) += P;
            }
        }
        return total;
    }

    std::string loss_fault(const solver::Model& m, const losses::MechanismPoint&,
                           const losses::MechanismDetail& d) const override {
        for (size_t i = 0; i < m.gearbox.bearings.size(); ++i)
            if (!(std::isfinite(d.at(i)) && d.at(i) >= 0)) return "bearing " + m.gearbox.bearings[i].name + " loss";
        return {};
    }

    std::string report(const solver::Model& m, const losses::PointInput& in, const losses::MechanismPoint&,
                       const losses::MechanismDetail& d) const override {
        const auto& gb = m.gearbox;
        std::string s = "bearings              type                       n [rpm]   Fr [N]    Fa [N]    P [W]\n";
        for (size_t i = 0; i < gb.bearings.size(); ++i)
            s += fmt::format("  {:<18} {:<26} {:8.1f} {:9.1f} {:9.1f} {:8.2f}\n", gb.bearings[i].name,
                             to_string(gb.bearings[i].spec.type),
                             m.layout.bearing_speed_ratio[i] * std::abs(in.omega_in) * rad_s_to_rpm, d.at(i, 1), d.at(i, 2),
                             d.at(i));
        return s;
    }
};

}  // namespace
}  // namespace gearloss::bearings

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_bearings() { return make_mechanism<bearings::Bearings>(); }
}  // namespace gearloss::losses
