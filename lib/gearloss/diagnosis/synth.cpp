#include "gearloss/diagnosis/synth.hpp"

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <random>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/effects.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/solver/operating_point.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::diagnosis {

namespace {
constexpr double to_rpm = 30.0 / std::numbers::pi;
}

std::pair<std::string, double> parse_effect_assignment(const solver::Model& model, const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw InputError("", 0, 0, "--effect", "expected NAME=VALUE, got '" + text + "'");
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    const auto e = find_effect(model, name);
    if (!e)
        throw InputError("", 0, 0, "--effect",
                         "unknown effect '" + io::excerpt(name) + "'; known for this case: " + effect_names(model));
    units::Quantity q;
    try {
        q = units::parse_quantity(value);
    } catch (const units::UnitError& err) {
        throw InputError("", 0, 0, "--effect " + name, err.message);
    }
    const units::Dimension want = e->unit == "W" ? units::dim::power : e->unit == "N*m" ? units::dim::torque : units::dim::none;
    if (q.dim != want && !(q.dim == units::dim::none))
        throw InputError("", 0, 0, "--effect " + name,
                         "'" + value + "' has dimension " + units::to_string(q.dim) + ", expected " + units::to_string(want));
    // A dimensioned value goes through the kind check of any other ("100 J" is no torque offset).
    if (!(q.dim == units::dim::none)) {
        try {
            q.value = units::checked_value(q, want, value);
        } catch (const units::UnitError& err) {
            throw InputError("", 0, 0, "--effect " + name, err.message);
        }
    }
    if (e->discrete()) {
        if (q.value != 0 && q.value != 1)
            throw InputError("", 0, 0, "--effect " + name, "a form is chosen (1) or not (0): give " + name + "=1");
    } else if (e->id == "unstabilised_test") {
        if (q.value < 0 || q.value != std::floor(q.value))
            throw InputError("", 0, 0, "--effect " + name, "the number of unstabilised points must be a whole number >= 0");
    } else if (q.value < e->lower || q.value > e->upper) {
        throw InputError("", 0, 0, "--effect " + name,
                         fmt::format("{} outside the physical bounds [{}, {}]", q.value, e->lower, e->upper));
    }
    return {name, q.value};
}

std::string effects_help() {
    const solver::Model every_mechanism;  // every registered mechanism, parameters and forms as published
    const SynthOptions defaults;
    std::string scales, forms;
    for (const auto& e : candidate_effects(every_mechanism)) {
        if (e.discrete()) {
            const size_t line = forms.size() - std::min(forms.size(), forms.rfind('\n') + 1);  // this line's length
            forms += (forms.empty() ? "  " : line + e.id.size() > 96 ? ",\n  " : ", ") + e.id;
            continue;
        }
        const std::string unit = e.unit.empty() ? "" : " " + e.unit;
        scales += fmt::format("  {:<26} default {:g}{}{}\n", e.id, e.neutral, unit,
                              e.kind == EffectKind::pointwise ? " (a number of points)"
                              : e.upper > e.lower         ? fmt::format(", {:g} to {:g}{}", e.lower, e.upper, unit)
                                                          : "");
    }
    return "Effects (--effect NAME=VALUE; the default leaves the model as the case describes it):\n" + scales +
           "  Forms (NAME=1: a published form other than the case's; here those of a case with the default forms):\n" +
           forms +
           fmt::format("\nDefault noise: --noise-loss {:g}% of the loss, --noise-temp {:g} K (one standard deviation).\n",
                       100 * defaults.noise_loss, defaults.noise_temp);
}

void SynthOptions::validate() const {
    const auto bad = [](const char* key, const std::string& message) { throw InputError("", 0, 0, key, message); };
    if (!(noise_loss >= 0 && noise_loss <= 0.5)) bad("--noise-loss", "must be between 0 and 50 %");
    if (!(noise_temp >= 0 && noise_temp <= 20)) bad("--noise-temp", "must be between 0 and 20 K");
    if (!(test_minutes > 0 && test_minutes <= 1e4)) bad("test_minutes", "a test lasts more than 0 and at most 10^4 min");
    if (!(short_test_minutes > 0 && short_test_minutes <= 1e4))
        bad("short_test_minutes", "a test lasts more than 0 and at most 10^4 min");
    for (size_t i = 0; i < effects.size(); ++i) {
        const auto& [id, v] = effects[i];
        if (!std::isfinite(v)) bad("--effect", "'" + io::excerpt(id) + "': the value is not a finite number");
        if (id == "unstabilised_test" && !(v >= 0 && v <= 1e6 && v == std::floor(v)))
            bad("--effect", "unstabilised_test: give a whole number of tests (0 to the number of points)");
        for (size_t k = 0; k < i; ++k)
            if (effects[k].first == id) bad("--effect", "'" + io::excerpt(id) + "' given twice");
    }
}

std::string synthesize(const solver::Model& model_in, const io::OperatingGrid& grid, const SynthOptions& opt) {
    opt.validate();
    solver::Model m = model_in;
    Hypothesis h = Hypothesis::of(model_in);  // concealed effects come on top of the case as described
    int unstabilised = 0;
    for (const auto& [id, v] : opt.effects) {
        const auto e = find_effect(model_in, id);
        if (!e) throw InputError("", 0, 0, "--effect", "unknown effect '" + io::excerpt(id) + "'");
        if (id == "unstabilised_test") unstabilised = static_cast<int>(v);
        else e->apply(h, v);
    }
    h.apply_to(m);
    if (m.thermal.mode != solver::ThermalMode::stabilised)
        throw InputError("", 0, 0, "thermal.mode", "synthetic recordings need a stabilised thermal model");
    if (opt.raw_log && !(m.thermal.heat_capacity > 0))
        throw InputError("", 0, 0, "thermal.heat_capacity", "a raw log needs the heat capacity of oil and housing (e.g. 25 kJ/K)");
    const size_t n = grid.size();
    if (unstabilised > static_cast<int>(n))
        throw InputError("", 0, 0, "--effect unstabilised_test", "more unstabilised points than points in the grid");
    // The model must stay physical at every point of the grid (diagnose scans the same range).
    double max_rpm = 0;
    for (size_t i = 0; i < n; ++i) max_rpm = std::max(max_rpm, std::abs(grid.at(i).first) * to_rpm);
    for (const auto& [id, v] : opt.effects) {
        const auto e = find_effect(model_in, id);
        const auto [lo, hi] = valid_range(*e, max_rpm);
        if (id != "unstabilised_test" && !(v >= lo && v <= hi))
            throw InputError("", 0, 0, "--effect " + id,
                             fmt::format("{} outside [{:.4g}, {:.4g}], where the heat flow to ambient stays positive up to "
                                         "{:.0f} rpm",
                                         v, lo, hi, max_rpm));
    }

    std::mt19937_64 rng(opt.seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<char> warming(n, 0);
    for (int k = 0; k < unstabilised; ++k) warming[order[static_cast<size_t>(k)]] = 1;

    const double Ta = m.thermal.ambient;
    const double gain = h.art.torque_gain, offset = h.art.torque_offset;
    std::string out;
    solver::PointState p;
    // A point the model cannot evaluate (gearloss/model/validate.hpp) stops the campaign with its cause.
    const auto prepare = [&](double w, double T) {
        solver::prepare_point(m, w, T, p);
        if (!p.fault.empty())
            throw InputError("", 0, 0, "operating",
                             fmt::format("out_of_range at {:.0f} rpm / {:.0f} N*m: {}", w * to_rpm, T, p.fault));
    };

    if (!opt.raw_log) {
        out = "speed_in_rpm,torque_in_Nm,P_loss_W,oil_temp_C,ambient_temp_C,label\n";
        for (size_t i = 0; i < n; ++i) {
            io::throw_if_interrupted();
            const auto [w, T] = grid.at(i);
            prepare(w, T);
            const auto eq = solver::solve_temperature(m, p, Ta);
            if (eq.status != thermal::EquilibriumStatus::ok)
                throw InputError("", 0, 0, "operating",
                                 fmt::format("no thermal equilibrium at {:.0f} rpm / {:.0f} N*m: choose a smaller grid", w * to_rpm, T));
            double T_oil = eq.T;
            std::string label = "stabilised";
            if (warming[i]) {
                // Recorded at 70-88 % of the way to equilibrium: colder oil, higher loss.
                const double f = 0.70 + 0.18 * std::uniform_real_distribution<double>(0, 1)(rng);
                T_oil = Ta + f * (eq.T - Ta);
                label = "warming";
            }
            const double loss = solver::total_loss(m, p, T_oil);
            if (!std::isfinite(loss))
                throw InputError("", 0, 0, "operating",
                                 fmt::format("out_of_range at {:.0f} rpm / {:.0f} N*m: {}", w * to_rpm, T,
                                             solver::loss_fault(m, p, T_oil, Ta)));
            const double T_rec = gain * T + offset;
            const double loss_rec = (loss + (T_rec - T) * w) * (1.0 + opt.noise_loss * gauss(rng));
            const double T_oil_rec = T_oil + opt.noise_temp * gauss(rng);
            out += fmt::format("{:.3f},{:.4f},{:.4f},{:.4f},{:.2f},{}\n", w * to_rpm, T_rec, loss_rec, T_oil_rec - 273.15,
                               Ta - 273.15, label);
        }
        return out;
    }

    // Raw log: each test warms (or cools) from where the previous one ended,
    // C dT/dt = P(T) - Q(T), integrated with Boost.Odeint; samples every 2 s.
    namespace odeint = boost::numeric::odeint;
    using State = std::array<double, 1>;
    out = "time_s,speed_in_rpm,speed_out_rpm,torque_in_Nm,torque_out_Nm,oil_temp_C,wall_temp_C,room_temp_C\n";
    const double C = m.thermal.heat_capacity, dt = 2.0;
    State x{Ta};
    double t = 0;
    odeint::runge_kutta4<State> stepper;
    for (size_t i = 0; i < n; ++i) {
        const double w = grid.at(i).first, T = grid.at(i).second;  // plain locals: captured below
        prepare(w, T);
        auto rhs = [&](const State& s, State& dxdt, double) {
            dxdt[0] = (solver::total_loss(m, p, s[0]) - m.heat_flow(s[0], Ta, w)) / C;
        };
        const double duration = 60.0 * (warming[i] ? opt.short_test_minutes : opt.test_minutes);
        // Test-level errors (sensor drift between tests) on top of per-sample noise.
        const double e_loss = opt.noise_loss * gauss(rng), e_temp = opt.noise_temp * gauss(rng);
        const double w_out = std::abs(m.layout.ratio) * w;
        for (double s = 0; s < duration; s += dt) {
            io::throw_if_interrupted();
            stepper.do_step(rhs, x, t, dt);
            t += dt;
            const double loss = solver::total_loss(m, p, x[0]);
            if (!std::isfinite(loss) || !std::isfinite(x[0]))
                throw InputError("", 0, 0, "operating",
                                 fmt::format("out_of_range at {:.0f} rpm / {:.0f} N*m, t = {:.0f} s: the loss or the oil "
                                             "temperature is not a finite number", w * to_rpm, T, t));
            const double T_rec = (gain * T + offset) * (1.0 + 0.002 * gauss(rng));
            const double loss_rec = (loss + (gain * T + offset - T) * w) * (1.0 + e_loss) * (1.0 + 0.01 * gauss(rng));
            const double T_out = (T_rec * w - loss_rec) / w_out;
            const double oil = x[0] + e_temp + 0.05 * gauss(rng);
            out += fmt::format("{:.0f},{:.2f},{:.2f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f}\n", t, w * to_rpm * (1 + 0.001 * gauss(rng)),
                               w_out * to_rpm, T_rec, T_out, oil - 273.15, oil - 3.0 - 273.15,
                               Ta - 273.15 + 0.05 * gauss(rng));
        }
    }
    return out;
}

}  // namespace gearloss::diagnosis
