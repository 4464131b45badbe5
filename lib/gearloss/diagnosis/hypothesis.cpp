// A compact formula for an unexplained remainder: a library of physically meaningful basis
// columns, forward stepwise selection by K-fold cross-validated weighted least squares, a
// refit on all points with standard errors, and the nearest known mechanisms.
//
// The library is deliberately small and readable (powers of speed, load, viscous drag, steps
// and bands at the recorded speed levels, hot-oil thresholds, run order): the engineer has to
// recognise each term, so a flexible but opaque fit (splines, kernels) would defeat the point.
#include "gearloss/diagnosis/hypothesis.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearloss::diagnosis::hypothesis {

namespace {

// What a basis resembles; one mechanism text per kind.
enum class Kind { Constant, Speed1, Speed2, Speed3, Load, Viscous, Step, Band, HotOil, RunOrder };

const char* mechanism(Kind k) {
    switch (k) {
        case Kind::Constant: return "a constant parasitic loss (pump, auxiliary drag)";
        case Kind::Speed1: return "seal friction or a torque-sensor offset (~ n)";
        case Kind::Speed2: return "churning (~ n^1.5-2)";
        case Kind::Speed3: return "windage (n^2.9)";
        case Kind::Load: return "mesh friction (load-dependent)";
        case Kind::Viscous: return "bearing or churning drag (viscous)";
        case Kind::Step: return "a loss that switches on above a speed (a pump or a clutch engaging?)";
        case Kind::Band: return "a resonance or a local contact problem at one speed";
        case Kind::HotOil: return "a loss that appears only in hot oil (a thermostat or bypass?)";
        case Kind::RunOrder: return "running-in or drift during the campaign (not a law of the operating point)";
    }
    return "";
}

struct Column {
    std::string basis;
    Kind kind;
    Eigen::VectorXd x;
};

// Rounds to `sig` significant digits and prints without an exponent in the range an engineer
// reads (1e-4 .. 1e6), so that "1150 rpm" does not come out as "1.15e+03 rpm".
std::string fmt(double v, int sig = 3) {
    if (v == 0 || !std::isfinite(v)) return v == 0 ? "0" : std::to_string(v);
    const double a = std::fabs(v);
    char buf[64];
    if (a >= 1e6 || a < 1e-4) {
        std::snprintf(buf, sizeof buf, "%.*e", sig - 1, v);
        return buf;
    }
    const int mag = static_cast<int>(std::floor(std::log10(a)));
    const double unit = std::pow(10.0, mag - sig + 1);
    const double r = std::round(v / unit) * unit;
    const int decimals = std::max(0, sig - 1 - mag);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, r);
    return buf;
}

// The same without trailing zeros, for the numbers inside a basis ("exp(-k/5)", "[n > 1150 rpm]").
std::string num(double v, int sig) {
    std::string s = fmt(v, sig);
    if (s.find('.') != std::string::npos && s.find('e') == std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
    }
    return s;
}

void check_finite(const std::vector<double>& v, const char* what) {
    for (double x : v)
        if (!std::isfinite(x)) throw std::invalid_argument(std::string("hypothesis: non-finite value in ") + what);
}

void check_size(const std::vector<double>& v, std::size_t n, const char* what) {
    if (!v.empty() && v.size() != n)
        throw std::invalid_argument(std::string("hypothesis: ") + what + " has " + std::to_string(v.size()) +
                                    " entries, the residual " + std::to_string(n));
}

// Linear-interpolation quantile of a sorted vector.
double quantile(const std::vector<double>& sorted, double p) {
    const double pos = p * static_cast<double>(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, sorted.size() - 1);
    return sorted[i] + (pos - static_cast<double>(i)) * (sorted[j] - sorted[i]);
}

// Speed levels of the grid: sorted speeds split where the relative gap exceeds 1 %.
// Returns each point's level index and, per level, its [min, max] speed.
struct Levels {
    std::vector<int> of_point;
    std::vector<double> lo, hi, mean;
};

Levels speed_levels(const std::vector<double>& speed) {
    const std::size_t n = speed.size();
    std::vector<std::size_t> idx(n);
    std::iota(idx.begin(), idx.end(), 0);
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return speed[a] < speed[b]; });
    Levels L;
    L.of_point.assign(n, 0);
    double sum = 0;
    int count = 0;
    for (std::size_t r = 0; r < n; ++r) {
        const double s = speed[idx[r]];
        if (r > 0) {
            const double prev = speed[idx[r - 1]];
            const double denom = std::max(std::fabs(prev), std::fabs(s));
            if (s - prev > 0.01 * denom) {
                L.mean.push_back(sum / count);
                sum = 0;
                count = 0;
            }
        }
        if (count == 0) {
            L.lo.push_back(s);
            L.hi.push_back(s);
        }
        L.hi.back() = s;
        sum += s;
        ++count;
        L.of_point[idx[r]] = static_cast<int>(L.lo.size()) - 1;
    }
    L.mean.push_back(sum / count);
    return L;
}

// More levels than this is not a grid but a continuous sweep: one band per level would flood
// the library (and the run time at 1000 points), so steps go at speed deciles instead.
constexpr std::size_t max_grid_levels = 12;

class Library {
public:
    explicit Library(std::size_t n) : n_(n) {}

    // Skips constant columns (the intercept aside) and duplicates up to a factor (including a
    // sign): they add nothing to the fit and would make the selection ambiguous.
    void add(std::string basis, Kind kind, Eigen::VectorXd x) {
        const double amax = x.cwiseAbs().maxCoeff();
        if (!(amax > 0) || !x.allFinite()) return;
        if (kind != Kind::Constant && x.maxCoeff() - x.minCoeff() <= 1e-12 * amax) return;
        Eigen::VectorXd u = x / amax;
        for (const auto& c : normalised_)
            if ((u - c).cwiseAbs().maxCoeff() < 1e-9 || (u + c).cwiseAbs().maxCoeff() < 1e-9) return;
        normalised_.push_back(u);
        cols.push_back({std::move(basis), kind, std::move(x)});
    }

    std::size_t n() const { return n_; }
    std::vector<Column> cols;

private:
    std::size_t n_;
    std::vector<Eigen::VectorXd> normalised_;
};

Library build_library(const Features& f, std::size_t n) {
    Library lib(n);
    auto vec = [&](auto fn) {
        Eigen::VectorXd v(static_cast<Eigen::Index>(n));
        for (std::size_t i = 0; i < n; ++i) v(static_cast<Eigen::Index>(i)) = fn(i);
        return v;
    };
    const bool has_n = !f.speed_rpm.empty(), has_t = !f.torque_Nm.empty();
    const bool has_nu = !f.viscosity_cSt.empty(), has_oil = !f.oil_temp_C.empty(), has_k = !f.order.empty();

    lib.add("1", Kind::Constant, Eigen::VectorXd::Ones(static_cast<Eigen::Index>(n)));

    auto sn = [&](std::size_t i) { return f.speed_rpm[i] / 1000.0; };
    if (has_n) {
        lib.add("(n/1000 rpm)", Kind::Speed1, vec([&](std::size_t i) { return sn(i); }));
        lib.add("(n/1000 rpm)^2", Kind::Speed2, vec([&](std::size_t i) { return std::pow(sn(i), 2); }));
        lib.add("(n/1000 rpm)^3", Kind::Speed3, vec([&](std::size_t i) { return std::pow(sn(i), 3); }));
    }

    // Torque relative to the largest recorded one, printed in N*m so the engineer reads it.
    double tmax = 0;
    for (double t : f.torque_Nm) tmax = std::max(tmax, std::fabs(t));
    const std::string tref = "(T_in/" + num(tmax, 4) + " N*m)";
    auto st = [&](std::size_t i) { return f.torque_Nm[i] / tmax; };
    if (has_t && tmax > 0) {
        lib.add(tref, Kind::Load, vec([&](std::size_t i) { return st(i); }));
        lib.add(tref + "^2", Kind::Load, vec([&](std::size_t i) { return st(i) * st(i); }));
        if (has_n) lib.add("(n/1000 rpm) " + tref, Kind::Load, vec([&](std::size_t i) { return sn(i) * st(i); }));
    }

    // Palmgren-like bearing drag: torque ~ (nu n)^(2/3), power ~ (nu n)^(2/3) n; and a
    // Newtonian (Petroff) drag ~ nu n. The reference 1e5 cSt*rpm only keeps the numbers O(1).
    if (has_n && has_nu) {
        auto vn = [&](std::size_t i) { return std::max(0.0, f.viscosity_cSt[i] * f.speed_rpm[i]) / 1e5; };
        lib.add("(nu*n/1e5 cSt*rpm)^(2/3) (n/1000 rpm)", Kind::Viscous,
                vec([&](std::size_t i) { return std::pow(vn(i), 2.0 / 3.0) * sn(i); }));
        lib.add("(nu*n/1e5 cSt*rpm)", Kind::Viscous, vec([&](std::size_t i) { return vn(i); }));
    }

    if (has_n) {
        const Levels L = speed_levels(f.speed_rpm);
        const std::size_t nl = L.lo.size();
        std::vector<double> cuts;
        if (nl <= max_grid_levels) {
            for (std::size_t j = 0; j + 1 < nl; ++j) cuts.push_back(0.5 * (L.hi[j] + L.lo[j + 1]));
        } else {
            std::vector<double> s = f.speed_rpm;
            std::sort(s.begin(), s.end());
            for (int d = 1; d <= 9; ++d) cuts.push_back(quantile(s, d / 10.0));
        }
        for (double c : cuts)
            lib.add("[n > " + num(c, 4) + " rpm]", Kind::Step,
                    vec([&](std::size_t i) { return f.speed_rpm[i] > c ? 1.0 : 0.0; }));
        if (nl <= max_grid_levels) {
            for (std::size_t j = 0; j < nl; ++j) {
                const std::string at = "[n = " + num(L.mean[j], 4) + " rpm]";
                auto in = [&, j](std::size_t i) { return L.of_point[i] == static_cast<int>(j) ? 1.0 : 0.0; };
                lib.add(at, Kind::Band, vec(in));
                if (has_t && tmax > 0)
                    lib.add(tref + "^2 " + at, Kind::Band, vec([&](std::size_t i) { return in(i) * st(i) * st(i); }));
            }
        }
    }

    if (has_oil) {
        std::vector<double> s = f.oil_temp_C;
        std::sort(s.begin(), s.end());
        for (double p : {0.25, 0.5, 0.75}) {
            const double q = quantile(s, p);
            lib.add("[theta_oil > " + num(q, 3) + " degC]", Kind::HotOil,
                    vec([&](std::size_t i) { return f.oil_temp_C[i] > q ? 1.0 : 0.0; }));
        }
    }

    if (has_k) {
        // k: the rank of each point in the run order (0 = first recorded), so that gaps or
        // offsets in the row numbers do not matter.
        std::vector<std::size_t> idx(n);
        std::iota(idx.begin(), idx.end(), 0);
        std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return f.order[a] < f.order[b]; });
        std::vector<double> k(n);
        for (std::size_t r = 0; r < n; ++r) k[idx[r]] = static_cast<double>(r);
        const double N = static_cast<double>(n);
        for (double frac : {0.1, 0.2, 0.4}) {
            const double tau = frac * N;
            lib.add("exp(-k/" + num(tau, 3) + ")", Kind::RunOrder,
                    vec([&](std::size_t i) { return std::exp(-k[i] / tau); }));
        }
        lib.add("(k/" + num(N, 4) + ")", Kind::RunOrder, vec([&](std::size_t i) { return k[i] / N; }));
    }
    return lib;
}

// Weighted least squares through a rank-revealing decomposition: a fold's training points may
// not span a band column (all its points held out); the minimum-norm solution then predicts 0.
Eigen::VectorXd wls(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::VectorXd& sw) {
    const Eigen::MatrixXd A = sw.asDiagonal() * X;
    const Eigen::VectorXd b = sw.cwiseProduct(y);
    return A.completeOrthogonalDecomposition().solve(b);
}

// Coefficients on all points and their standard errors from (X^T W X)^-1 sigma^2, sigma^2 the
// weighted residual variance with n - p degrees of freedom.
struct Fit {
    Eigen::VectorXd beta, se;
};

Fit refit(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& sw) {
    Fit fit;
    fit.beta = wls(X, y, sw);
    const Eigen::VectorXd e = y - X * fit.beta;
    const double dof = static_cast<double>(X.rows() - X.cols());
    const double sigma2 = w.dot(e.cwiseProduct(e)) / dof;
    const Eigen::MatrixXd XtWX = X.transpose() * w.asDiagonal() * X;
    const Eigen::MatrixXd cov = XtWX.completeOrthogonalDecomposition().pseudoInverse() * sigma2;
    fit.se = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
    return fit;
}

// z with P(|Z| > z) = a for a standard normal Z, by bisection on erfc (monotone, no tables).
double two_sided_z(double a) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > a ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

struct Problem {
    const Library& lib;
    Eigen::VectorXd y, w, sw;  // residual, weights (mean 1), their square roots
    std::vector<int> fold;
    int K;

    Eigen::MatrixXd design(const std::vector<std::size_t>& sel) const {
        Eigen::MatrixXd X(y.size(), static_cast<Eigen::Index>(sel.size()));
        for (std::size_t c = 0; c < sel.size(); ++c) X.col(static_cast<Eigen::Index>(c)) = lib.cols[sel[c]].x;
        return X;
    }

    // Weighted RMS of the out-of-fold prediction error, in W.
    double cv_rmse(const std::vector<std::size_t>& sel) const {
        const Eigen::MatrixXd X = design(sel);
        const Eigen::Index n = y.size(), p = X.cols();
        double sse = 0;
        for (int k = 0; k < K; ++k) {
            Eigen::Index nt = 0;
            for (Eigen::Index i = 0; i < n; ++i) nt += fold[static_cast<std::size_t>(i)] != k;
            Eigen::MatrixXd Xt(nt, p);
            Eigen::VectorXd yt(nt), swt(nt);
            for (Eigen::Index i = 0, r = 0; i < n; ++i) {
                if (fold[static_cast<std::size_t>(i)] == k) continue;
                Xt.row(r) = X.row(i);
                yt(r) = y(i);
                swt(r) = sw(i);
                ++r;
            }
            const Eigen::VectorXd beta = wls(Xt, yt, swt);
            for (Eigen::Index i = 0; i < n; ++i) {
                if (fold[static_cast<std::size_t>(i)] != k) continue;
                const double e = y(i) - X.row(i).dot(beta);
                sse += w(i) * e * e;
            }
        }
        return std::sqrt(sse / w.sum());
    }

    bool full_rank(const std::vector<std::size_t>& sel) const {
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(sw.asDiagonal() * design(sel));
        qr.setThreshold(1e-9);
        return qr.rank() == static_cast<Eigen::Index>(sel.size());
    }
};

}  // namespace

Proposal propose(const std::vector<double>& residual, const std::vector<double>& scale, const Features& f,
                 int max_terms, std::uint64_t seed) {
    const std::size_t n = residual.size();
    check_size(scale, n, "scale");
    if (scale.size() != n) throw std::invalid_argument("hypothesis: scale is empty but the residual is not");
    check_size(f.speed_rpm, n, "speed_rpm");
    check_size(f.torque_Nm, n, "torque_Nm");
    check_size(f.oil_temp_C, n, "oil_temp_C");
    check_size(f.viscosity_cSt, n, "viscosity_cSt");
    check_size(f.order, n, "order");
    check_finite(residual, "residual");
    check_finite(scale, "scale");
    check_finite(f.speed_rpm, "speed_rpm");
    check_finite(f.torque_Nm, "torque_Nm");
    check_finite(f.oil_temp_C, "oil_temp_C");
    check_finite(f.viscosity_cSt, "viscosity_cSt");
    check_finite(f.order, "order");
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
    w /= w.mean();  // the weighted RMS below is then in W
    const double rms0 = std::sqrt(w.dot(y.cwiseProduct(y)) / w.sum());
    // Finite inputs can still overflow here (a scale of 1e-200, a residual of 1e200).
    if (!w.allFinite() || !std::isfinite(rms0)) throw std::invalid_argument("hypothesis: residual or scale out of range");
    out.cv_rmse_before = out.cv_rmse_after = rms0;
    if (n < 6 || rms0 == 0) return out;

    const Library lib = build_library(f, n);
    const int K = static_cast<int>(std::min<std::size_t>(n, 10));

    // Folds by a Fisher-Yates shuffle written out (std::shuffle's draws are implementation
    // defined), so the same seed gives the same folds with every standard library.
    std::vector<std::size_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::mt19937_64 rng(seed);
    for (std::size_t i = n - 1; i > 0; --i) std::swap(perm[i], perm[rng() % (i + 1)]);
    std::vector<int> fold(n);
    for (std::size_t r = 0; r < n; ++r) fold[perm[r]] = static_cast<int>(r % static_cast<std::size_t>(K));

    Problem pb{lib, y, w, w.cwiseSqrt(), fold, K};

    // Each training set holds at least n - ceil(n/K) points; keep one degree of freedom there
    // and one for the residual variance of the refit.
    const auto smallest_train = static_cast<int>(n - (n + static_cast<std::size_t>(K) - 1) / static_cast<std::size_t>(K));
    const int p_max = std::max(0, std::min({max_terms, smallest_train - 1, static_cast<int>(n) - 1}));

    std::vector<std::size_t> sel;
    double current = rms0;  // predicting zero: nothing is fitted, so its CV error is the plain RMS
    while (static_cast<int>(sel.size()) < p_max) {
        double best = std::numeric_limits<double>::infinity();
        std::size_t best_c = lib.cols.size();
        std::size_t candidates = 0;
        for (std::size_t c = 0; c < lib.cols.size(); ++c) {
            if (std::find(sel.begin(), sel.end(), c) != sel.end()) continue;
            std::vector<std::size_t> trial = sel;
            trial.push_back(c);
            if (!pb.full_rank(trial)) continue;  // collinear with the chosen terms: adds nothing
            ++candidates;
            const double e = pb.cv_rmse(trial);
            if (e < best) {
                best = e;
                best_c = c;
            }
        }
        // A term must earn its place: at least 5 % less out-of-fold error.
        if (best_c == lib.cols.size() || !(best < 0.95 * current)) break;
        // The best of some 40 candidates beats 5 % on noise alone in a good share of small
        // campaigns; it must also be significant on all points, at 5 % family-wise over the
        // candidates it was chosen from (Bonferroni), or it is noise that the engineer would
        // read as a second mechanism.
        std::vector<std::size_t> trial = sel;
        trial.push_back(best_c);
        const Fit fit = refit(pb.design(trial), y, w, pb.sw);
        const Eigen::Index last = fit.beta.size() - 1;
        const double z = two_sided_z(0.05 / static_cast<double>(candidates));
        if (!(std::fabs(fit.beta(last)) >= z * fit.se(last))) break;
        sel = std::move(trial);
        current = best;
    }
    out.cv_rmse_after = current;
    out.found = !sel.empty() && current < 0.8 * rms0;
    if (sel.empty()) return out;

    const Fit fit = refit(pb.design(sel), y, w, pb.sw);

    out.formula = "dP = ";
    for (std::size_t t = 0; t < sel.size(); ++t) {
        const Column& c = lib.cols[sel[t]];
        const auto ti = static_cast<Eigen::Index>(t);
        Term term;
        term.basis = c.basis;
        term.coefficient = fit.beta(ti);
        term.uncertainty = fit.se(ti);
        out.terms.push_back(term);

        const std::string mag = fmt(std::fabs(term.coefficient)) + " W " + c.basis;
        if (t == 0)
            out.formula += (term.coefficient < 0 ? "-" : "") + mag;
        else
            out.formula += (term.coefficient < 0 ? " - " : " + ") + mag;

        const std::string m = mechanism(c.kind);
        if (std::find(out.nearest.begin(), out.nearest.end(), m) == out.nearest.end()) out.nearest.push_back(m);
    }
    return out;
}

}  // namespace gearloss::diagnosis::hypothesis
