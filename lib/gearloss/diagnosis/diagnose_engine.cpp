// diagnose: hypothesis fitting: the model at the recorded points (Engine), one-parameter fits, cross-validation.
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
        if (!p.fault.empty()) return p.fault;
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

Engine::Engine(const solver::Model& m, std::vector<Obs> obs, int threads, bool physical_range)
    : obs_(std::move(obs)), physical_range_(physical_range) {
    threads_ = threads > 0 ? threads : omp_get_max_threads();
    work_.assign(static_cast<size_t>(threads_), m);
    states_.resize(static_cast<size_t>(threads_));
    all_.resize(obs_.size());
    std::iota(all_.begin(), all_.end(), 0);
    for (const auto& o : obs_) {
        mean_loss_ += std::abs(o.loss) / obs_.size();
        mean_n29_ += std::pow(o.w * to_rpm / 1000.0, 2.9) / obs_.size();
        n_T_ += o.T_evidence;
        max_rpm_ = std::max(max_rpm_, std::abs(o.w) * to_rpm);
    }
}

// Never throws (it runs inside parallel regions): a point that cannot be evaluated, or an
// interrupt (polled per point), ends the prediction with `out.failure` set.
void Engine::predict(const Hypothesis& h, const std::vector<int>& idx, Pred& out, int tid) const {
    out.loss.resize(obs_.size());
    out.temp.resize(obs_.size());
    out.failure.clear();
    solver::Model& m = work_[static_cast<size_t>(tid)];
    h.apply_to(m);
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
        const std::string why = evaluate_point(m, p, h, o, out.loss[i], out.temp[i]);
        if (!why.empty()) {
            out.loss[i] = out.temp[i] = std::nan("");
            out.failure = point_name(o) + ": " + why;
            return;
        }
    }
}

// A prediction outside parallel regions of a hypothesis evaluated before (the case as
// described, or a fitted one): an interrupt throws io::Interrupted.
Pred Engine::predict_checked(const Hypothesis& h, const std::vector<int>& idx) const {
    Pred p;
    predict(h, idx, p, 0);
    io::throw_if_interrupted();
    if (!p.failure.empty()) throw std::runtime_error("diagnose: a fitted hypothesis failed at " + p.failure);
    return p;
}

Score Engine::score(const Hypothesis& h, const Pred& p, const std::vector<int>& idx) const {
    double rP = 0, rT = 0;
    Score s;
    for (int i : idx) {
        const Obs& o = obs_[i];
        const double eP = (o.loss - p.loss[i]) / o.scale;
        rP += eP * eP;
        ++s.nP;
        if (o.T_evidence) {
            // A point flagged unstabilised has its own temperature parameter: residual 0.
            const bool own = !h.unstabilised.empty() && h.unstabilised[i];
            const double eT = own ? 0.0 : o.T_oil - p.temp[i];
            rT += eT * eT;
            ++s.nT;
        }
    }
    s.nll = profiled(rP, s.nP, kFloorLoss) + profiled(rT, s.nT, kFloorTemp);
    return s;
}

// kFailedNll when the hypothesis cannot be evaluated at a point of idx (why: *failure, if given).
double Engine::nll(const Hypothesis& h, const std::vector<int>& idx, int tid, std::string* failure) const {
    Pred p;
    predict(h, idx, p, tid);
    if (!p.failure.empty()) {
        if (failure && failure->empty()) *failure = p.failure;
        return kFailedNll;
    }
    return score(h, p, idx).nll;
}

// The scan range of a parameter: its bounds, narrowed to where the model stays physical at
// every point of the campaign (effects.hpp valid_range: heat flow to ambient positive).
std::pair<double, double> Engine::range(const Effect& e) const {
    return physical_range_ ? valid_range(e, max_rpm_) : std::make_pair(e.lower, e.upper);
}

std::vector<double> Engine::scan_values(const Effect& e) const {
    std::vector<double> v;
    auto scaled = [&](double base, std::initializer_list<double> f) {
        for (double x : f) v.push_back(base * x);
    };
    const std::string& id = e.id;
    if (id == "windage") scaled(mean_loss_ / std::max(mean_n29_, 1e-9), {0, .01, .02, .04, .07, .1, .15, .2, .3, .45, .7, 1, 1.5});
    else if (id == "constant_parasitic") scaled(mean_loss_, {0, .01, .02, .04, .07, .1, .15, .2, .3, .45, .7, 1, 1.5});
    else if (id == "churning" || id == "seal_friction")
        v = {0, .25, .5, .75, 1, 1.5, 2, 3, 4, 6, 8, 12, 16, 24, 36, 50};
    else if (id == "bearing_drag") v = {0, .25, .5, 1, 1.5, 2, 3, 4, 6, 8, 12, 16, 24, 36, 50};
    else if (id == "mesh_friction" || id == "oil_viscosity" || id == "thermal_resistance")
        v = {.2, .35, .5, .65, .8, .9, 1, 1.1, 1.25, 1.5, 2, 2.5, 3.5, 5};
    else if (id == "speed_dependent_cooling") v = {-.9, -.6, -.3, -.1, 0, .1, .25, .5, 1, 1.5, 2.5, 4, 6, 10};
    else if (id == "torque_sensor_gain") v = {.8, .85, .9, .93, .96, .98, .99, 1, 1.01, 1.02, 1.04, 1.07, 1.1, 1.15, 1.2};
    else if (id == "torque_sensor_offset") v = {-100, -50, -25, -12, -6, -3, -1, 0, 1, 3, 6, 12, 25, 50, 100};
    const auto [lo, hi] = range(e);
    for (auto& x : v) x = std::clamp(x, lo, hi);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

// Fits one effect's parameter on top of `base` using the points `idx`.
Fit Engine::fit(const Effect& e, const Hypothesis& base, const std::vector<int>& idx, int tid, bool with_uncertainty) const {
    if (e.id == "unstabilised_test") return fit_unstabilised(base, idx, tid);
    Fit f;
    f.k = 1;
    std::string failure;  // the first parameter value (and point) the model could not be evaluated at
    auto at = [&](double x, std::string* why) {
        Hypothesis h = base;
        e.apply(h, x);
        std::string w;
        const double v = nll(h, idx, tid, &w);
        if (!w.empty() && why && why->empty()) *why = fmt::format("{} = {:.4g}: {}", e.parameter, x, w);
        return v;
    };
    auto objective = [&](double x) { return at(x, &failure); };
    auto rejected = [&] {
        f.failed = failure;
        f.nll = kFailedNll;
        f.value = std::nan("");
        f.h = base;
        return f;
    };
    const auto grid = scan_values(e);
    std::vector<double> val(grid.size());
    size_t best = 0;
    for (size_t i = 0; i < grid.size(); ++i) {
        val[i] = objective(grid[i]);
        if (val[i] < val[best]) best = i;
    }
    if (!failure.empty()) return rejected();
    const double lo = grid[best == 0 ? 0 : best - 1], hi = grid[std::min(best + 1, grid.size() - 1)];
    std::uintmax_t iters = 40;
    const auto [x, fx] = boost::math::tools::brent_find_minima(objective, lo, hi, 24, iters);
    if (!failure.empty()) return rejected();
    f.value = fx <= val[best] ? x : grid[best];
    f.nll = std::min(fx, val[best]);
    f.h = base;
    e.apply(f.h, f.value);
    if (with_uncertainty) {
        // Curvature of the profiled log-likelihood: sigma = 1/sqrt(d2 NLL / d theta2).
        const auto [lower, upper] = range(e);
        const double step = std::max(1e-4 * (e.upper - e.lower), 2e-3 * std::abs(f.value));
        const double a = std::max(lower, f.value - step), b = std::min(upper, f.value + step);
        const double fa = at(a, nullptr), fb = at(b, nullptr);
        const double h1 = f.value - a, h2 = b - f.value;
        double d2 = 0;  // a neighbour that cannot be evaluated leaves the uncertainty unknown
        if (h1 > 0 && h2 > 0 && fa < kFailedNll && fb < kFailedNll)
            d2 = 2.0 * (h1 * fb + h2 * fa - (h1 + h2) * f.nll) / (h1 * h2 * (h1 + h2));
        f.uncertainty = d2 > 0 ? 1.0 / std::sqrt(d2) : std::nan("");
    }
    return f;
}

// Greedy: flag the points whose oil is coldest relative to the model until the BIC stops improving.
Fit Engine::fit_unstabilised(const Hypothesis& base, const std::vector<int>& idx, int tid) const {
    Fit f;
    f.h = base;
    Pred p;
    predict(base, idx, p, tid);
    if (!p.failure.empty()) {
        f.failed = p.failure;
        f.nll = kFailedNll;
        return f;
    }
    f.nll = score(base, p, idx).nll;
    if (!has_temperature()) return f;
    std::vector<int> uniq(idx);
    std::sort(uniq.begin(), uniq.end());
    uniq.erase(std::unique(uniq.begin(), uniq.end()), uniq.end());
    // Only points far colder than the noise can be "still warming": robust
    // z-score below -4 against the median/MAD of all temperature residuals.
    std::vector<std::pair<double, int>> resid;
    for (int i : uniq)
        if (obs_[i].T_evidence && (base.unstabilised.empty() || !base.unstabilised[i]))
            resid.push_back({obs_[i].T_oil - p.temp[i], i});
    if (resid.size() < 4) return f;
    std::vector<double> v;
    for (const auto& r : resid) v.push_back(r.first);
    std::sort(v.begin(), v.end());
    const double med = v[v.size() / 2];
    std::vector<double> dev;
    for (double x : v) dev.push_back(std::abs(x - med));
    std::sort(dev.begin(), dev.end());
    const double scale = std::max(1.4826 * dev[dev.size() / 2], 2.0 * kFloorTemp);
    // Still warming (colder) or still cooling (hotter) than the heat balance.
    std::vector<std::pair<double, int>> cold;
    for (const auto& r : resid)
        if (std::abs(r.first - med) / scale > 4.0) cold.push_back({-std::abs(r.first - med), r.second});
    std::sort(cold.begin(), cold.end());
    // Each flagged point costs a parameter (ln N) and the choice of which point (ln n).
    const double penalty = std::log(static_cast<double>(idx.size() + n_T_)) + std::log(static_cast<double>(uniq.size()));
    Hypothesis h = base;
    if (h.unstabilised.empty()) h.unstabilised.assign(obs_.size(), 0);
    double best_bic = 2 * f.nll;
    const size_t max_m = std::min<size_t>(cold.size(), std::max<size_t>(1, uniq.size() / 4));
    for (size_t m = 1; m <= max_m; ++m) {
        h.unstabilised[cold[m - 1].second] = 1;
        const double nll_m = score(h, p, idx).nll;
        const double bic = 2 * nll_m + static_cast<double>(m) * penalty;
        if (bic < best_bic) {
            best_bic = bic;
            f.nll = nll_m;
            f.k = static_cast<int>(m);
            f.extra_penalty = static_cast<double>(m) * std::log(static_cast<double>(uniq.size()));
            f.h = h;
        }
    }
    f.value = f.k;
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

// Leave-one-out: refit on all other points, predict the held-out one.
CvResult cross_validate(const Engine& E, const Effect* e, const Hypothesis& base, const Hypothesis& full_fit) {
    const size_t n = E.obs().size();
    std::vector<double> eP(n, 0), eL(n, 0), eT(n, 0);
    std::vector<char> hasT(n, 0);
    std::vector<std::string> failed(n);
    RegionErrors errors;
#pragma omp parallel for num_threads(E.threads()) schedule(dynamic, 1)
    for (long jl = 0; jl < static_cast<long>(n); ++jl) {
        if (io::interrupted()) continue;  // the remaining folds are skipped; rethrow() throws after the region
        try {
            const int j = static_cast<int>(jl);
            const int tid = omp_get_thread_num();
            Hypothesis h = base;
            if (e) {
                std::vector<int> train;
                for (int i : E.all())
                    if (i != j) train.push_back(i);
                Fit f = E.fit(*e, base, train, tid, false);
                if (!f.failed.empty()) {
                    failed[j] = "fit without " + point_name(E.obs()[j]) + ": " + f.failed;
                    continue;
                }
                h = std::move(f.h);
            }
            Pred p;
            E.predict(h, {j}, p, tid);
            if (!p.failure.empty()) {
                failed[j] = p.failure;
                continue;
            }
            const auto& o = E.obs()[j];
            eL[j] = o.loss - p.loss[j];
            eP[j] = eL[j] / o.scale;
            // A point the full fit calls unstabilised carries no temperature evidence.
            const bool flagged = !full_fit.unstabilised.empty() && full_fit.unstabilised[j];
            if (o.T_evidence && !flagged) {
                eT[j] = o.T_oil - p.temp[j];
                hasT[j] = 1;
            }
        } catch (...) {
            errors.capture();
        }
    }
    errors.rethrow();
    CvResult r;
    for (const auto& f : failed)
        if (!f.empty()) {
            r.failed = "cross-validation: " + f;
            r.nll = kFailedNll;
            return r;
        }
    double rP = 0, rT = 0;
    int nT = 0;
    for (size_t j = 0; j < n; ++j) {
        rP += eP[j] * eP[j];
        r.rmse_loss += eL[j] * eL[j];
        if (hasT[j]) {
            rT += eT[j] * eT[j];
            ++nT;
        }
    }
    // Flagged points keep their (zero) residual in the count so both sides compare like with like.
    int nT_all = 0;
    for (const auto& o : E.obs()) nT_all += o.T_evidence;
    r.nll = profiled(rP, static_cast<int>(n), kFloorLoss) + profiled(rT, nT_all, kFloorTemp);
    r.rmse_loss = std::sqrt(r.rmse_loss / n);
    r.rmse_temp = nT ? std::sqrt(rT / nT) : 0.0;
    return r;
}

}  // namespace gearloss::diagnosis::detail
