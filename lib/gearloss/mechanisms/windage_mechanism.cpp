// Windage: the drag of the air (or air/oil mist) on each rotating gear, from its geometry
// and speed, as a loss mechanism: the class and its factory (listed by one line in
// gearloss/losses/registry.cpp); the physics is in gearloss/windage/gear_windage.hpp.
//
// Forms (mechanisms: {windage: {form: ...}}):
//   none                 (default) no windage: the published models of this tool leave it out;
//   anderson_loewenthal  Anderson & Loewenthal (1980), NASA TP-1622: per gear
//                        P = 2.82e-7 (1 + 2.3 b/R) n^2.8 R^4.6 (0.028 mu + 0.019)^0.2 [kW],
//                        n [rpm], R pitch radius and b face width [m], mu the viscosity of the
//                        air/oil mist [cP]; fitted on spur gears in a jet-lubricated housing;
//   free_disk            both faces of each gear as a free disk in air (von Karman 1921;
//                        Schlichting & Gersten 2017, ch. 5 and 17): M = C_M 1/2 rho w^2 R^5 with
//                        C_M = 3.87 Re^-1/2 (laminar, Cochran 1934) or 0.146 Re^-1/5 (turbulent),
//                        the larger of the two (continuous across the transition), Re = w R^2/nu;
//                        air at the oil temperature (ideal gas, Sutherland 1893 viscosity). No
//                        tooth pumping and no periphery: a lower bound for a toothed gear.
// Planet gears count once per planet, at their speed relative to the housing.
//
// Whatever the form, the calibration may add an empirical drag of the whole box (component
// "box"): P = C (n_in / 1000 rpm)^2.9, the speed exponent of Dawson (1984), C fitted to
// measurements (calibration: {windage: {empirical_W_at_1000rpm: 12 W}}; the diagnosis's
// windage effect).
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "gearloss/core/errors.hpp"
#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"
#include "gearloss/thermal/air.hpp"
#include "gearloss/units/units.hpp"
#include "gearloss/windage/gear_windage.hpp"

namespace gearloss::windage {

namespace {

enum class Form { none, anderson_loewenthal, free_disk };
constexpr const char* kFormNames[] = {"none", "anderson_loewenthal", "free_disk"};

struct WindagePoint : losses::MechanismPointOf<WindagePoint> {
    std::vector<double> omega;  // per gear, relative to the housing [rad/s]
    double box = 0;             // W, the calibration's empirical drag of the whole box
};

class GearWindage final : public losses::LossMechanism {
public:
    enum : size_t { kFactor, kMistViscosity, kPressure, kEmpirical };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<GearWindage>(*this); }
    std::string_view name() const override { return "windage"; }
    std::string_view label() const override { return "windage"; }
    std::string_view column() const override { return "P_windage_W"; }
    std::vector<std::string> components(const solver::Model& m) const override {
        auto names = losses::names_of(m.gearbox.gears, [](const auto& g) { return g.spec.name; });
        names.push_back("box");  // the empirical term, last
        return names;
    }
    std::vector<losses::DetailQuantity> quantities() const override { return {{"P_windage_{}_W", 1.0}}; }
    std::vector<losses::Parameter> parameters() const override {
        return {{"factor", "scales every gear's windage", nullptr, "1.5", 1.0, 0.0, 100.0, true},
                {"mist_viscosity", "viscosity of the air/oil mist (anderson_loewenthal)", &units::dim::dynamic_viscosity,
                 "1.8e-5 Pa*s", 1.8e-5, 0.0, 1.0, false, "", "", false, "anderson_loewenthal"},
                {"pressure", "gas pressure in the housing (free_disk)", &units::dim::pressure, "101325 Pa", 101325.0, 1e3,
                 1e7, false, "", "", false, "free_disk"},
                {"empirical_W_at_1000rpm", "empirical drag of the whole box at 1000 rpm input speed (n^2.9)",
                 &units::dim::power, "12 W", 0.0, 0.0, 1e9, true, "windage",
                 "air/oil-mist drag of the rotating gears, P = C (n/1000 rpm)^2.9, independent of oil viscosity and load"}};
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
        for (int i = 0; i < 3; ++i)
            if (f == kFormNames[i]) {
                form_ = Form(i);
                return;
            }
        throw InputError(fmt::format("windage has no form '{}'", f));
    }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<WindagePoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        const auto& L = m.layout;
        auto& p = static_cast<WindagePoint&>(out);
        p.omega.assign(m.gearbox.gears.size(), 0.0);
        p.box = 0.0;
        if (!enabled()) return;  // switched off: every gear's drag and the box's are zero
        for (size_t g = 0; g < p.omega.size(); ++g) p.omega[g] = L.body_speed_ratio[L.body_of_gear[g]] * in.omega_in;
        const double C = param(kEmpirical);  // 0 unless calibrated: no pow per point then
        p.box = C == 0.0 ? 0.0 : C * std::pow(std::abs(in.omega_in) * 30.0 / std::numbers::pi / 1000.0, 2.9);
    }
    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const WindagePoint&>(pt);
        for (size_t g = 0; g < p.omega.size(); ++g)
            if (!std::isfinite(p.omega[g])) return "windage gear " + m.gearbox.gears[g].spec.name;
        if (!(std::isfinite(p.box) && p.box >= 0.0)) return "windage";
        return {};
    }
    double power(const solver::Model& m, const losses::MechanismPoint& pt, losses::Evaluation& e,
                 losses::MechanismDetail* d) const override {
        const auto& p = static_cast<const WindagePoint&>(pt);
        if (d) {
            d->reset(p.omega.size() + 1, 1);
            d->at(p.omega.size()) = p.box;
        }
        if (form_ == Form::none) return p.box;
        const double T = e.oil.T;
        const double rho = thermal::air_density(T, param(kPressure)), nu = thermal::air_viscosity(T) / rho;
        double total = 0.0;
        for (size_t g = 0; g < p.omega.size(); ++g) {
            const auto& gear = m.gearbox.gears[g];
            const double R = 0.5 * gear.spec.d();
            const double P1 = form_ == Form::anderson_loewenthal
                                  ? anderson_loewenthal_power(R, gear.spec.b, p.omega[g], param(kMistViscosity))
                                  : free_disk_power(R, p.omega[g], rho, nu);
            const double P = param(kFactor) * P1 * gear.planets;
            total += P;
            if (d) d->at(g) = P;
        }
        return total + p.box;
    }

private:
    Form form_ = Form::none;
};

}  // namespace
}  // namespace gearloss::windage

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_gear_windage() { return make_mechanism<windage::GearWindage>(); }
}  // namespace gearloss::losses
