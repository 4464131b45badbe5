// diagnose: the joint refit of several accepted parameters at once. Coordinate descent (one
// parameter refitted with the others held) crawls along the valley of two correlated effects
// (a torque-sensor gain and offset, a heat-path factor and forced convection) and costs a
// whole one-parameter fit per parameter per sweep. Gauss-Newton on the profiled likelihood
// (Levenberg 1944, Marquardt 1963 damping) moves them together: each step needs one model
// evaluation per parameter for the Jacobian (finite differences, evaluated in parallel) and
// one for the trial.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "gearloss/diagnosis/diagnose_select.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::diagnosis::detail {
namespace {

// The weighted residuals of a prediction: loss relative to each point's scale, oil
// temperature where it is equilibrium evidence (flagged points excluded), in one vector with
// the channel of each entry; and the profiled likelihood they give (score_points' value).
struct Residuals {
    std::vector<double> r;
    std::vector<char> temp;  // 1: an oil-temperature entry
    double rss_loss = 0, rss_temp = 0;
    int n_loss = 0, n_temp = 0;
    double nll() const { return profiled(rss_loss, n_loss, kFloorLoss) + profiled(rss_temp, n_temp, kFloorTemp); }
};

Residuals residuals(const Engine& E, const Pred& p, const std::vector<char>& flags) {
    Residuals res;
    for (int i : E.all()) {
        const ScaledResidual e = scaled_residual(E.obs()[i], flags, i, p.loss[i], p.temp[i]);
        res.r.push_back(e.loss);
        res.temp.push_back(0);
        res.rss_loss += e.loss * e.loss;
        ++res.n_loss;
        if (e.has_temp) {
            res.r.push_back(e.temp);
            res.temp.push_back(1);
            res.rss_temp += e.temp * e.temp;
            ++res.n_temp;
        }
    }
    return res;
}

}  // namespace

double joint_gauss_newton(const Engine& E, const Hypothesis& neutral, std::vector<Term>& terms,
                          const std::vector<char>& flags, int skip) {
    std::vector<size_t> J;  // the continuous parameters refitted
    for (size_t j = 0; j < terms.size(); ++j)
        if (static_cast<int>(j) != skip && terms[j].effect->kind != EffectKind::pointwise && !terms[j].effect->discrete())
            J.push_back(j);
    const size_t k = J.size();
    // Internal coordinates: the logarithm of a factor (scanned on a log scale too), else the value.
    std::vector<char> lg(k, 0);
    Eigen::VectorXd u(k), lo(k), hi(k), step(k);
    {
        const Hypothesis h = with_terms(neutral, terms, flags, skip);
        for (size_t q = 0; q < k; ++q) {
            const Effect& e = *terms[J[q]].effect;
            const auto [a, b] = E.range(e, h);
            // A value that could not be fitted alone starts from the case's.
            const double start = std::isfinite(terms[J[q]].value) ? terms[J[q]].value : e.neutral;
            lg[q] = e.multiplicative && a > 0 && start > 0;
            lo(q) = lg[q] ? std::log(a) : a;
            hi(q) = lg[q] ? std::log(b) : b;
            u(q) = std::clamp(lg[q] ? std::log(start) : start, lo(q), hi(q));
            step(q) = 1e-3 * (hi(q) - lo(q));
            if (!(step(q) > 0)) return kFailedNll;
        }
    }
    auto value = [&](size_t q, double x) { return lg[q] ? std::exp(x) : x; };
    auto hypothesis = [&](const Eigen::VectorXd& x) {
        std::vector<Term> t = terms;
        for (size_t q = 0; q < k; ++q) t[J[q]].value = value(q, x(q));
        return with_terms(neutral, t, flags, skip);
    };
    // Several hypotheses at once (a Jacobian's columns), or one over the points.
    auto predict_all = [&](const std::vector<Eigen::VectorXd>& xs, std::vector<Pred>& out) {
        out = E.predict_many(xs.size(), [&](size_t c) { return hypothesis(xs[c]); });
    };

    std::vector<Pred> p;
    predict_all({u}, p);
    if (!p[0].failure.empty()) return kFailedNll;
    Residuals cur = residuals(E, p[0], flags);
    double f = cur.nll();
    double lambda = 1e-3;
    bool converged = false;
    for (int iter = 0; iter < 12 && !converged; ++iter) {
        // The Jacobian of the predictions by forward differences, stepping inwards at a bound.
        std::vector<Eigen::VectorXd> xs(k, u);
        Eigen::VectorXd h(k);
        for (size_t q = 0; q < k; ++q) {
            h(q) = u(q) + step(q) <= hi(q) ? step(q) : -step(q);
            xs[q](q) += h(q);
        }
        std::vector<Pred> pj;
        predict_all(xs, pj);
        // Weights of the profiled likelihood: d nll = (n / rss) sum r dr per channel.
        const double wl = cur.n_loss / std::max(cur.rss_loss, cur.n_loss * kFloorLoss * kFloorLoss);
        const double wt = cur.n_temp ? cur.n_temp / std::max(cur.rss_temp, cur.n_temp * kFloorTemp * kFloorTemp) : 0.0;
        Eigen::MatrixXd D(cur.r.size(), k);
        bool usable = true;
        for (size_t q = 0; q < k && usable; ++q) {
            if (!pj[q].failure.empty()) {
                usable = false;
                break;
            }
            const Residuals rq = residuals(E, pj[q], flags);
            for (size_t m = 0; m < cur.r.size(); ++m) D(static_cast<long>(m), static_cast<long>(q)) = (rq.r[m] - cur.r[m]) / h(q);
        }
        if (!usable) break;
        Eigen::VectorXd w(cur.r.size()), r(cur.r.size());
        for (size_t m = 0; m < cur.r.size(); ++m) {
            w(static_cast<long>(m)) = cur.temp[m] ? wt : wl;
            r(static_cast<long>(m)) = cur.r[m];
        }
        const Eigen::MatrixXd H = D.transpose() * w.asDiagonal() * D;
        const Eigen::VectorXd g = D.transpose() * w.asDiagonal() * r;  // half the gradient of sum w r^2
        bool improved = false;
        for (int tries = 0; tries < 6 && !improved; ++tries) {
            Eigen::MatrixXd A = H;
            A.diagonal() += lambda * H.diagonal().cwiseMax(1e-12);
            const Eigen::VectorXd delta = -A.ldlt().solve(g);
            if (!delta.allFinite()) break;
            const Eigen::VectorXd trial = (u + delta).cwiseMax(lo).cwiseMin(hi);
            std::vector<Pred> pt;
            predict_all({trial}, pt);
            io::throw_if_interrupted();
            if (pt[0].failure.empty()) {
                Residuals rt = residuals(E, pt[0], flags);
                const double ft = rt.nll();
                if (ft < f) {
                    const double gain = f - ft;
                    u = trial;
                    cur = std::move(rt);
                    f = ft;
                    lambda = std::max(lambda / 4, 1e-6);
                    improved = true;
                    converged = gain < 0.01;  // nats: the likelihood no longer moves
                    break;
                }
            }
            lambda *= 8;
        }
        if (!improved) break;
    }
    for (size_t q = 0; q < k; ++q) terms[J[q]].value = value(q, u(q));
    return f;
}

}  // namespace gearloss::diagnosis::detail
