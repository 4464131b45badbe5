#include "diagnosis/diagnose.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <numbers>
#include <numeric>
#include <omp.h>
#include <random>
#include <stdexcept>

#include "core/errors.hpp"
#include "io/interrupt.hpp"
#include "solver/operating_point.hpp"
#include "solver/validate.hpp"

namespace gearloss::diagnosis {

namespace {

constexpr double to_rpm = 30.0 / std::numbers::pi;
constexpr double kFloorLoss = 0.002;  // relative loss residual floor (0.2 %)
constexpr double kFloorTemp = 0.05;   // K

struct Obs {
    int row;
    double w, torque, loss, ambient, scale;
    bool has_T;        // measured oil temperature known: the loss is compared at it
    bool T_evidence;   // the temperature is an equilibrium value: compared with the coupled solve
    double T_oil;
    bool stabilised;
    double drift;
};

struct Pred {
    std::vector<double> loss, temp;
    std::string failure;  // the first point the hypothesis could not be evaluated at (then the values are void)
};

struct Score {
    double nll = 0;
    int nP = 0, nT = 0;
};

struct Fit {
    double value = 0, nll = 0, uncertainty = 0;
    int k = 0;                 // parameters added
    double extra_penalty = 0;  // selection penalty beyond k ln N (choice of flagged points)
    Hypothesis h;
    std::string failed;        // why the candidate could not be evaluated (it is then rejected)
};

// Objective of a hypothesis that could not be evaluated: finite (Brent's arithmetic stays
// defined), far above any likelihood.
constexpr double kFailedNll = 1e100;
constexpr double kRejectedBic = -1e300;  // delta BIC of a rejected or already used candidate

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

// The first exception thrown in the iterations of a parallel region, rethrown after it
// (an exception must not leave an OpenMP region: that would be std::terminate).
class RegionErrors {
public:
    void capture() noexcept {
#pragma omp critical(diagnose_region_errors)
        if (!first_) first_ = std::current_exception();
    }
    void rethrow() const {
        io::throw_if_interrupted();
        if (first_) std::rethrow_exception(first_);
    }

private:
    std::exception_ptr first_;
};

double profiled(double rss, int n, double floor) {
    if (n == 0) return 0.0;
    return 0.5 * n * std::log(std::max(rss / n, floor * floor));
}

class Engine {
public:
    Engine(const solver::Model& m, std::vector<Obs> obs, int threads, bool physical_range)
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
    int threads() const { return threads_; }
    const std::vector<Obs>& obs() const { return obs_; }
    const std::vector<int>& all() const { return all_; }
    bool has_temperature() const { return n_T_ > 0; }

    // Never throws (it runs inside parallel regions): a point that cannot be evaluated, or an
    // interrupt (polled per point), ends the prediction with `out.failure` set.
    void predict(const Hypothesis& h, const std::vector<int>& idx, Pred& out, int tid) const {
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
    Pred predict_checked(const Hypothesis& h, const std::vector<int>& idx) const {
        Pred p;
        predict(h, idx, p, 0);
        io::throw_if_interrupted();
        if (!p.failure.empty()) throw std::runtime_error("diagnose: a fitted hypothesis failed at " + p.failure);
        return p;
    }

    Score score(const Hypothesis& h, const Pred& p, const std::vector<int>& idx) const {
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
    double nll(const Hypothesis& h, const std::vector<int>& idx, int tid, std::string* failure = nullptr) const {
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
    std::pair<double, double> range(const Effect& e) const {
        return physical_range_ ? valid_range(e, max_rpm_) : std::make_pair(e.lower, e.upper);
    }

    std::vector<double> scan_values(const Effect& e) const {
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
    Fit fit(const Effect& e, const Hypothesis& base, const std::vector<int>& idx, int tid, bool with_uncertainty) const {
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
    Fit fit_unstabilised(const Hypothesis& base, const std::vector<int>& idx, int tid) const {
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

private:
    std::vector<Obs> obs_;
    std::vector<int> all_;
    int threads_ = 1;
    mutable std::vector<solver::Model> work_;
    mutable std::vector<solver::PointState> states_;
    double mean_loss_ = 0, mean_n29_ = 0, max_rpm_ = 0;
    bool physical_range_ = true;
    int n_T_ = 0;
};

double delta_bic(double nll_base, const Fit& f, size_t n_obs) {
    return 2.0 * (nll_base - f.nll) - f.k * std::log(static_cast<double>(n_obs)) - f.extra_penalty;
}

size_t n_observations(const Engine& E, const std::vector<int>& idx) {
    size_t n = idx.size();
    for (int i : idx) n += E.obs()[i].T_evidence;
    return n;
}

struct ChannelStats {
    double rmse_loss = 0, rmse_temp = 0;
};

ChannelStats channel_rmse(const Engine& E, const Pred& p, const Hypothesis& h) {
    ChannelStats s;
    int nT = 0;
    for (int i : E.all()) {
        const auto& o = E.obs()[i];
        s.rmse_loss += std::pow(o.loss - p.loss[i], 2);
        if (o.T_evidence && (h.unstabilised.empty() || !h.unstabilised[i])) {
            s.rmse_temp += std::pow(o.T_oil - p.temp[i], 2);
            ++nT;
        }
    }
    s.rmse_loss = std::sqrt(s.rmse_loss / E.obs().size());
    s.rmse_temp = nT ? std::sqrt(s.rmse_temp / nT) : 0.0;
    return s;
}

// Leave-one-out: refit on all other points, predict the held-out one.
struct CvResult {
    double nll = 0, rmse_loss = 0, rmse_temp = 0;
    std::string failed;  // a fold whose fit or prediction could not be evaluated (the candidate is rejected)
};

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

// Is there structure a generic smooth model of the operating point explains?
// Residuals regressed on [1, ln n, torque, oil temperature] per channel (OLS, Eigen).
double structure_delta_bic(const Engine& E, const Pred& p, const Hypothesis& h) {
    const auto& obs = E.obs();
    const int n = static_cast<int>(obs.size());
    auto design = [&](bool temp_only) {
        std::vector<int> rows;
        for (int i = 0; i < n; ++i)
            if (!temp_only || (obs[i].T_evidence && (h.unstabilised.empty() || !h.unstabilised[i]))) rows.push_back(i);
        Eigen::MatrixXd X(rows.size(), 4);
        double mT = 0, mQ = 0, mO = 0;
        for (int i : rows) {
            mT += std::log(std::max(obs[i].w, 1e-3)) / rows.size();
            mQ += obs[i].torque / rows.size();
            mO += (obs[i].has_T ? obs[i].T_oil : p.temp[i]) / rows.size();
        }
        for (size_t r = 0; r < rows.size(); ++r) {
            const auto& o = obs[rows[r]];
            X(r, 0) = 1;
            X(r, 1) = std::log(std::max(o.w, 1e-3)) - mT;
            X(r, 2) = (o.torque - mQ) / 100.0;
            X(r, 3) = ((o.has_T ? o.T_oil : p.temp[rows[r]]) - mO) / 10.0;
        }
        return std::make_pair(rows, X);
    };
    double dnll = 0;
    int k = 0;
    size_t nobs = 0;
    {
        auto [rows, X] = design(false);
        Eigen::VectorXd y(rows.size());
        for (size_t r = 0; r < rows.size(); ++r) y(r) = (obs[rows[r]].loss - p.loss[rows[r]]) / obs[rows[r]].scale;
        if (rows.size() > 6) {
            const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
            const double rss0 = y.squaredNorm(), rss1 = (y - X * beta).squaredNorm();
            const int m = static_cast<int>(rows.size());
            dnll += profiled(rss0, m, kFloorLoss) - profiled(rss1, m, kFloorLoss);
            k += 4;
            nobs += rows.size();
        }
    }
    if (E.has_temperature()) {
        auto [rows, X] = design(true);
        Eigen::VectorXd y(rows.size());
        for (size_t r = 0; r < rows.size(); ++r) y(r) = obs[rows[r]].T_oil - p.temp[rows[r]];
        if (rows.size() > 6) {
            const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
            const double rss0 = y.squaredNorm(), rss1 = (y - X * beta).squaredNorm();
            const int m = static_cast<int>(rows.size());
            dnll += profiled(rss0, m, kFloorTemp) - profiled(rss1, m, kFloorTemp);
            k += 4;
            nobs += rows.size();
        }
    }
    return 2.0 * dnll - k * std::log(static_cast<double>(std::max<size_t>(nobs, 2)));
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
    const size_t n = x.size();
    if (n < 3) return 0;
    const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double sxy = 0, sxx = 0, syy = 0;
    for (size_t i = 0; i < n; ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// Where the mismatch lives: per channel, mean, RMSE, and its dependence on
// speed, torque and oil viscosity.
struct Location {
    std::string text, clause;  // clause: short form for the summary sentence
};

Location locate(const Engine& E, const Pred& p, const Hypothesis& h, const solver::Model& model) {
    const auto& obs = E.obs();
    std::vector<double> lnn, tq, visc, dL, dT, lnnT, tqT, viscT;
    for (size_t i = 0; i < obs.size(); ++i) {
        const auto& o = obs[i];
        const double T = o.has_T ? o.T_oil : p.temp[i];
        lnn.push_back(std::log(std::max(o.w * to_rpm, 1e-3)));
        tq.push_back(o.torque);
        visc.push_back(std::log(model.oil.nu_mm2s(T)));
        dL.push_back(o.loss - p.loss[i]);
        if (o.T_evidence && (h.unstabilised.empty() || !h.unstabilised[i])) {
            dT.push_back(o.T_oil - p.temp[i]);
            lnnT.push_back(lnn.back());
            tqT.push_back(tq.back());
            viscT.push_back(visc.back());
        }
    }
    Location L;
    auto describe = [&](const char* what, const char* unit, const std::vector<double>& d, const std::vector<double>& ln,
                        const std::vector<double>& t, const std::vector<double>& v, double rel_scale,
                        std::string* clause) {
        const size_t n = d.size();
        if (n == 0) return std::string();
        const double mean = std::accumulate(d.begin(), d.end(), 0.0) / n;
        double ss = 0;
        for (double x : d) ss += x * x;
        const double rmse = std::sqrt(ss / n);
        // Torque and viscosity as partial correlations given speed: hotter, thinner
        // oil goes with higher speed, so a raw correlation would blame viscosity
        // for what speed does.
        const double r_n = pearson(ln, d);
        auto partial = [&](const std::vector<double>& x) {
            const double r_xd = pearson(x, d), r_xn = pearson(x, ln);
            const double den = std::sqrt(std::max((1 - r_n * r_n) * (1 - r_xn * r_xn), 1e-12));
            return std::clamp((r_xd - r_n * r_xn) / den, -1.0, 1.0);
        };
        const double r_t = partial(t), r_v = partial(v);
        std::string s = fmt::format("{} residual (recorded - model): mean {:+.3g} {}", what, mean, unit);
        if (rel_scale > 0) s += fmt::format(" ({:+.1f} %)", 100 * mean / rel_scale);
        s += fmt::format(", RMSE {:.3g} {}", rmse, unit);
        // Power law in speed when the residual is one-signed.
        size_t pos = 0;
        for (double x : d) pos += x > 0;
        const bool one_sign = pos >= 0.85 * n || pos <= 0.15 * n;
        double expo = std::nan("");
        if (one_sign && std::abs(mean) > 0) {
            std::vector<double> ld;
            for (double x : d) ld.push_back(std::log(std::max(std::abs(x), 1e-9)));
            const double mx = std::accumulate(ln.begin(), ln.end(), 0.0) / n;
            const double my = std::accumulate(ld.begin(), ld.end(), 0.0) / n;
            double sxy = 0, sxx = 0;
            for (size_t i = 0; i < n; ++i) {
                sxy += (ln[i] - mx) * (ld[i] - my);
                sxx += (ln[i] - mx) * (ln[i] - mx);
            }
            if (sxx > 0) expo = sxy / sxx;
        }
        auto trend = [](double r) {
            return std::abs(r) >= 0.7 ? (r > 0 ? "grows with" : "falls with")
                   : std::abs(r) >= 0.4 ? (r > 0 ? "rises somewhat with" : "falls somewhat with")
                                        : "independent of";
        };
        s += fmt::format("; {} speed (r = {:+.2f}", trend(r_n), r_n);
        if (std::isfinite(expo) && std::abs(r_n) >= 0.4) s += fmt::format(", ~ n^{:.1f}", expo);
        s += fmt::format("), {} torque (partial r = {:+.2f}), {} oil viscosity (partial r = {:+.2f})", trend(r_t), r_t,
                         trend(r_v), r_v);
        size_t big = 0;
        for (size_t i = 1; i < n; ++i)
            if (std::abs(d[i]) > std::abs(d[big])) big = i;
        s += fmt::format("; largest {:+.3g} {} at {:.0f} rpm / {:.0f} N*m", d[big], unit, std::exp(ln[big]), t[big]);
        if (clause) {
            // "<what> residual grows with speed^2.8, independent of torque and viscosity"
            std::vector<std::string> dep, indep;
            if (std::abs(r_n) >= 0.4)
                dep.push_back(std::isfinite(expo) ? fmt::format("{} speed (~ n^{:.1f})", r_n > 0 ? "grows with" : "falls with", expo)
                                                  : fmt::format("{} speed", trend(r_n)));
            else
                indep.push_back("speed");
            if (std::abs(r_t) >= 0.4) dep.push_back(fmt::format("{} torque", trend(r_t)));
            else indep.push_back("torque");
            if (std::abs(r_v) >= 0.4) dep.push_back(fmt::format("{} viscosity", trend(r_v)));
            else indep.push_back("viscosity");
            std::string c = fmt::format("{} residual ", what);
            if (dep.empty()) c += fmt::format("{:+.3g} {} on average, ", mean, unit);
            for (size_t i = 0; i < dep.size(); ++i) c += (i ? ", " : "") + dep[i];
            if (!indep.empty()) {
                c += dep.empty() ? "independent of " : ", independent of ";
                for (size_t i = 0; i < indep.size(); ++i)
                    c += (i == 0 ? "" : i + 1 == indep.size() ? " and " : ", ") + indep[i];
            }
            *clause = c;
        }
        return s;
    };
    double mean_loss = 0;
    for (const auto& o : obs) mean_loss += o.loss / obs.size();
    std::string cl, ct;
    L.text = describe("loss", "W", dL, lnn, tq, visc, mean_loss, &cl);
    if (!dT.empty()) L.text += "\n" + describe("oil temperature", "K", dT, lnnT, tqT, viscT, 0, &ct);
    L.clause = cl;
    if (!ct.empty()) L.clause += "; " + ct;
    return L;
}

// Why a recorded point cannot be compared with the model (empty: it can): a value that is
// not finite or outside the stated ranges, an oil or ambient temperature outside the oil's
// validity (a recorded oil_temp_C of 9999).
std::string recorded_fault(const solver::Model& model, const Obs& o) {
    if (!std::isfinite(o.loss)) return "the recorded loss is not a finite number";
    if (auto f = solver::speed_fault(o.w)) return "recorded " + *f;
    if (auto f = solver::torque_fault(o.torque)) return "recorded " + *f;
    if (auto f = solver::ambient_fault(o.ambient)) return *f;
    if (model.thermal.mode == solver::ThermalMode::stabilised)
        if (auto f = solver::oil_temperature_fault(model.oil, o.ambient)) return "ambient temperature " + *f;
    if (o.has_T)
        if (auto f = solver::oil_temperature_fault(model.oil, o.T_oil)) return "recorded oil temperature " + *f;
    return {};
}

}  // namespace

std::string fmt_value(double v, const std::string& unit) {
    return unit.empty() ? fmt::format("{:.4g}", v) : fmt::format("{:.4g} {}", v, unit);
}

void DiagnoseOptions::validate() const {
    const auto bad = [](const char* key, const std::string& message) { throw InputError("", 0, 0, key, message); };
    if (bootstrap < 4 || bootstrap > 1000) bad("--bootstrap", fmt::format("{} resamples: give 4 to 1000", bootstrap));
    if (threads < 0 || threads > 1024) bad("--threads", fmt::format("{} threads: give 1 to 1024 (0 = all cores)", threads));
    if (!(bic_threshold >= 0 && bic_threshold <= 1e3)) bad("bic_threshold", "must be within 0..1000");
    if (!(cv_margin >= 0 && cv_margin <= 1e3)) bad("cv_margin", "must be within 0..1000 nats");
    if (!(stability_min >= 0 && stability_min <= 1)) bad("stability_min", "must be a share within 0..1");
    if (!(ambiguity_bic >= 0 && ambiguity_bic <= 1e3)) bad("ambiguity_bic", "must be within 0..1000");
    if (max_findings < 1 || max_findings > 10) bad("max_findings", "give 1 to 10");
}

Diagnosis diagnose(const solver::Model& model, const Recordings& rec, const DiagnoseOptions& opt) {
    opt.validate();
    Diagnosis d;
    d.warnings = rec.warnings;
    // The case as described (with any calibration it carries): the baseline hypothesis.
    Hypothesis neutral = Hypothesis::of(model);
    std::vector<Obs> obs;
    std::vector<Outlier> unused;  // rows the model cannot be compared with: listed, not used
    {
        solver::Model m = model;
        solver::PointState ps;
        for (const auto& r : rec.points) {
            io::throw_if_interrupted();
            Obs o;
            o.row = r.row;
            o.w = r.speed_in;
            o.torque = r.torque_in;
            o.loss = r.loss;
            o.ambient = r.ambient_temp ? *r.ambient_temp : model.thermal.ambient;
            o.has_T = r.oil_temp.has_value();
            // Tests the log criterion rejects carry no equilibrium temperature.
            o.T_evidence = o.has_T && r.stabilised && model.thermal.mode == solver::ThermalMode::stabilised;
            o.T_oil = r.oil_temp ? *r.oil_temp : 0.0;
            o.stabilised = r.stabilised;
            o.drift = r.stabilisation_drift;
            std::string why = recorded_fault(model, o);
            double L = 0, T = 0;
            if (why.empty()) why = evaluate_point(m, ps, neutral, o, L, T);
            if (why.empty() && !(std::isfinite(o.loss - L) && std::isfinite(o.T_oil - T)))
                why = "its residual is not a finite number";
            if (!why.empty()) {
                unused.push_back({o.row, "not used: " + why});
                continue;
            }
            obs.push_back(o);
        }
    }
    double mean_abs = 0;
    for (const auto& o : obs) mean_abs += std::abs(o.loss) / obs.size();
    for (auto& o : obs) o.scale = std::max({std::abs(o.loss), 0.05 * mean_abs, 1.0});
    if (!unused.empty())
        d.warnings.push_back(fmt::format("{} recorded point(s) not used, the model cannot be compared with them (first: row "
                                         "{}, {}); see the outliers",
                                         unused.size(), unused.front().row, unused.front().reason.substr(10)));
    if (obs.size() < 4) {
        std::string why = "at least 4 recorded points are needed for a diagnosis";
        if (!unused.empty())
            why += fmt::format(" ({} usable of {}; row {}: {})", obs.size(), rec.points.size(), unused.front().row,
                               unused.front().reason.substr(10));
        throw std::invalid_argument(why);
    }
    if (model.thermal.mode != solver::ThermalMode::stabilised)
        d.warnings.push_back("the case is in fixed-temperature mode: oil temperatures are not used as evidence");
    Engine E(model, std::move(obs), opt.threads, opt.physical_scan_range);
    d.points = static_cast<int>(E.obs().size());
    d.has_temperature = E.has_temperature();
    const auto& all = E.all();
    const size_t N = n_observations(E, all);

    // The baseline is the case as described, including any calibration it carries.
    const Pred p0 = E.predict_checked(neutral, all);
    const ChannelStats s0 = channel_rmse(E, p0, neutral);
    d.rmse_before = s0.rmse_loss;
    d.temp_rmse_before = s0.rmse_temp;
    const Location baseline = locate(E, p0, neutral, model);
    d.location = baseline.text;
    const std::string& baseline_clause = baseline.clause;

    Hypothesis base = neutral;
    std::vector<std::string> used;
    std::string partial;  // a candidate that matched only part of the residual
    const auto& lib = effect_library();
    for (int round = 0; round < opt.max_findings; ++round) {
        const double nll_base = E.score(base, E.predict_checked(base, all), all).nll;
        std::vector<Fit> fits(lib.size());
        std::vector<double> dbic(lib.size(), kRejectedBic);
        // A candidate that cannot be evaluated somewhere in its scan is rejected with the reason;
        // an interrupt skips the remaining candidates (checked after the region).
#pragma omp parallel for num_threads(E.threads()) schedule(dynamic, 1)
        for (long k = 0; k < static_cast<long>(lib.size()); ++k) {
            if (io::interrupted()) continue;
            if (std::find(used.begin(), used.end(), lib[k].id) != used.end()) continue;
            try {
                fits[k] = E.fit(lib[k], base, all, omp_get_thread_num(), true);
            } catch (const std::exception& ex) {
                fits[k] = Fit{};
                fits[k].failed = ex.what();
            } catch (...) {
                fits[k] = Fit{};
                fits[k].failed = "unknown error";
            }
            if (fits[k].failed.empty()) dbic[k] = delta_bic(nll_base, fits[k], N);
            else fits[k].value = std::nan("");
        }
        io::throw_if_interrupted();
        std::vector<size_t> order(lib.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return dbic[a] > dbic[b]; });
        if (round == 0)
            for (size_t k : order)
                d.candidates.push_back({lib[k].id, fits[k].value, dbic[k], fits[k].failed});
        else
            for (size_t k : order)
                if (!fits[k].failed.empty())
                    d.warnings.push_back(fmt::format("on top of {}: candidate {} rejected: {}", used.back(), lib[k].id,
                                                     fits[k].failed));
        // Candidates that pass the BIC threshold, checked by cross-validation in BIC order.
        CvResult cv0 = cross_validate(E, nullptr, base, base);
        if (!cv0.failed.empty()) throw std::runtime_error("diagnose: the current hypothesis failed in " + cv0.failed);
        int chosen = -1;
        CvResult cv_chosen;
        for (size_t r = 0; r < std::min<size_t>(order.size(), 3); ++r) {
            const size_t k = order[r];
            if (dbic[k] < opt.bic_threshold) break;
            const CvResult cv = cross_validate(E, &lib[k], base, fits[k].h);
            if (!cv.failed.empty()) {
                // Rejected with the reason, not fatal: the next candidate in BIC order is checked.
                const std::string why = fmt::format("{} rejected: {}", lib[k].id, cv.failed);
                if (round == 0)
                    for (auto& c : d.candidates)
                        if (c.effect == lib[k].id) c.rejected = cv.failed;
                d.warnings.push_back("candidate " + why);
                continue;
            }
            if (cv0.nll - cv.nll >= opt.cv_margin) {
                chosen = static_cast<int>(k);
                cv_chosen = cv;
                break;
            }
        }
        if (chosen < 0) break;
        // Stability: refit the leading candidates on bootstrap resamples.
        std::vector<size_t> contenders;
        for (size_t r = 0; r < std::min<size_t>(order.size(), 4); ++r)
            if (dbic[order[r]] > 0) contenders.push_back(order[r]);
        if (std::find(contenders.begin(), contenders.end(), static_cast<size_t>(chosen)) == contenders.end())
            contenders.push_back(static_cast<size_t>(chosen));
        std::vector<int> wins(lib.size(), 0);
        RegionErrors errors;
#pragma omp parallel for num_threads(E.threads()) schedule(dynamic, 1)
        for (int b = 0; b < opt.bootstrap; ++b) {
            if (io::interrupted()) continue;  // the remaining resamples are skipped; rethrow() throws
            try {
                const int tid = omp_get_thread_num();
                std::mt19937_64 rng(opt.seed + 7919u * static_cast<unsigned>(b) + 104729u * static_cast<unsigned>(round));
                std::uniform_int_distribution<int> pick(0, static_cast<int>(all.size()) - 1);
                std::vector<int> idx(all.size());
                for (auto& i : idx) i = pick(rng);
                std::string failure;
                const double nb = E.nll(base, idx, tid, &failure);
                if (!failure.empty()) throw std::runtime_error("diagnose: the current hypothesis failed at " + failure);
                const size_t Nb = n_observations(E, idx);
                int winner = -1;
                double best = opt.bic_threshold;
                for (size_t k : contenders) {
                    const Fit f = E.fit(lib[k], base, idx, tid, false);
                    if (!f.failed.empty()) continue;  // cannot be evaluated on this resample: does not win it
                    const double db = delta_bic(nb, f, Nb);
                    if (db > best) {
                        best = db;
                        winner = static_cast<int>(k);
                    }
                }
#pragma omp critical
                if (winner >= 0) ++wins[winner];
            } catch (...) {
                errors.capture();
            }
        }
        errors.rethrow();
        const double stability = static_cast<double>(wins[chosen]) / opt.bootstrap;
        Finding f;
        const Effect& e = lib[chosen];
        // Equally good alternatives: within the ambiguity margin in BIC.
        double shared = stability;
        // Without temperature evidence, effects that differ only in whether they
        // heat the oil cannot be told apart by the data (only through second-order
        // coupling inside the model), whatever their BIC difference.
        auto unobservable_difference = [&](const Effect& a, const Effect& b) {
            const Signature &x = a.sig, &y = b.sig;
            return !E.has_temperature() && x.heats_oil != y.heats_oil && x.thermal_path == y.thermal_path &&
                   x.load_dependent == y.load_dependent && x.viscosity_dependent == y.viscosity_dependent &&
                   std::abs(x.speed_exponent - y.speed_exponent) < 0.4 && x.pointwise == y.pointwise;
        };
        for (size_t k : order) {
            if (static_cast<int>(k) == chosen || dbic[k] < opt.bic_threshold) continue;
            if (dbic[chosen] - dbic[k] <= opt.ambiguity_bic || unobservable_difference(lib[chosen], lib[k])) {
                f.equivalent.push_back(lib[k].id);
                shared += static_cast<double>(wins[k]) / opt.bootstrap;
                if (f.separating_measurement.empty()) f.separating_measurement = separating_measurement(e, lib[k]);
            }
        }
        if (stability < opt.stability_min && (f.equivalent.empty() || shared < 0.8)) break;
        f.effect = e.id;
        f.description = e.description;
        f.parameter = {e.parameter, e.unit, fits[chosen].value, fits[chosen].uncertainty};
        if (e.id == "unstabilised_test") {
            f.parameter.uncertainty = 0;
            for (int i : all)
                if (fits[chosen].h.unstabilised[i]) f.rows.push_back(E.obs()[i].row);
        }
        f.delta_bic = dbic[chosen];
        f.stability = stability;
        f.cv_gain = cv0.nll - cv_chosen.nll;
        const Pred pb = E.predict_checked(base, all), pa = E.predict_checked(fits[chosen].h, all);
        // A candidate must explain the bulk of the systematic residual: if the
        // structure it leaves (generic smooth fit, BIC) is more significant than
        // what it explained, it is only a partial match, not the explanation.
        const double left = structure_delta_bic(E, pa, fits[chosen].h);
        if (left > opt.bic_threshold && left >= dbic[chosen]) {
            partial = fmt::format("{} explains only part of it (delta BIC {:.1f}, loss RMSE {:.3g} -> {:.3g} W) and leaves "
                                  "a larger systematic residual (delta BIC {:.1f} for a generic fit)",
                                  e.id, dbic[chosen], channel_rmse(E, pb, base).rmse_loss,
                                  channel_rmse(E, pa, fits[chosen].h).rmse_loss, left);
            break;
        }
        const ChannelStats sb = channel_rmse(E, pb, base), sa = channel_rmse(E, pa, fits[chosen].h);
        f.rmse_before = sb.rmse_loss;
        f.rmse_after = sa.rmse_loss;
        f.cv_rmse_before = cv0.rmse_loss;
        f.cv_rmse_after = cv_chosen.rmse_loss;
        f.temp_rmse_before = sb.rmse_temp;
        f.temp_rmse_after = sa.rmse_temp;
        d.findings.push_back(f);
        used.push_back(e.id);
        base = fits[chosen].h;
        d.cv_rmse_after = cv_chosen.rmse_loss;
    }
    d.calibrated = base;

    const Pred pf = E.predict_checked(base, all);
    const ChannelStats sf = channel_rmse(E, pf, base);
    d.rmse_after = sf.rmse_loss;
    d.temp_rmse_after = sf.rmse_temp;
    if (d.findings.empty()) d.cv_rmse_after = d.rmse_before;

    if (!d.findings.empty()) {
        d.verdict = "missing_physics";
        if (structure_delta_bic(E, pf, base) > opt.bic_threshold)
            d.remaining = "a systematic residual remains after the findings:\n" + locate(E, pf, base, model).text;
    } else if (!partial.empty() || structure_delta_bic(E, p0, neutral) > opt.bic_threshold) {
        d.verdict = "unexplained_mismatch";
        d.remaining = d.location;
    } else {
        d.verdict = "no_significant_mismatch";
    }

    // Outliers against the final model (robust z-scores), plus tests the log criterion flagged.
    {
        std::vector<double> eP, eT;
        for (int i : all) {
            const auto& o = E.obs()[i];
            eP.push_back((o.loss - pf.loss[i]) / o.scale);
            if (o.T_evidence && (base.unstabilised.empty() || !base.unstabilised[i])) eT.push_back(o.T_oil - pf.temp[i]);
        }
        auto robust = [](std::vector<double> v, double floor) {
            if (v.empty()) return std::make_pair(0.0, floor);
            std::sort(v.begin(), v.end());
            const double med = v[v.size() / 2];
            std::vector<double> dev;
            for (double x : v) dev.push_back(std::abs(x - med));
            std::sort(dev.begin(), dev.end());
            return std::make_pair(med, std::max(1.4826 * dev[dev.size() / 2], floor));
        };
        const auto [mP, sP] = robust(eP, 0.004);
        const auto [mT, sT] = robust(eT, 0.15);
        for (int i : all) {
            const auto& o = E.obs()[i];
            std::vector<std::string> why;
            if (!o.stabilised)
                why.push_back(fmt::format("never stabilised: (T_oil - T_room) varied {:.2f} K over the last 30 min", o.drift));
            if (!base.unstabilised.empty() && base.unstabilised[i])
                why.push_back(fmt::format("oil {:.1f} K {} than the heat balance of its measured loss: the test was still "
                                          "{} (unstabilised)",
                                          std::abs(pf.temp[i] - o.T_oil), o.T_oil < pf.temp[i] ? "colder" : "hotter",
                                          o.T_oil < pf.temp[i] ? "warming up" : "cooling down"));
            const double zP = ((o.loss - pf.loss[i]) / o.scale - mP) / sP;
            if (std::abs(zP) > 4.5)
                why.push_back(fmt::format("loss {:+.1f} W ({:+.1f} %) away from the model and its neighbours", o.loss - pf.loss[i],
                                          100 * (o.loss - pf.loss[i]) / o.scale));
            if (o.T_evidence && (base.unstabilised.empty() || !base.unstabilised[i])) {
                const double zT = (o.T_oil - pf.temp[i] - mT) / sT;
                if (std::abs(zT) > 4.5) {
                    const double dLz = zP;
                    why.push_back(fmt::format("oil temperature {:+.1f} K away from the model{}", o.T_oil - pf.temp[i],
                                              (o.T_oil < pf.temp[i] && dLz > -1) ? " while its loss is not low: loss and "
                                                                                   "temperature disagree (still warming up?)"
                                                                                 : ""));
                }
            }
            if (!why.empty()) {
                std::string r = why[0];
                for (size_t k = 1; k < why.size(); ++k) r += "; " + why[k];
                d.outliers.push_back({o.row, r});
            }
        }
        if (!unused.empty()) {
            d.outliers.insert(d.outliers.end(), unused.begin(), unused.end());
            std::stable_sort(d.outliers.begin(), d.outliers.end(), [](const Outlier& a, const Outlier& b) { return a.row < b.row; });
        }
    }
    // Every number reported is finite (the rows that could not be compared are not used).
    for (double v : {d.rmse_before, d.rmse_after, d.cv_rmse_after, d.temp_rmse_before, d.temp_rmse_after})
        if (!std::isfinite(v)) throw std::runtime_error("diagnose: a residual statistic is not a finite number");

    // Per-point residuals before and after.
    for (int i : all) {
        const auto& o = E.obs()[i];
        PointResidual r{o.row, o.w * to_rpm, o.torque, o.loss, p0.loss[i], pf.loss[i], {}, {}, {}};
        if (o.has_T) {
            r.temp = o.T_oil - 273.15;
            r.temp_before = p0.temp[i] - 273.15;
            r.temp_after = pf.temp[i] - 273.15;
        }
        d.residuals.push_back(r);
    }

    // The summary, in one paragraph.
    if (d.verdict == "missing_physics") {
        std::string s;
        for (size_t k = 0; k < d.findings.size(); ++k) {
            const auto& f = d.findings[k];
            if (k == 0) s += baseline_clause + " -> ";
            else s += "; then ";
            if (f.equivalent.empty()) {
                s += fmt::format("{} was left out ({})", f.effect, f.description);
            } else {
                std::string eq;
                for (const auto& x : f.equivalent) eq += " or " + x;
                s += fmt::format("{}{} was left out — the data cannot tell which ({})", f.effect, eq, f.description);
            }
            if (f.effect == "unstabilised_test") {
                std::string rows;
                for (int r : f.rows) rows += (rows.empty() ? "" : ", ") + std::to_string(r);
                s += fmt::format("; rows {} excluded from the temperature evidence", rows);
            } else {
                s += fmt::format("; added {} = {}", f.parameter.name, fmt_value(f.parameter.value, f.parameter.unit));
                if (std::isfinite(f.parameter.uncertainty))
                    s += fmt::format(" +/- {}", fmt_value(f.parameter.uncertainty, f.parameter.unit));
            }
            s += fmt::format("; loss RMSE {:.3g} W -> {:.3g} W (cross-validated {:.3g} W)", f.rmse_before, f.rmse_after,
                             f.cv_rmse_after);
            if (d.has_temperature)
                s += fmt::format(", oil temperature RMSE {:.2f} K -> {:.2f} K", f.temp_rmse_before, f.temp_rmse_after);
            if (!f.equivalent.empty()) s += fmt::format(". To separate them: {}", f.separating_measurement);
        }
        d.summary = s + ".";
    } else if (d.verdict == "unexplained_mismatch") {
        d.summary = fmt::format(
            "the recordings differ systematically from the model, but no candidate effect explains it ({}); the "
            "unexplained residual: {}",
            !partial.empty() ? partial
            : d.candidates.front().rejected.empty()
                ? fmt::format("best: {} with delta BIC {:.1f}", d.candidates.front().effect, d.candidates.front().delta_bic)
                : std::string("no candidate could be evaluated"),
            baseline_clause);
    } else if (!d.candidates.front().rejected.empty()) {
        d.verdict = "unexplained_mismatch";
        d.summary = "no candidate effect could be evaluated on these recordings (see the candidates); " + baseline_clause;
    } else {
        d.summary = fmt::format("no significant missing physics: the residuals are consistent with measurement noise "
                                "(loss RMSE {:.3g} W{}); best candidate {} (delta BIC {:.1f}) is below the evidence threshold",
                                d.rmse_before,
                                d.has_temperature ? fmt::format(", oil temperature RMSE {:.2f} K", d.temp_rmse_before) : "",
                                d.candidates.front().effect, d.candidates.front().delta_bic);
    }
    return d;
}

}  // namespace gearloss::diagnosis
