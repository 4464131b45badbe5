// diagnose: the model at the recorded points (Engine), parameter ranges relative to the
// campaign, signatures measured on the model, and the one-parameter fits.
#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numeric>
#include <omp.h>
#include <stdexcept>

#include "gearloss/diagnosis/diagnose_internal.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::diagnosis::detail {

std::string point_name(const Obs& o) {
    return fmt::format("row {} ({:.0f} rpm, {:.4g} N*m)", o.row, o.w * to_rpm, o.torque);
}

// The model at one recorded point under a hypothesis: the loss as recorded (with the
// torque-sensor error) at the measured oil temperature, and the coupled oil temperature.
// Returns why it cannot be evaluated (an exception of a solver, a value that is not finite),
// or an empty string.
std::string evaluate_point(solver::Model& m, solver::PointState& p, const Hypothesis& h, const Obs& o, double& loss,
                           double& temp) {
    try {
        const double T_true = (o.torque - h.art.torque_offset) / h.art.torque_gain;
        solver::prepare_point(m, o.w, T_true, p);
        // The fault names the value that left the model's range ("bearing B1 contact angle"): said as
        // a sentence, since the diagnosis quotes it as the reason a point is not used.
        if (!p.fault.empty())
            return "the model is out of its range at the recorded speed and torque (" + p.fault +
                   " out of range: a torque or speed in the wrong unit, or beyond what the gearbox carries?)";
        // A fixed-temperature case holds its oil where the case says (a cooler): no heat balance.
        if (m.thermal.mode == solver::ThermalMode::fixed) {
            const double T_fixed = m.thermal.oil_temperature;
            loss = solver::total_loss(m, p, o.has_T ? o.T_oil : T_fixed) + (o.torque - T_true) * o.w;
            temp = T_fixed;
            if (std::isfinite(loss)) return {};
            const std::string f = solver::loss_fault(m, p, o.has_T ? o.T_oil : T_fixed, o.ambient);
            return f.empty() ? "the model's loss is not a finite number" : f;
        }
        const auto eq = solver::solve_temperature(m, p, o.ambient);
        if (eq.status == thermal::EquilibriumStatus::iteration_limit)
            return fmt::format("thermal equilibrium: no bracket within {} steps", m.thermal.equilibrium.max_bracket_steps);
        if (eq.status == thermal::EquilibriumStatus::non_finite) {
            const std::string f = std::isfinite(eq.T) ? solver::loss_fault(m, p, eq.T, o.ambient) : std::string();
            return "thermal equilibrium: " + (f.empty() ? std::string("a value that is not finite") : f);
        }
        const double T_model = eq.status == thermal::EquilibriumStatus::ok ? eq.T : m.thermal.equilibrium.T_max;
        const double L = solver::total_loss(m, p, o.has_T ? o.T_oil : T_model);
        loss = L + (o.torque - T_true) * o.w;
        temp = T_model;
        if (!std::isfinite(loss) || !std::isfinite(temp)) {
            const std::string f = solver::loss_fault(m, p, o.has_T ? o.T_oil : T_model, o.ambient);
            return f.empty() ? "the model's loss or oil temperature is not a finite number" : f;
        }
        return {};
    } catch (const std::exception& e) {
        return std::string("solver error: ") + e.what();
    }
}

double profiled(double rss, int n, double floor) {
    if (n == 0) return 0.0;
    return 0.5 * n * std::log(std::max(rss / n, floor * floor));
}

Engine::Engine(const solver::Model& m, std::vector<Obs> obs, int threads, bool physical_range,
               const std::vector<solver::Model>& per_oil, const std::vector<Obs>* campaign)
    : obs_(std::move(obs)),
      physical_range_(physical_range),
      heat_path_speed_dependent_(m.thermal.rejection.depends_on_speed()) {
    threads_ = threads > 0 ? threads : omp_get_max_threads();
    n_oils_ = per_oil.empty() ? 1 : static_cast<int>(per_oil.size());
    work_.reserve(static_cast<size_t>(threads_ * n_oils_));
    for (int t = 0; t < threads_; ++t) {
        if (per_oil.empty()) work_.push_back(m);
        else work_.insert(work_.end(), per_oil.begin(), per_oil.end());
    }
    states_.resize(static_cast<size_t>(threads_));
    all_.resize(obs_.size());
    std::iota(all_.begin(), all_.end(), 0);
    for (const auto& o : obs_) n_T_ += o.T_evidence;
    const std::vector<Obs>& c = campaign ? *campaign : obs_;
    for (const auto& o : c) {
        mean_loss_ += std::abs(o.loss) / c.size();
        mean_power_ += std::abs(o.torque * o.w) / c.size();
        mean_omega_ += std::abs(o.w) / c.size();
        max_rpm_ = std::max(max_rpm_, std::abs(o.w) * to_rpm);
    }
}

void Engine::predict(const Hypothesis& h, const std::vector<int>& idx, Pred& out, int tid) const {
    out.loss.resize(obs_.size());
    out.temp.resize(obs_.size());
    out.failure.clear();
    apply(h, tid);
    solver::PointState& p = states_[static_cast<size_t>(tid)];
    std::vector<char> done(obs_.size(), 0);
    for (int i : idx) {
        if (done[i]) continue;
        done[i] = 1;
        if (io::interrupted()) {
            out.failure = "interrupted";
            return;
        }
        const Obs& o = obs_[i];
        const std::string why = evaluate_point(model(tid, o.oil), p, h, o, out.loss[i], out.temp[i]);
        if (!why.empty()) {
            out.loss[i] = out.temp[i] = std::nan("");
            out.failure = point_name(o) + ": " + why;
            return;
        }
    }
}

double point_viscosity(const Engine& E, const Obs& o, double T) { return E.oil(o.oil).nu_mm2s(T); }

void Engine::apply(const Hypothesis& h, int tid) const {
    for (int j = 0; j < n_oils_; ++j) h.apply_to(model(tid, j), j);
}

std::vector<Pred> Engine::predict_many(size_t count, const std::function<Hypothesis(size_t)>& make) const {
    std::vector<Pred> out(count);
    if (count == 1 && threads_ > 1) {
        // One hypothesis: the points in contiguous runs, one per thread, merged in point order
        // (the first failing point is the one predict() would stop at).
        const Hypothesis h = make(0);
        std::vector<Pred> part(static_cast<size_t>(threads_));
        std::vector<std::vector<int>> run(static_cast<size_t>(threads_));
        for (size_t q = 0; q < all_.size(); ++q) run[q * run.size() / all_.size()].push_back(all_[q]);
#pragma omp parallel for num_threads(threads_) schedule(static, 1)
        for (long t = 0; t < threads_; ++t) predict(h, run[static_cast<size_t>(t)], part[static_cast<size_t>(t)], omp_get_thread_num());
        Pred& p = out[0];
        p.loss.assign(obs_.size(), 0.0);
        p.temp.assign(obs_.size(), 0.0);
        for (size_t t = 0; t < part.size() && p.failure.empty(); ++t) {
            for (int i : run[t]) {
                p.loss[i] = part[t].loss[i];
                p.temp[i] = part[t].temp[i];
            }
            p.failure = part[t].failure;
        }
        return out;
    }
    RegionErrors errors;
#pragma omp parallel for num_threads(threads_) schedule(dynamic, 1)
    for (long c = 0; c < static_cast<long>(count); ++c) {
        try {
            predict(make(static_cast<size_t>(c)), all_, out[static_cast<size_t>(c)], omp_get_thread_num());
        } catch (...) {
            errors.capture();  // an exception must not leave the region (std::terminate)
        }
    }
    errors.rethrow();
    return out;
}

Pred Engine::predict_checked(const Hypothesis& h, const std::vector<int>& idx) const {
    Pred p;
    if (idx == all_) p = std::move(predict_many(1, [&](size_t) { return h; })[0]);
    else predict(h, idx, p, 0);
    io::throw_if_interrupted();
    if (!p.failure.empty()) throw std::runtime_error("diagnose: a fitted hypothesis failed at " + p.failure);
    return p;
}

Score Engine::score(const Hypothesis& h, const Pred& p, const std::vector<int>& idx) const {
    return score_points(obs_, h.unstabilised, idx, [&](int i, double& L, double& T) { L = p.loss[i], T = p.temp[i]; });
}

double Engine::nll(const Hypothesis& h, const std::vector<int>& idx, int tid, std::string* failure) const {
    Pred p;
    predict(h, idx, p, tid);
    if (!p.failure.empty()) {
        if (failure && failure->empty()) *failure = p.failure;
        return kFailedNll;
    }
    return score(h, p, idx).nll;
}

double Engine::loss_sensitivity(const Effect& e, const Hypothesis& base) const {
    // At the measured (or a mid) oil temperature, no thermal solve: what a unit of the
    // parameter adds to the recorded loss on average.
    solver::PointState& p = states_[0];
    const double step = std::max(1e-3, 1e-3 * std::abs(e.neutral));
    double sum = 0;
    int n = 0;
    for (int pass = 0; pass < 2; ++pass) {
        Hypothesis h = base;
        e.apply(h, e.neutral + (pass ? step : 0.0));
        apply(h, 0);
        for (const auto& o : obs_) {
            solver::Model& m = model(0, o.oil);
            const double T_true = (o.torque - h.art.torque_offset) / h.art.torque_gain;
            solver::prepare_point(m, o.w, T_true, p);
            if (!p.fault.empty()) continue;
            const double T = o.has_T ? o.T_oil : m.thermal.mode == solver::ThermalMode::fixed ? m.thermal.oil_temperature
                                                                                                 : o.ambient + 40.0;
            const double L = solver::total_loss(m, p, T) + (o.torque - T_true) * o.w;
            if (!std::isfinite(L)) continue;
            sum += pass ? L : -L;
            n += pass ? 1 : 0;
        }
    }
    return n ? std::abs(sum) / n / step : 0.0;
}

// Loss parameters get bounds relative to the recorded losses; factors on a property, the heat
// path and the pointwise candidate keep their physical bounds.
bool Engine::relative_bounds(const Effect& e) const {
    return physical_range_ && !e.multiplicative && e.kind != EffectKind::heat_path && e.kind != EffectKind::pointwise &&
           !e.discrete();
}

std::pair<double, double> Engine::range_for(const Effect& e, double s) const {
    const auto [lo, hi] = physical_range_ ? valid_range(e, max_rpm_, heat_path_speed_dependent_)
                                          : std::make_pair(e.lower, e.upper);
    if (!relative_bounds(e) || !(s > 0) || !std::isfinite(s)) return {lo, hi};
    // An added (or removed) loss of at most 3x (1.5x) the mean recorded loss: relative to the
    // gearbox, so a 2.5 MW box and a bench gearbox get bounds of the same meaning.
    const double unit = mean_loss_ / s;
    return {std::max(lo, e.neutral - 1.5 * unit), std::min(hi, e.neutral + 3.0 * unit)};
}

std::pair<double, double> Engine::range(const Effect& e, const Hypothesis& base) const {
    return range_for(e, relative_bounds(e) ? loss_sensitivity(e, base) : 0.0);
}

std::vector<double> Engine::scan_values(const Effect& e, const Hypothesis& base) const {
    if (e.discrete()) return {e.lower, e.upper};  // the case's form and the alternative
    std::vector<double> v;
    const bool additive = !e.multiplicative && e.kind != EffectKind::heat_path;
    const double s = additive ? loss_sensitivity(e, base) : 0.0;
    const auto [lo, hi] = range_for(e, s);
    if (e.multiplicative) {
        for (double x : {.2, .3, .4, .5, .6, .7, .8, .87, .93, 1., 1.07, 1.15, 1.25, 1.4, 1.6, 2., 2.5, 3.2, 4., 5.})
            v.push_back(e.neutral * x);
    } else if (e.kind == EffectKind::heat_path) {
        v = {-.9, -.6, -.4, -.25, -.12, -.05, 0, .05, .12, .25, .4, .6, 1, 1.5, 2.5, 4, 6, 10};
    } else {
        const double unit = s > 0 && std::isfinite(s) ? mean_loss_ / s : 1.0;
        for (double x : {-1.5, -1., -.6, -.35, -.2, -.1, -.05, -.02, 0., .02, .05, .1, .2, .35, .6, 1., 1.5, 2.2, 3.})
            v.push_back(e.neutral + x * unit);
    }
    for (auto& x : v) x = std::clamp(x, lo, hi);
    v.push_back(std::clamp(e.neutral, lo, hi));
    auto tidy = [&] {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) <= 1e-12 * (1 + std::abs(a)); }),
                v.end());
    };
    tidy();
    // A parameter that barely moves the loss clamps most values to its bounds: fill the span
    // evenly so that the response still has knots to interpolate between.
    if (v.size() < 8 && hi > lo)
        for (int k = 0; k <= 8; ++k) v.push_back(lo + (hi - lo) * k / 8.0);
    tidy();
    return v;
}

Signature Engine::signature(const Effect& e, const Hypothesis& base) const {
    Signature s;
    s.pointwise = e.kind == EffectKind::pointwise;
    s.thermal_path = e.kind == EffectKind::heat_path;
    s.heats_oil = e.kind == EffectKind::mechanism || e.kind == EffectKind::oil || e.discrete();
    s.form = e.discrete();
    if (s.pointwise || !e.apply) return s;
    // The loss the effect adds at each point, at the recorded oil temperature and 15 K
    // hotter: its powers of speed and load, and whether it follows the oil's viscosity.
    solver::PointState& p = states_[0];
    const double step = e.discrete() ? 1.0 : e.multiplicative ? 0.1 * e.neutral : [&] {
        const double sens = loss_sensitivity(e, base);
        return sens > 0 ? 0.1 * mean_loss_ / sens : 1.0;
    }();
    std::vector<double> ln_n, load, ln_d, ratio;
    double max_torque = 0;
    for (const auto& o : obs_) max_torque = std::max(max_torque, std::abs(o.torque));
    // a: at the recorded temperature, b: 15 K hotter; [0] at the base value, [1] one step up.
    std::vector<double> a[2], b[2];
    for (int pass = 0; pass < 2; ++pass) {
        a[pass].assign(obs_.size(), std::nan(""));
        b[pass].assign(obs_.size(), std::nan(""));
        Hypothesis h = base;
        e.apply(h, e.neutral + (pass ? step : 0.0));
        apply(h, 0);
        for (size_t i = 0; i < obs_.size(); ++i) {
            const auto& o = obs_[i];
            solver::Model& m = model(0, o.oil);
            const double T_true = (o.torque - h.art.torque_offset) / h.art.torque_gain;
            solver::prepare_point(m, o.w, T_true, p);
            if (!p.fault.empty()) continue;
            const double T = o.has_T ? o.T_oil : o.ambient + 40.0;
            a[pass][i] = solver::total_loss(m, p, T) + (o.torque - T_true) * o.w;
            b[pass][i] = solver::total_loss(m, p, T + 15.0) + (o.torque - T_true) * o.w;
        }
    }
    std::vector<double> d0(obs_.size()), d1(obs_.size());
    for (size_t i = 0; i < obs_.size(); ++i) {
        d0[i] = a[1][i] - a[0][i];
        d1[i] = b[1][i] - b[0][i];
    }
    for (size_t i = 0; i < obs_.size(); ++i) {
        if (!(std::abs(d0[i]) > 1e-9 * std::max(1.0, obs_[i].scale)) || !std::isfinite(d1[i])) continue;
        ln_n.push_back(std::log(std::max(std::abs(obs_[i].w) * to_rpm, 1.0)));
        load.push_back(max_torque > 0 ? std::abs(obs_[i].torque) / max_torque : 0.0);
        ln_d.push_back(std::log(std::abs(d0[i])));
        ratio.push_back(d1[i] / d0[i]);
    }
    if (ln_d.size() < 3) return s;
    // ln|dL| = a + b ln n + c load (least squares, normal equations of three unknowns).
    Eigen::MatrixXd X(ln_d.size(), 3);
    Eigen::VectorXd y(ln_d.size());
    for (size_t i = 0; i < ln_d.size(); ++i) {
        X(i, 0) = 1;
        X(i, 1) = ln_n[i];
        X(i, 2) = load[i];
        y(i) = ln_d[i];
    }
    const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
    s.speed_exponent = std::isfinite(beta(1)) ? beta(1) : 0.0;
    s.load_dependent = std::isfinite(beta(2)) && beta(2) > std::log(1.5);  // > 1.5x from no load to full load
    std::sort(ratio.begin(), ratio.end());
    s.viscosity_dependent = std::abs(ratio[ratio.size() / 2] - 1.0) > 0.08;  // changes > 8 % over 15 K
    return s;
}

Fit Engine::refit(const Effect& e, const Hypothesis& base, double near) const {
    if (e.kind == EffectKind::pointwise || e.discrete() || !std::isfinite(near)) return fit(e, base);
    // Three knots of the scan on either side of `near`, and `near` itself.
    const std::vector<double> grid = scan_values(e, base);
    const auto at = std::lower_bound(grid.begin(), grid.end(), near) - grid.begin();
    const long first = std::max<long>(0, at - 3), last = std::min<long>(static_cast<long>(grid.size()), at + 3);
    std::vector<double> knots(grid.begin() + first, grid.begin() + last);
    if (near > grid.front() && near < grid.back()) knots.push_back(near);
    std::sort(knots.begin(), knots.end());
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    if (knots.size() < 5 || knots.size() + 2 >= grid.size()) return fit(e, base);
    Response r;
    Fit f = fit(e, base, &r, std::move(knots));
    // A local scan that failed has no knots: the whole scan.
    if (!f.failed.empty() || r.knots().empty()) return fit(e, base);
    // An optimum at an inner end of the local knots may lie beyond them: the whole scan.
    const bool inner_lo = r.lo() > grid.front(), inner_hi = r.hi() < grid.back();
    const double tol = 1e-6 * (grid.back() - grid.front());
    if ((inner_lo && f.value <= r.lo() + tol) || (inner_hi && f.value >= r.hi() - tol)) return fit(e, base);
    return f;
}

Fit Engine::fit(const Effect& e, const Hypothesis& base, Response* response) const {
    return fit(e, base, response, {});
}

Fit Engine::fit(const Effect& e, const Hypothesis& base, Response* response, std::vector<double> knots) const {
    if (e.kind == EffectKind::pointwise) return fit_unstabilised(base, all_, 0.0);
    Fit f;
    // A published form has no fitted parameter: which candidate it is, is the choice every
    // candidate pays for alike (BIC of a model with none).
    f.k = e.bic_parameters();
    f.extra_penalty = e.shape_penalty();
    Response local;
    Response& r = response ? *response : local;
    r = knots.empty() ? Response(*this, e, base) : Response(*this, e, base, knots);
    auto rejected = [&](const std::string& why) {
        f.failed = why;
        f.nll = kFailedNll;
        f.value = std::nan("");
        f.h = base;
        return f;
    };
    if (!r.failed().empty()) return rejected(r.failed());
    auto [x, fx] = r.minimise(all_);
    f.h = base;
    if (e.discrete()) {  // a choice between two forms: nothing to refine, no curvature
        f.value = x;
        f.nll = fx;
        e.apply(f.h, x);
        f.uncertainty = std::nan("");
        return f;
    }
    // Two refinements: a knot evaluated with the model at the optimum, then re-minimised.
    for (int k = 0; k < 2; ++k) {
        r.refine(x);
        if (!r.failed().empty()) return rejected(r.failed());
        const auto [x2, f2] = r.minimise(all_);
        const bool done = std::abs(x2 - x) <= 1e-4 * (std::abs(x) + (r.hi() - r.lo()) * 1e-3);
        x = x2;
        fx = f2;
        if (done) break;
    }
    f.value = x;
    f.nll = fx;
    f.h = base;
    e.apply(f.h, x);
    f.extra_penalty += e.prior_penalty(x);  // at the maximum-likelihood value (Effect::prior_penalty)
    // Curvature of the profiled log-likelihood: sigma = 1/sqrt(d2 NLL / d theta2).
    const double step = std::max(1e-4 * (r.hi() - r.lo()), 2e-3 * std::abs(x));
    const double a = std::max(r.lo(), x - step), b = std::min(r.hi(), x + step);
    const double fa = r.nll(a, all_), fb = r.nll(b, all_);
    const double h1 = x - a, h2 = b - x;
    double d2 = 0;
    if (h1 > 0 && h2 > 0) d2 = 2.0 * (h1 * fb + h2 * fa - (h1 + h2) * fx) / (h1 * h2 * (h1 + h2));
    f.uncertainty = d2 > 0 ? 1.0 / std::sqrt(d2) : std::nan("");
    return f;
}

double delta_bic(double nll_base, const Fit& f, size_t n_obs) {
    return 2.0 * (nll_base - f.nll) - f.k * std::log(static_cast<double>(n_obs)) - f.extra_penalty;
}

size_t n_observations(const Engine& E, const std::vector<int>& idx) {
    size_t n = idx.size();
    for (int i : idx) n += E.obs()[i].T_evidence;
    return n;
}

}  // namespace gearloss::diagnosis::detail
