// diagnose: the joint refit of several accepted parameters at once. Coordinate descent (one
// parameter refitted with the others held) crawls along the valley of two correlated effects
// (a torque-sensor gain and offset, a heat-path factor and forced convection) and costs a
// whole one-parameter fit per parameter per sweep. Gauss-Newton on the profiled likelihood
// (Levenberg 1944, Marquardt 1963 damping) moves them together: each step needs one model
// evaluation per parameter for the Jacobian (finite differences, evaluated in parallel) and
// one for the trial. Then refit_jointly: that refit with the findings' shapes moved along
// their grids (a profiled shape stepwise, a refinement scanned coarsely over its grid, then stepwise).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "gearloss/diagnosis/diagnose_select.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::diagnosis::detail {
namespace {

// A refinement's first scan visits every other grid value (on the film limit's, a factor 1.41
// apart): the likelihood along it is peaked (a logistic step 15 % wide), and every fourth
// value missed the peak of the planetary step + heat path campaign.
constexpr size_t kRefinementScanStride = 2;
// The grid indices of that scan.
std::vector<size_t> refinement_scan(size_t grid_size) {
    std::vector<size_t> visit;
    for (size_t k = 0; k < grid_size; k += kRefinementScanStride) visit.push_back(k);
    return visit;
}

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

// Two or more continuous parameters: Gauss-Newton over all of them at once (above).
// Otherwise coordinate descent: each refitted with the others held (forms, flagged points),
// until the likelihood stops improving (a few sweeps; every step a one-parameter fit near
// the value it had).
// The flagged points of an unstabilised-test term are chosen again only when `refit_flags`
// (after an addition); trial fits keep them, so that no trial gains flags it does not pay for.
// kFailedNll when the combination cannot be evaluated (a trial is then rejected, not fatal).
namespace {
// refit_jointly with each term's shape setting held.
double refit_shapes_held(const Engine& E, const Hypothesis& neutral, std::vector<Term>& terms, std::vector<char>& flags,
                         const DiagnoseOptions& opt, bool refit_flags, int skip) {
    size_t continuous = 0;
    bool pointwise = false;
    for (size_t j = 0; j < terms.size(); ++j) {
        if (static_cast<int>(j) == skip) continue;
        pointwise |= terms[j].effect->kind == EffectKind::pointwise;
        continuous += terms[j].effect->kind != EffectKind::pointwise && !terms[j].effect->discrete();
    }
    if (continuous >= 2) {
        const double f = joint_gauss_newton(E, neutral, terms, flags, skip);
        if (f >= kFailedNll || !pointwise || !refit_flags) return f;
        // The flagged points chosen again on top of the refitted laws, then the laws once more.
        Hypothesis clean = with_terms(neutral, terms, flags, skip);
        clean.unstabilised.clear();
        const Fit fl = E.fit_unstabilised(clean, E.all(), opt.loss_uncertainty);
        if (fl.failed.empty()) flags = fl.h.unstabilised;
        return joint_gauss_newton(E, neutral, terms, flags, skip);
    }
    double last = kFailedNll;
    for (int sweep = 0; sweep < 4; ++sweep) {
        for (size_t j = 0; j < terms.size(); ++j) {
            if (static_cast<int>(j) == skip) continue;
            const Hypothesis h = with_terms(neutral, terms, flags, skip);
            if (terms[j].effect->kind == EffectKind::pointwise) {
                if (!refit_flags) continue;
                Hypothesis clean = h;
                clean.unstabilised.clear();
                const Fit f = E.fit_unstabilised(clean, E.all(), opt.loss_uncertainty);
                if (f.failed.empty()) flags = f.h.unstabilised;
                continue;
            }
            const Fit f = E.refit(*terms[j].effect, h, terms[j].value);
            if (f.failed.empty()) terms[j].value = f.value;
        }
        const Hypothesis h = with_terms(neutral, terms, flags, skip);
        const double now = E.nll(h, E.all(), 0);
        if (now >= kFailedNll) return kFailedNll;
        if (terms.size() - (skip >= 0) <= 1 || last - now < 0.01) return now;
        last = now;
    }
    return last;
}
}  // namespace

std::vector<size_t> refinement_leads(const Engine& E, const Hypothesis& neutral, const std::vector<Term>& terms,
                                     const std::vector<char>& flags, const DiagnoseOptions& opt, size_t count) {
    const auto j = static_cast<size_t>(std::find_if(terms.begin(), terms.end(), [](const Term& t) {
                                           return t.effect->shape && t.effect->shape->deferred &&
                                                  t.effect->shape->variants && t.effect->shape->at_own();
                                       }) - terms.begin());
    if (j == terms.size()) return {};
    const std::vector<Effect>& variants = *terms[j].effect->shape->variants;
    std::vector<std::pair<double, size_t>> scanned;
    for (size_t k : refinement_scan(variants.size())) {
        if (variants[k].shape->at_own()) continue;
        std::vector<Term> t = terms;
        t[j].effect = &variants[k];
        std::vector<char> fl = flags;
        const double nll = refit_shapes_held(E, neutral, t, fl, opt, false, -1);
        if (nll < kFailedNll) scanned.emplace_back(nll, k);
    }
    std::sort(scanned.begin(), scanned.end());
    std::vector<size_t> leads;
    for (size_t r = 0; r < std::min(count, scanned.size()); ++r) leads.push_back(scanned[r].second);
    return leads;
}

double refit_jointly(const Engine& E, const Hypothesis& neutral, std::vector<Term>& terms, std::vector<char>& flags,
                     const DiagnoseOptions& opt, bool refit_flags, int skip, bool hold_deferred,
                     const std::vector<size_t>* scan) {
    double best = refit_shapes_held(E, neutral, terms, flags, opt, refit_flags, skip);
    // A profiled shape (where mixed friction sets in) was chosen for its effect alone; with
    // others beside it, it moves too (an onset chosen alone absorbs part of a bearing drag that
    // its partner then cannot win): from its value, a step along its grid while the joint
    // likelihood improves, towards the better neighbour. A deferred shape (a refinement of a
    // named effect) moves also when its effect stands alone, and is held while a candidate is
    // judged beside the findings (`hold_deferred`: the candidate would be credited with its move).
    // The refinement `scan` belongs to: the first unmoved one, as refinement_leads finds it.
    const auto unmoved_refinement = [](const Term& t) {
        return t.effect->shape && t.effect->shape->deferred && t.effect->shape->variants && t.effect->shape->at_own();
    };
    const auto scanned = scan ? std::find_if(terms.begin(), terms.end(), unmoved_refinement) - terms.begin() : -1;
    auto movable = [&](const Term& t) {
        if (!t.effect->shape || !t.effect->shape->variants) return false;
        if (!t.effect->shape->deferred) return true;
        return !hold_deferred && (!scan || &t - terms.data() == scanned || !t.effect->shape->at_own());
    };
    const bool refinement = !hold_deferred && std::any_of(terms.begin(), terms.end(), [&](const Term& t) {
        return movable(t) && t.effect->shape->deferred && (skip < 0 || &t != &terms[static_cast<size_t>(skip)]);
    });
    if (terms.size() - (skip >= 0 && skip < static_cast<int>(terms.size())) < 2 && !refinement) return best;
    // Two shapes move in turn until neither does (a few passes: each step is a joint refit).
    const auto shaped = std::count_if(terms.begin(), terms.end(), movable);
    for (int pass = 0, moved = 1; pass < (shaped >= 2 ? 3 : 1) && moved; ++pass) {
        moved = 0;
        for (size_t j = 0; j < terms.size(); ++j) {
            if (static_cast<int>(j) == skip) continue;
            if (!movable(terms[j])) continue;
            const std::vector<Effect>& variants = *terms[j].effect->shape->variants;
            auto at = static_cast<long>(std::find_if(variants.begin(), variants.end(), [&](const Effect& v) {
                                            return v.shape->chosen == terms[j].effect->shape->chosen;
                                        }) - variants.begin());
            if (terms[j].effect->shape->deferred && terms[j].effect->shape->at_own()) {
                // A refinement that has not moved is first scanned over every other value of its
                // grid, or over the values given (`scan`: where it fits best alone): its case
                // value (the factor acting at every film) may lie at the end of a flat stretch the
                // steps would not leave. The steps below then refine the best.
                std::vector<Term> best_terms;
                std::vector<char> best_flags;
                double best_penalised = best;
                long best_k = at;
                for (size_t k : scan ? *scan : refinement_scan(variants.size())) {
                    if (static_cast<long>(k) == at || k >= variants.size()) continue;
                    std::vector<Term> t = terms;
                    t[j].effect = &variants[k];
                    std::vector<char> fl = flags;
                    const double nll = refit_shapes_held(E, neutral, t, fl, opt, refit_flags, skip);
                    const double prior = 0.5 * (t[j].effect->shape->bic_penalty() - terms[j].effect->shape->bic_penalty());
                    if (nll + prior < best_penalised - 1e-6) {
                        best_penalised = nll + prior;
                        best_terms = std::move(t);
                        best_flags = std::move(fl);
                        best_k = static_cast<long>(k);
                    }
                }
                if (best_terms.empty()) continue;
                best = best_penalised - 0.5 * (best_terms[j].effect->shape->bic_penalty() -
                                               terms[j].effect->shape->bic_penalty());
                terms = std::move(best_terms);
                flags = std::move(best_flags);
                at = best_k;
                moved = 1;
            }
            for (int dir : {-1, +1}) {
                for (long k = at + dir; k >= 0 && k < static_cast<long>(variants.size()); k += dir) {
                    std::vector<Term> t = terms;
                    t[j].effect = &variants[static_cast<size_t>(k)];
                    std::vector<char> fl = flags;
                    const double nll = refit_shapes_held(E, neutral, t, fl, opt, refit_flags, skip);
                    // Leaving or reaching the case's own value changes what the shape costs.
                    const double prior = 0.5 * (t[j].effect->shape->bic_penalty() - terms[j].effect->shape->bic_penalty());
                    if (!(nll + prior < best - 1e-6)) break;
                    best = nll;
                    terms = std::move(t);
                    flags = std::move(fl);
                    at = k;
                    moved = 1;
                }
            }
        }
    }
    return best;
}

}  // namespace gearloss::diagnosis::detail
