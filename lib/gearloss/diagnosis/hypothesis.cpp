// A compact formula for an unexplained remainder: forward stepwise selection over the basis
// library (hypothesis_basis.cpp) by K-fold cross-validated weighted least squares, the size
// chosen by the one-standard-error rule (Hastie, Tibshirani & Friedman 2009, section 7.10),
// which also gives the leading term a form without a location (a power) where one predicts as well,
// a paired test of the cross-validated gain against predicting zero, a refit on all points
// with standard errors, and the nearest known mechanisms.
#include "gearloss/diagnosis/hypothesis.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearloss/diagnosis/hypothesis_basis.hpp"

namespace gearloss::diagnosis::hypothesis {

namespace {

using detail::Column;

void check_finite(const std::vector<double>& v, const char* what) {
    for (double x : v)
        if (!std::isfinite(x)) throw std::invalid_argument(std::string("hypothesis: non-finite value in ") + what);
}

template <class V>
void check_size(const V& v, std::size_t n, const char* what) {
    if (!v.empty() && v.size() != n)
        throw std::invalid_argument(std::string("hypothesis: ") + what + " has " + std::to_string(v.size()) +
                                    " entries, the residual " + std::to_string(n));
}

// Weighted least squares through a rank-revealing decomposition: a fold's training points may
// not span a window column (all its points held out); the minimum-norm solution then predicts 0.
Eigen::VectorXd solve_normal(const Eigen::MatrixXd& G, const Eigen::VectorXd& b) {
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(G);
    cod.setThreshold(1e-10);
    return cod.solve(b);
}

// Coefficients on all points and their standard errors from (X^T W X)^-1 sigma^2, sigma^2 the
// weighted residual variance with n - p degrees of freedom.
struct Fit {
    Eigen::VectorXd beta, se;
};

Fit refit(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::VectorXd& w) {
    Fit fit;
    const Eigen::MatrixXd A = w.cwiseSqrt().asDiagonal() * X;
    fit.beta = A.completeOrthogonalDecomposition().solve(w.cwiseSqrt().cwiseProduct(y));
    const Eigen::VectorXd e = y - X * fit.beta;
    const double dof = std::max(1.0, static_cast<double>(X.rows() - X.cols()));
    const double sigma2 = w.dot(e.cwiseProduct(e)) / dof;
    const Eigen::MatrixXd XtWX = X.transpose() * w.asDiagonal() * X;
    const Eigen::MatrixXd cov = XtWX.completeOrthogonalDecomposition().pseudoInverse() * sigma2;
    fit.se = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
    return fit;
}

// The cross-validation, with the fold sums of every column kept so that a trial model's
// out-of-fold error costs K solves of its p x p normal equations (not K fits over the points):
// the training sums are the totals minus the fold's, and the fold's squared error follows from
// its sums, sum w (y - x b)^2 = yy - 2 b.(X^T W y) + b^T (X^T W X) b.
class CrossValidation {
public:
    CrossValidation(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::VectorXd& w, std::vector<int> fold,
                    int K)
        : X_(X), y_(y), w_(w), fold_(std::move(fold)), K_(K) {
        const Eigen::Index C = X.cols();
        diag_.assign(static_cast<std::size_t>(K + 1), Eigen::VectorXd::Zero(C));
        xy_.assign(static_cast<std::size_t>(K + 1), Eigen::VectorXd::Zero(C));
        yy_.assign(static_cast<std::size_t>(K + 1), 0.0);
        const Eigen::MatrixXd X2 = X.array().square().matrix();
        for (int k = 0; k < K; ++k) {
            const Eigen::VectorXd wk = masked(w, k);
            diag_[k] = X2.transpose() * wk;
            xy_[k] = X.transpose() * wk.cwiseProduct(y);
            yy_[k] = wk.dot(y.cwiseProduct(y));
            diag_[K] += diag_[k];
            xy_[K] += xy_[k];
            yy_[K] += yy_[k];
        }
    }

    // Adds column c to the selection (its fold cross sums with every column).
    void select(Eigen::Index c) {
        std::vector<Eigen::VectorXd> cross(static_cast<std::size_t>(K_ + 1), Eigen::VectorXd::Zero(X_.cols()));
        const Eigen::VectorXd wx = w_.cwiseProduct(X_.col(c));
        for (int k = 0; k < K_; ++k) {
            cross[k] = X_.transpose() * masked(wx, k);
            cross[K_] += cross[k];
        }
        sel_.push_back(c);
        cross_.push_back(std::move(cross));
    }
    const std::vector<Eigen::Index>& selected() const { return sel_; }

    // Out-of-fold weighted mean squared error of the selection plus column c (c < 0: none).
    double mse_with(Eigen::Index c) const {
        const std::size_t p = sel_.size() + (c >= 0 ? 1 : 0);
        if (p == 0) return yy_[K_] / w_.sum();
        double sse = 0;
        Eigen::MatrixXd Gf(p, p), Gt(p, p);
        Eigen::VectorXd bf(p), bt(p);
        for (int k = 0; k <= K_ - 1; ++k) {
            fill(k, c, Gf, bf);
            fill(K_, c, Gt, bt);
            Gt -= Gf;
            bt -= bf;
            const Eigen::VectorXd beta = solve_normal(Gt, bt);
            sse += std::max(0.0, yy_[k] - 2 * beta.dot(bf) + beta.dot(Gf * beta));
        }
        return sse / w_.sum();
    }

    // Whether column c adds a direction to the selection on all points (not collinear with it).
    bool independent(Eigen::Index c) const {
        const std::size_t p = sel_.size() + 1;
        Eigen::MatrixXd G(p, p);
        Eigen::VectorXd b(p);
        fill(K_, c, G, b);
        if (!(G(p - 1, p - 1) > 0)) return false;
        if (p == 1) return true;
        const Eigen::MatrixXd Gss = G.topLeftCorner(p - 1, p - 1);
        const Eigen::VectorXd gsc = G.col(p - 1).head(p - 1);
        const double resid = G(p - 1, p - 1) - gsc.dot(solve_normal(Gss, gsc));
        return resid > 1e-8 * G(p - 1, p - 1);
    }

    // Each point's weighted out-of-fold squared error of a model (its columns), refitted per fold.
    Eigen::VectorXd point_errors(const std::vector<Eigen::Index>& cols) const {
        const Eigen::Index n = y_.size();
        Eigen::VectorXd e2 = Eigen::VectorXd::Zero(n);
        if (cols.empty()) return w_.cwiseProduct(y_.cwiseProduct(y_));
        Eigen::MatrixXd Xs(n, static_cast<Eigen::Index>(cols.size()));
        for (std::size_t j = 0; j < cols.size(); ++j) Xs.col(static_cast<Eigen::Index>(j)) = X_.col(cols[j]);
        for (int k = 0; k < K_; ++k) {
            Eigen::VectorXd wt = w_;
            for (Eigen::Index i = 0; i < n; ++i)
                if (fold_[static_cast<std::size_t>(i)] == k) wt(i) = 0;
            const Eigen::MatrixXd G = Xs.transpose() * wt.asDiagonal() * Xs;
            const Eigen::VectorXd beta = solve_normal(G, Xs.transpose() * wt.cwiseProduct(y_));
            for (Eigen::Index i = 0; i < n; ++i)
                if (fold_[static_cast<std::size_t>(i)] == k) {
                    const double e = y_(i) - Xs.row(i).dot(beta);
                    e2(i) = w_(i) * e * e;
                }
        }
        return e2;
    }

private:
    Eigen::VectorXd masked(const Eigen::VectorXd& v, int k) const {
        Eigen::VectorXd m = v;
        for (Eigen::Index i = 0; i < v.size(); ++i)
            if (fold_[static_cast<std::size_t>(i)] != k) m(i) = 0;
        return m;
    }
    // The sums of fold k (k = K: all points) over the selection plus column c.
    void fill(int k, Eigen::Index c, Eigen::MatrixXd& G, Eigen::VectorXd& b) const {
        const std::size_t s = sel_.size();
        for (std::size_t a = 0; a < s; ++a) {
            for (std::size_t j = 0; j < s; ++j) G(a, j) = cross_[a][k](sel_[j]);
            b(a) = xy_[k](sel_[a]);
        }
        if (c < 0) return;
        for (std::size_t a = 0; a < s; ++a) G(a, s) = G(s, a) = cross_[a][k](c);
        G(s, s) = diag_[k](c);
        b(s) = xy_[k](c);
    }

    const Eigen::MatrixXd& X_;
    const Eigen::VectorXd& y_;
    const Eigen::VectorXd& w_;
    std::vector<int> fold_;
    int K_;
    std::vector<Eigen::VectorXd> diag_, xy_;
    std::vector<double> yy_;
    std::vector<Eigen::Index> sel_;
    std::vector<std::vector<Eigen::VectorXd>> cross_;  // per selected column, per fold (K: total)
};

// z with P(|Z| > z) = a for a standard normal Z, by bisection on erfc (monotone, no tables).
double two_sided_z(double a) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > a ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double mean(const Eigen::VectorXd& v) { return v.mean(); }
double standard_error(const Eigen::VectorXd& v) {
    const double n = static_cast<double>(v.size());
    if (n < 2) return 0;
    const double m = v.mean();
    return std::sqrt((v.array() - m).square().sum() / (n - 1) / n);
}

// The weighted residual sum of squares of a least-squares fit of y on X.
double fit_sse(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::VectorXd& w) {
    const Eigen::MatrixXd A = w.cwiseSqrt().asDiagonal() * X;
    const Eigen::VectorXd b = w.cwiseSqrt().cwiseProduct(y);
    return (b - A * A.completeOrthogonalDecomposition().solve(b)).squaredNorm();
}

// A plain power of one variable (no gate, oil, window or second factor): its exponent can be
// profiled over the grid's other powers of the same variable.
bool plain_power(const Column& c) {
    const Term& t = c.term;
    return t.shape == "power" && std::isfinite(t.exponent) && !t.gate && t.oil.empty() && !t.relative &&
           t.empirical && t.empirical->factors.size() == 1;
}

// Each selected power of one variable profiled over the grid's other powers of the same
// variable (the others refitted): the exponent moves to the least weighted residual sum of
// squares on all points (the selection chose it by its folds' error), and its 95 %
// profile-likelihood interval is the exponents within Delta chi^2 = 3.84 sigma^2 of the least,
// sigma^2 = least SSE / (n - p).
void profile_exponents(std::vector<Column>& lib, std::vector<Eigen::Index>& sel, const Eigen::VectorXd& y,
                        const Eigen::VectorXd& w) {
    const auto N = y.size();
    const auto P = static_cast<Eigen::Index>(sel.size());
    for (Eigen::Index j = 0; j < P; ++j) {
        const auto chosen_index = sel[static_cast<std::size_t>(j)];
        if (!plain_power(lib[static_cast<std::size_t>(chosen_index)])) continue;
        const std::string variable = lib[static_cast<std::size_t>(chosen_index)].term.variable;
        Eigen::MatrixXd X(N, P);
        for (Eigen::Index k = 0; k < P; ++k) X.col(k) = lib[static_cast<std::size_t>(sel[static_cast<std::size_t>(k)])].x;
        std::vector<std::pair<Eigen::Index, double>> profile;  // column, SSE
        for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(lib.size()); ++c) {
            const Column& col = lib[static_cast<std::size_t>(c)];
            if (!plain_power(col) || col.term.variable != variable) continue;
            if (c != chosen_index && std::find(sel.begin(), sel.end(), c) != sel.end()) continue;
            X.col(j) = col.x;
            profile.emplace_back(c, fit_sse(X, y, w));
        }
        auto best = std::min_element(profile.begin(), profile.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
        const double least = best->second;
        const double sigma2 = least / std::max(1.0, static_cast<double>(N - P));
        constexpr double kChiSquare95 = 3.84;  // chi-square quantile, one degree of freedom, 95 %
        sel[static_cast<std::size_t>(j)] = best->first;
        Term& t = lib[static_cast<std::size_t>(best->first)].term;
        double lo = t.exponent, hi = t.exponent;
        for (const auto& [c, sse] : profile) {
            const double a = lib[static_cast<std::size_t>(c)].term.exponent;
            if (sse <= least + kChiSquare95 * sigma2) lo = std::min(lo, a), hi = std::max(hi, a);
        }
        t.exponent_low = lo;
        t.exponent_high = hi;
    }
}

// A column without a location: a plain power of one variable, or the constant.
bool smooth(const Column& c) { return plain_power(c) || (c.term.shape == "constant" && c.term.oil.empty()); }

// best_c, or smooth_c (the best smooth column, -1: none) when it predicts out of fold within one
// paired standard error of it (beside the columns already selected).
Eigen::Index smooth_within_one_se(const CrossValidation& cv, Eigen::Index best_c, Eigen::Index smooth_c) {
    if (smooth_c < 0 || smooth_c == best_c) return best_c;
    auto errors_with = [&cv](Eigen::Index c) {
        auto cols = cv.selected();
        cols.push_back(c);
        return cv.point_errors(cols);
    };
    const Eigen::VectorXd worse = errors_with(smooth_c) - errors_with(best_c);
    return mean(worse) <= standard_error(worse) ? smooth_c : best_c;
}

}  // namespace

Proposal propose(const std::vector<double>& residual, const std::vector<double>& scale, const Features& f,
                 const Settings& settings) {
    const std::size_t n = residual.size();
    check_size(scale, n, "scale");
    if (scale.size() != n) throw std::invalid_argument("hypothesis: scale is empty but the residual is not");
    check_size(f.speed_rpm, n, "speed_rpm");
    check_size(f.torque_Nm, n, "torque_Nm");
    check_size(f.oil_temp_C, n, "oil_temp_C");
    check_size(f.viscosity_cSt, n, "viscosity_cSt");
    check_size(f.order, n, "order");
    check_size(f.model_loss_W, n, "model loss");
    check_size(f.oil, n, "oil");
    check_finite(residual, "residual");
    check_finite(scale, "scale");
    check_finite(f.speed_rpm, "speed_rpm");
    check_finite(f.torque_Nm, "torque_Nm");
    check_finite(f.oil_temp_C, "oil_temp_C");
    check_finite(f.viscosity_cSt, "viscosity_cSt");
    check_finite(f.order, "order");
    check_finite(f.model_loss_W, "model loss");
    // A zero or negative scale has no weight 1/scale^2; it is an input error, not a point to drop.
    for (double s : scale)
        if (!(s > 0)) throw std::invalid_argument("hypothesis: scale must be positive");

    Proposal out;
    if (n == 0) return out;
    const auto N = static_cast<Eigen::Index>(n);
    Eigen::VectorXd y(N), w(N);
    for (std::size_t i = 0; i < n; ++i) {
        y(static_cast<Eigen::Index>(i)) = residual[i];
        w(static_cast<Eigen::Index>(i)) = 1.0 / (scale[i] * scale[i]);
    }
    const double mean_w = w.mean();
    w /= mean_w;  // the weighted RMS below is then in W
    const double rms0 = std::sqrt(w.dot(y.cwiseProduct(y)) / w.sum());
    // Finite inputs can still overflow here (a scale of 1e-200, a residual of 1e200).
    if (!w.allFinite() || !std::isfinite(rms0)) throw std::invalid_argument("hypothesis: residual or scale out of range");
    // Noise of sigma x scale_i at each point has this weighted RMS: sigma / sqrt(mean(1/scale^2)).
    if (settings.noise_relative > 0) out.noise_W = settings.noise_relative / std::sqrt(mean_w);
    out.cv_rmse_before = out.cv_rmse_after = rms0;
    if (n < 6 || rms0 == 0) return out;

    std::vector<Column> lib = detail::build_library(f, n);
    const auto C = static_cast<Eigen::Index>(lib.size());
    // Columns scaled to a largest value of 1 (the normal equations stay well conditioned).
    Eigen::MatrixXd X(N, C);
    for (Eigen::Index c = 0; c < C; ++c) {
        const auto& x = lib[static_cast<std::size_t>(c)].x;
        X.col(c) = x / x.cwiseAbs().maxCoeff();
    }
    const int K = static_cast<int>(std::min<std::size_t>(n, 10));

    // Folds by a Fisher-Yates shuffle written out (std::shuffle's draws are implementation
    // defined), so the same seed gives the same folds with every standard library.
    std::vector<std::size_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::mt19937_64 rng(settings.seed);
    for (std::size_t i = n - 1; i > 0; --i) std::swap(perm[i], perm[rng() % (i + 1)]);
    std::vector<int> fold(n);
    for (std::size_t r = 0; r < n; ++r) fold[perm[r]] = static_cast<int>(r % static_cast<std::size_t>(K));

    CrossValidation cv(X, y, w, fold, K);

    // Each training set holds at least n - ceil(n/K) points; keep one degree of freedom there
    // and one for the residual variance of the refit.
    const auto smallest_train = static_cast<int>(n - (n + static_cast<std::size_t>(K) - 1) / static_cast<std::size_t>(K));
    const int p_max = std::max(0, std::min({settings.max_terms, smallest_train - 2, static_cast<int>(n) - 2}));

    // The forward path: at each size the column that lowers the out-of-fold error most.
    std::vector<std::vector<Eigen::Index>> path = {{}};
    for (int p = 0; p < p_max; ++p) {
        double best = std::numeric_limits<double>::infinity(), best_smooth = best;
        Eigen::Index best_c = -1, smooth_c = -1;
        std::size_t candidates = 0;
        for (Eigen::Index c = 0; c < C; ++c) {
            if (std::find(cv.selected().begin(), cv.selected().end(), c) != cv.selected().end()) continue;
            if (!cv.independent(c)) continue;
            ++candidates;
            const double e = cv.mse_with(c);
            if (e < best) {
                best = e;
                best_c = c;
            }
            if (e < best_smooth && smooth(lib[static_cast<std::size_t>(c)])) {
                best_smooth = e;
                smooth_c = c;
            }
        }
        if (best_c < 0) break;
        // The leading term states the form. A power (or the constant) has no location to
        // choose, while hundreds of steps and hinges do, and the best of those wins the folds
        // on noise: a hinge in cold oil beats a viscous drag nu^p by a fraction of a standard
        // error. So the best smooth column leads when its out-of-fold error is within one
        // standard error (paired, per point) of the best column's: the one-standard-error rule
        // of the size below, applied to the form (Hastie, Tibshirani & Friedman 2009, 7.10).
        if (p == 0) best_c = smooth_within_one_se(cv, best_c, smooth_c);
        // The best of several hundred candidates lowers the out-of-fold error on noise alone in
        // many campaigns; it must also be significant on all points, at 5 % family-wise over
        // the candidates it was chosen from (Bonferroni), or it is noise that the engineer
        // would read as a mechanism.
        std::vector<Eigen::Index> trial = cv.selected();
        trial.push_back(best_c);
        Eigen::MatrixXd Xt(N, static_cast<Eigen::Index>(trial.size()));
        for (std::size_t j = 0; j < trial.size(); ++j) Xt.col(static_cast<Eigen::Index>(j)) = X.col(trial[j]);
        const Fit t = refit(Xt, y, w);
        const Eigen::Index last = t.beta.size() - 1;
        if (!(std::fabs(t.beta(last)) >= two_sided_z(0.05 / static_cast<double>(candidates)) * t.se(last))) break;
        cv.select(best_c);
        path.push_back(cv.selected());
    }

    // The size by the one-standard-error rule: the smallest model whose cross-validated error
    // is within one standard error of the best (noise then does not buy terms).
    std::vector<Eigen::VectorXd> errors;
    std::size_t best_m = 0;
    for (std::size_t m = 0; m < path.size(); ++m) {
        errors.push_back(cv.point_errors(path[m]));
        if (mean(errors[m]) < mean(errors[best_m])) best_m = m;
    }
    const double limit = mean(errors[best_m]) + standard_error(errors[best_m]);
    std::size_t chosen = best_m;
    for (std::size_t m = 0; m < best_m; ++m)
        if (mean(errors[m]) <= limit) {
            chosen = m;
            break;
        }
    // ... and its gain over predicting zero significant: the paired per-point differences of
    // the out-of-fold squared errors more than 2 standard errors above zero, or (a law of a
    // few points, a step or a window, whose gain is too concentrated for that test) a fifth
    // less out-of-fold error.
    const Eigen::VectorXd gain = errors[0] - errors[chosen];
    const bool significant =
        chosen > 0 && (mean(gain) > 2 * standard_error(gain) || std::sqrt(mean(errors[chosen]) / mean(errors[0])) < 0.8);
    out.cv_rmse_after = std::sqrt(mean(errors[chosen]) * static_cast<double>(n) / w.sum());
    out.found = significant;
    if (!significant) {
        out.cv_rmse_after = rms0;
        return out;
    }
    std::vector<Eigen::Index> sel = path[chosen];
    // Each power's exponent at the least squares of all points (the selection chose it on folds).
    profile_exponents(lib, sel, y, w);
    if (sel != path[chosen])  // the reported cross-validated error is the formula's as reported
        out.cv_rmse_after = std::sqrt(mean(cv.point_errors(sel)) * static_cast<double>(n) / w.sum());

    Eigen::MatrixXd Xs(N, static_cast<Eigen::Index>(sel.size()));
    for (std::size_t j = 0; j < sel.size(); ++j) Xs.col(static_cast<Eigen::Index>(j)) = lib[static_cast<std::size_t>(sel[j])].x;
    const Fit fit = refit(Xs, y, w);

    out.formula = "dP = ";
    for (std::size_t t = 0; t < sel.size(); ++t) {
        const Column& c = lib[static_cast<std::size_t>(sel[t])];
        const auto ti = static_cast<Eigen::Index>(t);
        Term term = c.term;
        term.coefficient = fit.beta(ti);
        term.uncertainty = fit.se(ti);
        if (term.empirical) term.empirical->coefficient = term.coefficient;
        const std::string mag = detail::fmt(std::fabs(term.coefficient)) + (c.term.relative ? " " : " W ") + c.term.basis;
        if (t == 0)
            out.formula += (term.coefficient < 0 ? "-" : "") + mag;
        else
            out.formula += (term.coefficient < 0 ? " - " : " + ") + mag;
        out.terms.push_back(std::move(term));
        if (std::find(out.nearest.begin(), out.nearest.end(), c.mechanism) == out.nearest.end())
            out.nearest.push_back(c.mechanism);
    }
    return out;
}

}  // namespace gearloss::diagnosis::hypothesis
