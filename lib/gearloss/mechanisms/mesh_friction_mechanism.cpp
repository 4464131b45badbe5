#include "gearloss/core/errors.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"

#include <cmath>
#include <fmt/format.h>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>

#include "gearloss/core/source_index.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/mesh/ehl_path.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::mesh {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr double kFilmLimitNone = 1000.0;  // friction_factor_film_limit: the factor acts at every film

struct NamedForm {
    const char* name;
    int value;
};
constexpr NamedForm kFriction[] = {{"schlenk", int(FrictionModel::schlenk)},
                                   {"iso_6336_20", int(FrictionModel::iso_6336_20)},
                                   {"fernandes_mixed", int(FrictionModel::fernandes_mixed)},
                                   {"ehl_local", int(FrictionModel::ehl_local)},
                                   {"ehl_maxwell", int(FrictionModel::ehl_maxwell)}};
constexpr NamedForm kLossFactor[] = {{"wimmer", int(LossFactorModel::wimmer)},
                                     {"ohlendorf", int(LossFactorModel::ohlendorf)},
                                     {"buckingham", int(LossFactorModel::buckingham)}};
constexpr NamedForm kFilm[] = {{"gupta", int(ThermalFilmCorrection::gupta)},
                               {"simplified", int(ThermalFilmCorrection::simplified)},
                               {"none", int(ThermalFilmCorrection::none)}};

template <size_t N>
std::vector<std::string> names(const NamedForm (&t)[N]) {
    std::vector<std::string> v;
    for (const auto& f : t) v.emplace_back(f.name);
    return v;
}
template <size_t N>
std::string name_of(const NamedForm (&t)[N], int value) {
    for (const auto& f : t)
        if (f.value == value) return f.name;
    return "?";
}
template <size_t N>
int value_of(const NamedForm (&t)[N], std::string_view axis, std::string_view name) {
    for (const auto& f : t)
        if (name == f.name) return f.value;
    throw InputError(fmt::format("mesh friction has no {} form '{}'", axis, name));
}

class MeshFriction final : public losses::LossMechanism {
public:
    enum : size_t { kFrictionFactor, kMuBl, kMuEhl, kMixedRise, kMixedOnset, kFactorFilmLimit };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<MeshFriction>(*this); }
    std::string_view name() const override { return "mesh"; }
    std::string_view label() const override { return "mesh"; }
    std::string_view column() const override { return "P_mesh_W"; }

    std::vector<std::string> components(const solver::Model& m) const override {
        return losses::names_of(m.gearbox.meshes, [](const auto& me) { return me.name; });
    }
    std::vector<losses::DetailQuantity> quantities() const override {
        return {{"P_mesh_{}_W", 1.0}, {"mu_{}", 1.0}, {"lambda_{}", 1.0}, {"h_min_{}_um", 1e6}, {"", 1e6}};
    }
    std::vector<losses::Parameter> parameters() const override {
        // The boundary / full-film pair of the mixed-film model (Fernandes et al. 2015):
        // settings of the physics, not calibration terms; their order is checked in validate().
        std::vector<losses::Parameter> v{{"friction_factor", "scales mu_mZ (an error of X_L)", nullptr, "1.1", 1.0, 0.05, 20.0, true, "mesh_friction",
                 "load-dependent mesh friction level differs (lubricant factor X_L, surface finish)",
                 /*oil_dependent=*/true},
                {"mu_bl", "boundary friction of fernandes_mixed", nullptr, "0.10", 0.10, 0.0, 1.0, false, "", "", false,
                 "fernandes_mixed"},
                {"mu_ehl", "full-film friction of fernandes_mixed", nullptr, "0.02", 0.02, 0.0, 1.0, false, "", "", false,
                 "fernandes_mixed"},
                // Friction that follows the film: mu x (1 + k xi(Lambda)), xi the boundary share
                // of Doleschel (2003), 0 above the onset. The published laws give mu a fixed
                // power of load, speed and viscosity; asperity contact makes it rise where the
                // film is thin (slow, loaded, hot), by an amount that is the lubricant's own.
                {"mixed_friction_rise", "relative rise of mu_mZ at full boundary share (Lambda -> 0)", nullptr, "0.5",
                 0.0, -0.9, 20.0, true, "mesh_friction_mixed",
                 "mesh friction rises where the film is thin (mixed lubrication: asperity contact below an onset Lambda)",
                 /*oil_dependent=*/true},
                // Where that rise sets in: Doleschel's 2, but asperities carry load up to Lambda of
                // 3 to 4 on some surfaces (Johnson, Greenwood & Poon 1972) and little above 1 on
                // run-in ones; the diagnosis fits it with the rise (a log grid from 1 to 5.6).
                {"mixed_friction_onset", "film parameter Lambda below which mixed_friction_rise acts", nullptr, "3",
                 2.0, 0.5, 10.0, true, "", "", false, "", "mesh_friction_mixed", {1.0, 1.4, 2.0, 2.8, 4.0, 5.6}},
                // Where friction_factor acts: everywhere (the nominal kFilmLimitNone), or only where
                // the film is thin, fading out over 15 % of the limit around it. Schlenk's (1994)
                // mu_mZ carries the lubricant in one factor X_L at every film; a lubricant whose
                // friction differs through its boundary chemistry (additives, surface layers)
                // differs only where asperities touch, not in a full film, whose friction is the
                // oil's rheology. The diagnosis moves it once mesh_friction is named (a refinement).
                {"friction_factor_film_limit", "film parameter Lambda above which friction_factor fades out "
                 "(1000: none)", nullptr, "1.5", kFilmLimitNone, 0.1, kFilmLimitNone, true, "", "", false, "",
                 "mesh_friction", {0.25, 0.3, 0.35, 0.42, 0.5, 0.6, 0.7, 0.84, 1.0, 1.19, 1.41, 1.68, 2.0, 2.38, 2.83, 3.36, 4.0},
                 /*profile_deferred=*/true}};
        v[0].scales_loss = true;
        return v;
    }
    // The pair is a property of the lubricant (Fernandes et al. 2015 measure it per oil):
    // an oil's `gear_friction` gives it where the case does not.
    std::optional<double> oil_value(const solver::Model& m, std::string_view name) const override {
        if (name == "mu_bl") return m.oil.gear_mu_bl;
        if (name == "mu_ehl") return m.oil.gear_mu_ehl;
        return std::nullopt;
    }
    // The pair in force (hot path: no lookup by name).
    double mixed_mu_bl(const solver::Model& m) const {
        return given(kMuBl) || !m.oil.gear_mu_bl ? param(kMuBl) : *m.oil.gear_mu_bl;
    }
    double mixed_mu_ehl(const solver::Model& m) const {
        return given(kMuEhl) || !m.oil.gear_mu_ehl ? param(kMuEhl) : *m.oil.gear_mu_ehl;
    }
    std::vector<losses::FormAxis> forms(const solver::Model&) const override {
        return {{"friction", names(kFriction)}, {"loss_factor", names(kLossFactor)}, {"film_correction", names(kFilm)}};
    }
    std::string form(const solver::Model& m, std::string_view axis) const override {
        if (axis == "friction") return name_of(kFriction, int(forms_.friction));
        if (axis == "loss_factor") return name_of(kLossFactor, int(forms_.loss_factor));
        if (axis == "film_correction") return name_of(kFilm, int(forms_.film_correction));
        return LossMechanism::form(m, axis);
    }
    void set_form(solver::Model& m, std::string_view axis, std::string_view f) override {
        if (axis == "friction") forms_.friction = FrictionModel(value_of(kFriction, axis, f));
        else if (axis == "loss_factor") forms_.loss_factor = LossFactorModel(value_of(kLossFactor, axis, f));
        else if (axis == "film_correction") forms_.film_correction = ThermalFilmCorrection(value_of(kFilm, axis, f));
        else LossMechanism::set_form(m, axis, f);
    }
    void validate(const solver::Model& m, std::vector<solver::Issue>& out) const override;

    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<MeshFrictionPoint>(); }
    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override;
    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override;
    double power(const solver::Model& m, const losses::MechanismPoint& pt, losses::Evaluation& e,
                 losses::MechanismDetail* d) const override;
    std::string loss_fault(const solver::Model& m, const losses::MechanismPoint& pt,
                           const losses::MechanismDetail& d) const override;
    std::string report(const solver::Model& m, const losses::PointInput& in, const losses::MechanismPoint& pt,
                       const losses::MechanismDetail& d) const override;

    MeshForms forms_;  // read by the hot path as enums (mesh_forms() gives typed access)
};

// An issue of a setting, at the key the case chose it with: its `mechanisms: {mesh: ...}`
// spelling when the case wrote that one (read after `options:`, it wins), else the `options:`
// key (also for a model built in code or a form set by map --spread).
solver::Issue setting_issue(const solver::Model& m, std::initializer_list<const char*> mechanism_keys,
                            const char* options_key, std::string message) {
    for (const char* k : mechanism_keys)
        if (m.source && m.source->has(std::string("mechanisms.mesh.") + k))
            return {"mechanisms", "", std::string("mesh.") + k, std::move(message)};
    return {"options", "", options_key, std::move(message)};
}

// The issue of the mixed-film pair: at the case's key when the case wrote one, else at the
// oil's (the case's own oil or one given by --oil, which the error then names).
solver::Issue pair_issue(const solver::Model& m, const losses::LossMechanism& mech, std::string message) {
    using Source = losses::LossMechanism::Source;
    const bool case_wrote = mech.value_source(m, "mu_bl") == Source::case_setting ||
                            mech.value_source(m, "mu_ehl") == Source::case_setting;
    if (!case_wrote)
        for (const char* k : {"mu_bl", "mu_ehl"})
            if (mech.value_source(m, k) == Source::oil)
                return {"oil", "", std::string("gear_friction.") + k, std::move(message)};
    return setting_issue(m, {"mu_bl", "mu_ehl"}, "gear_friction", std::move(message));
}

void MeshFriction::validate(const solver::Model& m, std::vector<solver::Issue>& out) const {
    LossMechanism::validate(m, out);  // each parameter within its bounds
    // The order of the mixed-film pair (a value outside its bounds is reported above, once),
    // naming where each value came from. A pair the case writes whole is checked whatever the
    // form (the oil's is, where it is read). A pair assembled from several places (an oil's
    // mu_ehl with the default mu_bl) matters only where fernandes_mixed reads it: an oil that
    // gives a measured full-film friction of 0.1 must not stop a schlenk case.
    const double bl = mixed_mu_bl(m), ehl = mixed_mu_ehl(m);
    const bool read = forms_.friction == FrictionModel::fernandes_mixed || (given(kMuBl) && given(kMuEhl));
    if (read && bl >= 0 && bl <= 1 && ehl >= 0 && ehl <= 1 && !mixed_friction_pair_valid(bl, ehl))
        out.push_back(pair_issue(m, *this,
                                 fmt::format("need 0 <= mu_ehl < mu_bl < 1 (mu_bl {:g} from the {}, mu_ehl {:g} from the {})",
                                             bl, source_name(value_source(m, "mu_bl")), ehl, source_name(value_source(m, "mu_ehl")))));
    // Ohlendorf's (1958) closed form and the single-pair average (Buckingham) assume
    // 1 <= eps_alpha < 2: one or two pairs in contact, alternating. Wimmer's (2006) sweep of the
    // contact lines holds for any contact ratio. The layout exists once the model is finalised.
    const auto& L = m.layout;
    if (forms_.loss_factor == LossFactorModel::wimmer || L.meshes.size() != m.gearbox.meshes.size()) return;
    for (size_t i = 0; i < L.meshes.size(); ++i) {
        const double eps = L.meshes[i].geom.eps_alpha;
        if (eps < 1.0 || eps >= 2.0) {
            out.push_back(setting_issue(
                m, {"loss_factor"}, "gear_loss_factor",
                fmt::format("mesh '{}' has eps_alpha = {:.3f}, outside the 1..2 that this closed form assumes; use "
                            "'wimmer' (rigid load sharing over the contact lines)",
                            m.gearbox.meshes[i].name, eps)));
            return;  // one issue for the setting, naming the first mesh
        }
    }
}

void MeshFriction::prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const {
    const auto& gb = m.gearbox;
    const auto& L = m.layout;
    const auto& opt = forms_;
    auto& meshes = static_cast<MeshFrictionPoint&>(out).meshes;
    meshes.resize(gb.meshes.size());
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = L.meshes[i];
        auto& ms = meshes[i];
        ms.ehl_film_rise.clear();  // no warm start carried over from another point
        ms.power = ms.mu_prefactor = ms.F_bn = ms.omega_rel = 0.0;
        ms.contact = LineContact{};
        const auto& g0 = gb.gears[gb.meshes[i].gear[0]].spec;
        const auto& g1 = gb.gears[gb.meshes[i].gear[1]].spec;
        ms.H_V = md.loss_factor(opt.loss_factor);
        if (opt.lambda_roughness == LambdaRoughness::average_Ra) {
            ms.sigma = 0.5 * (g0.Ra + g1.Ra);
        } else {
            const double q0 = g0.Rq ? *g0.Rq : 1.25 * g0.Ra, q1 = g1.Rq ? *g1.Rq : 1.25 * g1.Ra;
            ms.sigma = std::sqrt(q0 * q0 + q1 * q1);
        }
        // Speeds relative to the carrier (the housing for an ordinary mesh).
        const double w0 = md.relative_speed * in.omega_in;
        const double vt = std::abs(w0) * 0.5 * md.geom.dw[0];
        const double v_sum = 2.0 * vt * std::sin(md.geom.alpha_wt);
        ms.contact.u_e = 0.5 * v_sum;
        ms.contact.R = md.geom.rho_redC;
        ms.contact.E_prime = m.mesh_E_prime[i];
        ms.contact.SRR = 0.0;  // pitch point
        if (!md.loaded || !enabled() || in.torque_in == 0.0 || w0 == 0.0) continue;
        // Mesh loss on the rolling power (relative to the carrier): P_VZP = mu H_V |P_roll|.
        ms.power = std::abs(in.power_in) * md.rolling_per_W;
        // Line load of one mesh (load shared by the planets of a set).
        const double F_wt = std::abs(md.force_per_Nm * in.torque_in) / md.planets;
        const double F_bt = F_wt / std::cos(md.geom.alpha_wt);
        const double w_Nmm = F_bt / (md.geom.b_eff * 1e3);
        const double rho_mm = md.geom.rho_redC * 1e3;
        const double Ra_um = 0.5 * (g0.Ra + g1.Ra) * 1e6;
        ms.contact.w_line = F_bt / std::cos(md.geom.beta_b) / md.L_min;
        ms.F_bn = F_bt / std::cos(md.geom.beta_b);
        ms.omega_rel = w0;
        switch (opt.friction) {
            case FrictionModel::ehl_local:
            case FrictionModel::ehl_maxwell:
            case FrictionModel::schlenk:
            case FrictionModel::fernandes_mixed:
                ms.mu_prefactor = mean_friction_schlenk(w_Nmm, v_sum, rho_mm, 1.0, Ra_um, m.oil.X_L);
                break;
            case FrictionModel::iso_6336_20: {
                // ISO/TS 6336-20 caps the pitch-line speed at 50 m/s in v_sum.
                const double v_sum_c = 2.0 * std::min(vt, 50.0) * std::sin(md.geom.alpha_wt);
                ms.mu_prefactor = mean_friction_iso_6336_20(w_Nmm, v_sum_c, rho_mm, 1.0, Ra_um, m.oil.X_L);
                break;
            }
        }
    }
}

std::string MeshFriction::point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const {
    const auto& meshes = static_cast<const MeshFrictionPoint&>(pt).meshes;
    auto finite = [](double v) { return std::isfinite(v); };
    for (size_t i = 0; i < meshes.size(); ++i) {
        const auto& ms = meshes[i];
        // Once per point: the message is built only for a fault.
        const char* f = nullptr;
        if (!finite(ms.power) || !finite(ms.F_bn) || !finite(ms.contact.w_line)) f = "load";
        else if (!finite(ms.contact.u_e) || !finite(ms.omega_rel)) f = "speed";
        else if (!finite(ms.mu_prefactor)) f = "friction coefficient";
        else if (!finite(ms.H_V) || !finite(ms.sigma)) f = "loss factor";
        if (f) return "mesh " + m.gearbox.meshes[i].name + " " + f;
    }
    return {};
}

double MeshFriction::power(const solver::Model& m, const losses::MechanismPoint& pt, losses::Evaluation& e,
                           losses::MechanismDetail* d) const {
    const auto& opt = forms_;
    const auto& s = e.oil;
    const auto& meshes = static_cast<const MeshFrictionPoint&>(pt).meshes;
    const double set_factor = param(kFrictionFactor);
    const double film_limit = param(kFactorFilmLimit);
    const bool limited = film_limit < kFilmLimitNone && set_factor != 1.0;
    const double mixed_rise = param(kMixedRise);
    const double mixed_onset = param(kMixedOnset);
    const double eta_factor = std::exp(-0.05 * std::log(s.eta * 1e3));  // eta [mPa s]^-0.05
    const bool need_film =
        d || e.want_film || opt.friction == FrictionModel::fernandes_mixed || mixed_rise != 0.0 || limited;
    if (d) d->reset(meshes.size(), kMeshQuantities);
    double total = 0.0;
    for (size_t i = 0; i < meshes.size(); ++i) {
        const auto& ms = meshes[i];
        if (ms.power == 0.0) continue;
        double factor = set_factor;
        double mixed = 1.0;  // the film's own rise of friction (mixed_friction_rise)
        double lambda = kNoValue;
        std::optional<Film> f;
        if (need_film) {
            f = line_contact_film(ms.contact, s.eta, s.alpha_p, s.beta_T, s.k, opt.film_correction);
            lambda = f->h_c / ms.sigma;
            // The factor's departure where the film is thin only: a logistic fade around the limit.
            if (limited) factor = 1.0 + (set_factor - 1.0) / (1.0 + std::exp((lambda - film_limit) / (0.15 * film_limit)));
        }
        double mu = ms.mu_prefactor * eta_factor * factor;
        if (need_film) {
            if (opt.friction == FrictionModel::fernandes_mixed) {
                const double xi = boundary_share_doleschel(lambda);
                mu = (xi * mixed_mu_bl(m) + (1.0 - xi) * mixed_mu_ehl(m)) * factor;
            }
            if (mixed_rise != 0.0) mixed = 1.0 + mixed_rise * boundary_share_doleschel(lambda, mixed_onset);
            mu *= mixed;
            e.add_lambda(lambda);
            if (d) {
                d->at(i, kMeshLambda) = lambda;
                d->at(i, kMeshHmin) = f->h_min;
                d->at(i, kMeshHc) = f->h_c;
            }
        }
        double loss = ms.power * mu * ms.H_V;
        if (opt.friction == FrictionModel::ehl_local || opt.friction == FrictionModel::ehl_maxwell) {
            // Local thermal EHL along the path of contact at the oil temperature.
            const auto& md = m.layout.meshes[i];
            loss = ehl_mesh_loss(md.geom, md.L_mean, ms.omega_rel, ms.F_bn, md.planets, ms.contact.E_prime, ms.sigma,
                                 s.T, m.oil, m.oil.traction, &ms.ehl_film_rise, traction_law(opt.friction),
                                 m.calibration.viscosity_factor) *
                   factor * mixed;
            mu = ms.power * ms.H_V > 0 ? loss / (ms.power * ms.H_V) : 0.0;  // equivalent mean friction
        }
        total += loss;
        if (d) {
            d->at(i, kMeshPower) = loss;
            d->at(i, kMeshMu) = mu;
        }
    }
    if (d)  // films of meshes without power have no value
        for (size_t i = 0; i < meshes.size(); ++i)
            if (!(d->at(i, kMeshPower) > 0)) d->at(i, kMeshLambda) = d->at(i, kMeshHmin) = kNoValue;
    return total;
}

std::string MeshFriction::loss_fault(const solver::Model& m, const losses::MechanismPoint& pt,
                                     const losses::MechanismDetail& d) const {
    const auto& meshes = static_cast<const MeshFrictionPoint&>(pt).meshes;
    for (size_t i = 0; i < meshes.size(); ++i) {
        const double P = d.at(i, kMeshPower);
        if (!(std::isfinite(P) && P >= 0)) return "mesh " + m.gearbox.meshes[i].name + " friction loss";
        if (meshes[i].power > 0 && !std::isfinite(d.at(i, kMeshLambda)) && P > 0)
            return "mesh " + m.gearbox.meshes[i].name + " film thickness";
    }
    return {};
}

std::string MeshFriction::report(const solver::Model& m, const losses::PointInput&, const losses::MechanismPoint&,
                                 const losses::MechanismDetail& d) const {
    const auto& gb = m.gearbox;
    std::string s = "meshes                 H_V     mu_mZ   P [W]     Lambda   h_c [um]  h_min [um]\n";
    for (size_t i = 0; i < gb.meshes.size(); ++i) {
        const auto& md = m.layout.meshes[i];
        const double H = md.loss_factor(forms_.loss_factor);
        if (d.at(i, kMeshPower) > 0)
            s += fmt::format("  {:<18} {:7.4f} {:7.4f} {:9.2f} {:8.3f} {:9.3f} {:11.3f}\n", gb.meshes[i].name, H,
                             d.at(i, kMeshMu), d.at(i, kMeshPower), d.at(i, kMeshLambda), d.at(i, kMeshHc) * 1e6,
                             d.at(i, kMeshHmin) * 1e6);
        else
            s += fmt::format("  {:<18} {:7.4f}  {}\n", gb.meshes[i].name, H, md.loaded ? "(no power)" : "idle (no load)");
    }
    return s;
}

}  // namespace

const MeshForms& mesh_forms(const solver::Model& m) {
    return dynamic_cast<const MeshFriction&>(m.mechanisms.at("mesh")).forms_;
}
MeshForms& mesh_forms(solver::Model& m) { return dynamic_cast<MeshFriction&>(m.mechanisms.at("mesh")).forms_; }

bool mixed_friction_pair_valid(double mu_bl, double mu_ehl) { return mu_ehl >= 0 && mu_ehl < mu_bl && mu_bl < 1; }

const MeshFrictionPoint& mesh_friction_point(const solver::Model& m,
                                             const std::vector<std::unique_ptr<losses::MechanismPoint>>& data) {
    return static_cast<const MeshFrictionPoint&>(*data.at(m.mechanisms.index("mesh")));
}

}  // namespace gearloss::mesh

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_mesh_friction() { return make_mechanism<mesh::MeshFriction>(); }
}  // namespace gearloss::losses
