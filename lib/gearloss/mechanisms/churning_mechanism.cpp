// Churning of dip-lubricated gears as a loss mechanism, per immersed gear, with a
// calibration factor. (The drag of the air/oil mist is the windage mechanism's,
// gearloss/windage/gear_windage.cpp.)
//
// Forms (mechanisms: {churning: {form: ...}}):
//   changenet_velex_2007  (default) Changenet & Velex (2007, 2008), gearloss/churning/changenet_velex.hpp:
//                         the running minimum over Re_c of the published curve (regime 'capped'
//                         beyond its minimum), precomputed per gear in prepare(): the hot path adds
//                         one comparison;
//   heingartner_mba_2003  the tooth-surface form of Heingartner & Mba (2003) as quoted by seed 003,
//                         gearloss/churning/heingartner_mba.hpp: P = k mu, k per gear and speed from
//                         prepare(). Its roughness factor R_f and arrangement constant A_g are
//                         settings (the quote gives no values); a spur gear, for which the quoted
//                         expression has no value (R_f / sqrt(tan beta)), keeps the default form;
//   mauz_1987             the splash torque of a dipping gear pair of Mauz (1987) as quoted for ISO/TR
//                         14179-2, gearloss/churning/mauz_1987.hpp: one torque per mesh from the
//                         immersions of its two gears, shared between them in proportion to their
//                         immersion, each share at its gear's speed; no oil property enters (fitted
//                         at one oil). The sump lengths h_c and l_h of its splash factor are settings
//                         (0: C_Sp = 1). A dipping gear counts in its first mesh only; a dipping gear
//                         in no mesh keeps the default form.
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <utility>

#include "gearloss/churning/changenet_velex.hpp"
#include "gearloss/churning/heingartner_mba.hpp"
#include "gearloss/churning/mauz_1987.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::churning {
namespace {

constexpr double rad_s_to_rpm = 30.0 / std::numbers::pi;

enum class Form { changenet_velex_2007, heingartner_mba_2003, mauz_1987 };
constexpr const char* kFormNames[] = {"changenet_velex_2007", "heingartner_mba_2003", "mauz_1987"};
constexpr int kForms = 3;

struct ChurningPoint : losses::MechanismPointOf<ChurningPoint> {
    std::vector<ChurningAtSpeed> gears;  // per gear (zero coefficients: not immersed)
    // Per gear, heingartner_mba_2003: P / mu [W/(Pa s)]; 0 where that form is not used.
    std::vector<double> tooth_surface;
    // Per gear, mauz_1987: its share of the pair's splash power [W] (independent of the oil);
    // `splash_form` marks the gears that churn by that form.
    std::vector<double> splash;
    std::vector<char> splash_form;
    // The form that churns gear g (for the report).
    const char* form_of(size_t g) const {
        if (g < splash_form.size() && splash_form[g]) return kFormNames[2];
        if (g < tooth_surface.size() && tooth_surface[g] != 0.0) return kFormNames[1];
        return nullptr;
    }
};

// The first mesh of gear g (-1: in none), and its side in it.
std::pair<int, int> first_mesh(const solver::Model& m, size_t g) {
    const auto& gb = m.gearbox;
    for (size_t k = 0; k < gb.meshes.size(); ++k)
        for (int s = 0; s < 2; ++s)
            if (gb.meshes[k].gear[s] == static_cast<int>(g)) return {static_cast<int>(k), s};
    return {-1, 0};
}

// Outside diameter of gear g: the tip diameter of its first mesh (ISO 21771 tip alteration
// or as given), else d + 2 m_n (h*_a + x).
double outside_diameter(const solver::Model& m, size_t g) {
    const auto& gb = m.gearbox;
    for (size_t k = 0; k < gb.meshes.size() && k < m.layout.meshes.size(); ++k)
        for (int s = 0; s < 2; ++s)
            if (gb.meshes[k].gear[s] == static_cast<int>(g)) return m.layout.meshes[k].geom.da[s];
    const auto& spec = gb.gears[g].spec;
    return spec.d() + 2.0 * spec.mn * (spec.ha_star + spec.x);
}

class Churning final : public losses::LossMechanism {
public:
    enum : size_t { kFactor, kRoughnessFactor, kArrangementConstant, kSplashHeight, kSplashLength };
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
        std::vector<losses::Parameter> v{{"factor", "scales every churning loss", nullptr, "1.3", 1.0, 0.0, 100.0, true, "churning",
                 "churning level of the dipping gears (immersion or oil level) differs from the description"},
                {"roughness_factor",
                 "roughness factor R_f of the tooth-surface form (heingartner_mba_2003); 0: R_f = 7.93 - 4.648/m_t "
                 "(m_t in mm), the AGMA 6123 value as commonly quoted (unconfirmed)",
                 nullptr, "6.4", 0.0, 0.0, 1e6, false, "", "", false, kFormNames[1]},
                {"arrangement_constant",
                 "arrangement constant A_g of the tooth-surface form (heingartner_mba_2003); 0.2 as commonly quoted "
                 "from AGMA 6123 (unconfirmed)",
                 nullptr, "0.2", 0.2, 1e-6, 1e6, false, "", "", false, kFormNames[1]},
                {"splash_height",
                 "length h_c of the splash factor C_Sp = (4 e_max/(3 h_c))^1.5 (2 h_c/l_h) of mauz_1987 (its definition "
                 "is not verified); 0: C_Sp = 1",
                 &units::dim::length, "60 mm", 0.0, 0.0, 100.0, false, "", "", false, kFormNames[2]},
                {"splash_length",
                 "length l_h of the splash factor C_Sp of mauz_1987 (its definition is not verified); 0: C_Sp = 1",
                 &units::dim::length, "200 mm", 0.0, 0.0, 100.0, false, "", "", false, kFormNames[2]}};
        v[0].scales_loss = true;
        return v;
    }
    std::vector<losses::FormAxis> forms(const solver::Model&) const override {
        return {{"form", {kFormNames[0], kFormNames[1], kFormNames[2]}}};
    }
    std::string form(const solver::Model& m, std::string_view axis) const override {
        if (axis == "form") return kFormNames[int(form_)];
        return LossMechanism::form(m, axis);
    }
    void set_form(solver::Model& m, std::string_view axis, std::string_view f) override {
        if (axis != "form") return LossMechanism::set_form(m, axis, f);
        for (int i = 0; i < kForms; ++i)
            if (f == kFormNames[i]) {
                form_ = Form(i);
                return;
            }
        throw InputError(fmt::format("churning has no form '{}'", f));
    }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<ChurningPoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        auto& p = static_cast<ChurningPoint&>(out);
        p.gears.assign(gb.gears.size(), ChurningAtSpeed{});
        p.tooth_surface.assign(gb.gears.size(), 0.0);
        p.splash.assign(gb.gears.size(), 0.0);
        p.splash_form.assign(gb.gears.size(), 0);
        if (!enabled()) return;
        if (form_ == Form::mauz_1987) prepare_splash(m, in, p);
        for (size_t g = 0; g < gb.gears.size(); ++g) {
            if (p.splash_form[g]) continue;
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
            if (form_ == Form::heingartner_mba_2003) {
                const double D = outside_diameter(m, g);
                const ToothSurfaceGear tg{D, spec.b, spec.beta, dip_factor(h, D)};
                if (heingartner_mba_defined(tg)) {
                    // R_f = 0: from the transverse module, R_f = 7.93 - 4.648/m_t with m_t in mm (AGMA 6123
                    // as quoted for the Heingartner & Mba form; unconfirmed, docs/config.md "Churning forms").
                    const double Rf = param(kRoughnessFactor) > 0 ? param(kRoughnessFactor)
                                                                  : 7.93 - 4.648 / (spec.mn / std::cos(spec.beta) * 1e3);
                    p.tooth_surface[g] = heingartner_mba_coefficient(tg, w, Rf, param(kArrangementConstant));
                    p.gears[g].omega = std::abs(w);
                    continue;
                }
            }
            p.gears[g] = ChurningAtSpeed::make(dg, w, gb.oil_volume);
        }
    }

    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const ChurningPoint&>(pt);
        for (size_t g = 0; g < p.gears.size(); ++g) {
            const auto& c = p.gears[g];
            if (!std::isfinite(c.omega) || !std::isfinite(c.coef_low) || !std::isfinite(c.coef_high) ||
                !std::isfinite(c.ReC_times_nu) || !std::isfinite(p.tooth_surface[g]) || !std::isfinite(p.splash[g]))
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
                if (p.splash_form[g]) {
                    // mauz_1987: no oil property enters (regime 'none').
                    const double P = param(kFactor) * p.splash[g];
                    total += P;
                    if (d) d->at(g, kPower) = P;
                    continue;
                }
                if (p.tooth_surface[g] != 0.0) {
                    // heingartner_mba_2003: P = k mu (mu = rho nu, falls as the oil warms).
                    const double P = param(kFactor) * p.tooth_surface[g] * e.oil.rho * e.oil.nu;
                    total += P;
                    if (d) d->at(g, kPower) = P;  // regime 'none': the form has no regimes
                    continue;
                }
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
            // A gear churning by a form without Reynolds regimes: the form is named.
            const char* form = p.form_of(g);
            s += fmt::format("  {:<18} {:14.2f} {:12.1f} {:9.2f}  {}\n", gb.gears[g].spec.name, L.gear_immersion[g] * 1e3,
                             std::abs(L.body_speed_ratio[L.body_of_gear[g]] * in.omega_in) * rad_s_to_rpm,
                             d.at(g, kPower), form ? form : to_string(regime));
            if (regime == Regime::capped && g < p.gears.size())
                capped += fmt::format("  capped '{}': the high-Re form is {:.2f} x the low-Re one at Re_c = 6000; held at the "
                                      "minimum of the published curve over Re_c (reached at Re_c = {:.0f})\n",
                                      gb.gears[g].spec.name, p.gears[g].transition_excess(), p.gears[g].ReC_cap);
        }
        return s + capped;
    }

private:
    // mauz_1987: per mesh, the pair's splash torque from the immersions of the gears that dip and
    // count in it (their first mesh), shared between them in proportion to their immersion
    // (docs/config.md "Churning forms and their ranges"), each share at its gear's speed.
    void prepare_splash(const solver::Model& m, const losses::PointInput& in, ChurningPoint& p) const {
        const auto& gb = m.gearbox;
        const auto& L = m.layout;
        const SplashSump sump{param(kSplashHeight), param(kSplashLength)};
        for (size_t k = 0; k < gb.meshes.size(); ++k) {
            double e[2] = {0, 0};
            for (int s = 0; s < 2; ++s) {
                const auto g = static_cast<size_t>(gb.meshes[k].gear[s]);
                if (L.gear_immersion[g] > 0 && first_mesh(m, g).first == static_cast<int>(k)) e[s] = L.gear_immersion[g];
            }
            if (!(e[0] + e[1] > 0)) continue;
            // The face width of the deeper-dipping gear; the pitch-line speed at its reference circle
            // (the same for both gears of the pair).
            const int deep = e[1] > e[0] ? 1 : 0;
            const auto gd = static_cast<size_t>(gb.meshes[k].gear[deep]);
            const double w_deep = L.body_speed_ratio[L.body_of_gear[gd]] * in.omega_in;
            const SplashPair pair{e[0], e[1], gb.gears[gd].spec.b, std::abs(w_deep) * 0.5 * gb.gears[gd].spec.d()};
            const double T = mauz_splash_torque(pair, mauz_splash_factor(e[deep], sump));
            for (int s = 0; s < 2; ++s) {
                if (!(e[s] > 0)) continue;
                const auto g = static_cast<size_t>(gb.meshes[k].gear[s]);
                const double w = L.body_speed_ratio[L.body_of_gear[g]] * in.omega_in;
                p.splash[g] = T * e[s] / (e[0] + e[1]) * std::abs(w);
                p.splash_form[g] = 1;
            }
        }
    }

    Form form_ = Form::changenet_velex_2007;
};

}  // namespace
}  // namespace gearloss::churning

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_churning() { return make_mechanism<churning::Churning>(); }
}  // namespace gearloss::losses
