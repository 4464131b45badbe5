// diagnose: the response of the recorded points to one parameter (fits on any subset without
// model evaluations), K-fold cross-validation, and the unstabilised-test candidate.
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "gearloss/diagnosis/diagnose_internal.hpp"

namespace gearloss::diagnosis::detail {

Response::Response(const Engine& E, const Effect& e, const Hypothesis& base)
    : Response(E, e, base, E.scan_values(e, base)) {}

Response::Response(const Engine& E, const Effect& e, const Hypothesis& base, const std::vector<double>& grid)
    : E_(&E), e_(&e), base_(std::make_shared<const Hypothesis>(base)) {
    std::vector<Pred> pred = E.predict_many(grid.size(), [&](size_t k) {
        Hypothesis h = base;
        e.apply(h, grid[k]);
        return h;
    });
    // The knots that can be evaluated, contiguous around the value of the case.
    size_t c = 0;
    for (size_t k = 0; k < grid.size(); ++k)
        if (std::abs(grid[k] - e.neutral) < std::abs(grid[c] - e.neutral)) c = k;
    if (!pred[c].failure.empty()) {
        failed_ = fmt::format("{} = {:.4g}: {}", e.parameter, grid[c], pred[c].failure);
        return;
    }
    if (e.discrete()) {
        // A form: the case's (knot 0) and the alternative (knot 1), nothing in between.
        const size_t alt = c == 0 ? 1 : 0;
        if (!pred[alt].failure.empty()) {
            failed_ = fmt::format("{} = {}: {}", e.parameter, e.form, pred[alt].failure);
            return;
        }
        discrete_ = true;
    }
    size_t a = c, b = c;
    if (discrete_) a = 0, b = grid.size() - 1;
    while (a > 0 && pred[a - 1].failure.empty()) --a;
    while (b + 1 < grid.size() && pred[b + 1].failure.empty()) ++b;
    if (!discrete_ && b - a + 1 < 4) {
        if (a == 0 && b + 1 == grid.size()) {
            failed_ = fmt::format("{}: fewer than 4 distinct values to scan within its bounds", e.parameter);
            return;
        }
        const size_t bad = a > 0 ? a - 1 : b + 1;
        failed_ = fmt::format("{} = {:.4g}: {}", e.parameter, grid[bad], pred[bad].failure);
        return;
    }
    if (a > 0 || b + 1 < grid.size()) {
        const size_t bad = a > 0 ? a - 1 : b + 1;
        narrowed_ = fmt::format("{} = {:.4g}: {}", e.parameter, grid[bad], pred[bad].failure);
    }
    for (size_t k = a; k <= b; ++k) {
        knots_.push_back(grid[k]);
        loss_.push_back(std::move(pred[k].loss));
        temp_.push_back(std::move(pred[k].temp));
    }
    flat_ = true;
    for (size_t k = 0; k < knots_.size() && flat_; ++k)
        for (int i : E.all()) {
            const auto& o = E.obs()[i];
            if (std::abs(loss_[k][i] - loss_[0][i]) > 1e-9 * o.scale ||
                (o.T_evidence && std::abs(temp_[k][i] - temp_[0][i]) > 1e-9)) {
                flat_ = false;
                break;
            }
        }
    build();
}

void Response::build() {
    if (discrete_) return;  // no interpolation between two forms
    const size_t n = E_->obs().size();
    iloss_.clear();
    itemp_.clear();
    iloss_.reserve(n);
    itemp_.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        std::vector<double> x = knots_, x2 = knots_, yl(knots_.size()), yt(knots_.size());
        for (size_t k = 0; k < knots_.size(); ++k) {
            yl[k] = loss_[k][i];
            yt[k] = temp_[k][i];
        }
        iloss_.emplace_back(std::move(x), std::move(yl));
        itemp_.emplace_back(std::move(x2), std::move(yt));
    }
}

void Response::predict(double x, int i, double& loss, double& temp) const {
    if (discrete_) {
        const size_t k = x >= 0.5 * (knots_.front() + knots_.back()) ? knots_.size() - 1 : 0;
        loss = loss_[k][i];
        temp = temp_[k][i];
        return;
    }
    x = std::clamp(x, knots_.front(), knots_.back());
    loss = iloss_[i](x);
    temp = itemp_[i](x);
}

double Response::nll(double x, const std::vector<int>& idx) const {
    return score_points(E_->obs(), base_->unstabilised, idx, [&](int i, double& L, double& T) { predict(x, i, L, T); }).nll;
}

std::pair<double, double> Response::minimise(const std::vector<int>& idx) const {
    if (knots_.empty()) return {std::nan(""), kFailedNll};  // a response that could not be built
    size_t best = 0;
    std::vector<double> v(knots_.size());
    for (size_t k = 0; k < knots_.size(); ++k) {
        v[k] = nll(knots_[k], idx);
        if (v[k] < v[best]) best = k;
    }
    // A form candidate is the alternative form itself (worse than the case's: a negative gain).
    if (discrete_) return {knots_.back(), v.back()};
    const double lo = knots_[best == 0 ? 0 : best - 1], hi = knots_[std::min(best + 1, knots_.size() - 1)];
    std::uintmax_t iters = 50;
    const auto [x, fx] = boost::math::tools::brent_find_minima([&](double t) { return nll(t, idx); }, lo, hi, 30, iters);
    return fx <= v[best] ? std::make_pair(x, fx) : std::make_pair(knots_[best], v[best]);
}

void Response::refine(double x) {
    if (discrete_) return;
    for (double k : knots_)
        if (std::abs(k - x) <= 1e-7 * (std::abs(k) + (knots_.back() - knots_.front()))) return;
    Hypothesis h = *base_;
    e_->apply(h, x);
    Pred p = std::move(E_->predict_many(1, [&](size_t) { return h; })[0]);
    io::throw_if_interrupted();
    if (!p.failure.empty()) {
        failed_ = fmt::format("{} = {:.4g}: {}", e_->parameter, x, p.failure);
        return;
    }
    const size_t at = static_cast<size_t>(std::upper_bound(knots_.begin(), knots_.end(), x) - knots_.begin());
    knots_.insert(knots_.begin() + static_cast<long>(at), x);
    loss_.insert(loss_.begin() + static_cast<long>(at), std::move(p.loss));
    temp_.insert(temp_.begin() + static_cast<long>(at), std::move(p.temp));
    build();
}

void profile_shapes(const Engine& E, std::vector<Effect>& lib, const Hypothesis& base) {
    for (auto& e : lib) {
        if (!e.shape || e.shape->grid.empty() || std::isfinite(e.shape->chosen)) continue;
        auto variants = std::make_shared<std::vector<Effect>>();
        for (double v : e.shape->grid) variants->push_back(with_shape(e, v));
        for (auto& x : *variants) x.shape->variants = variants.get();
        // The case's own value first: it is kept unless another fits better (a deferred shape
        // keeps it until the effect is named).
        const auto& grid = e.shape->grid;
        const size_t own = static_cast<size_t>(std::find(grid.begin(), grid.end(), e.shape->own) - grid.begin());
        size_t chosen = own;
        double best = kFailedNll;
        for (size_t n = 0; n < (e.shape->deferred ? 0 : grid.size()); ++n) {
            const size_t k = n == 0 ? own : n <= own ? n - 1 : n;  // own, then the others in order
            io::throw_if_interrupted();
            const Fit f = E.fit((*variants)[k], base, nullptr);
            // The likelihood with the prior of the shape (its own value weighs half).
            const double penalised = f.nll + 0.5 * (*variants)[k].shape->bic_penalty();
            if (f.failed.empty() && penalised < best - 1e-9) best = penalised, chosen = k;
        }
        e = (*variants)[chosen];
        e.shape->variants_owner = std::move(variants);
    }
}

CvResult cross_validate(const Engine& E, const Response* r, const Pred& base_pred, const Hypothesis& base) {
    const auto& all = E.all();
    const size_t n = all.size();
    const size_t K = std::min<size_t>(n, 10);
    // Folds interleaved in row order: each holds points from the whole campaign.
    std::vector<int> by_row(all);
    std::sort(by_row.begin(), by_row.end(), [&](int a, int b) { return E.obs()[a].row < E.obs()[b].row; });
    std::vector<double> eP(n, 0), eL(n, 0), eT(n, 0);
    std::vector<char> hasT(n, 0);
    for (size_t f = 0; f < K; ++f) {
        std::vector<int> train, test;
        for (size_t q = 0; q < n; ++q) (q % K == f ? test : train).push_back(by_row[q]);
        const double x = r ? r->minimise(train).first : 0.0;
        for (int j : test) {
            const auto& o = E.obs()[j];
            double L = base_pred.loss[j], T = base_pred.temp[j];
            if (r) r->predict(x, j, L, T);
            eL[j] = o.loss - L;
            eP[j] = eL[j] / o.scale;
            const bool flagged = !base.unstabilised.empty() && base.unstabilised[j];
            if (o.T_evidence && !flagged) {
                eT[j] = o.T_oil - T;
                hasT[j] = 1;
            }
        }
    }
    CvResult res;
    double rP = 0, rT = 0;
    int nT = 0, nT_all = 0;
    for (size_t j = 0; j < n; ++j) {
        rP += eP[j] * eP[j];
        res.rmse_loss += eL[j] * eL[j];
        if (hasT[j]) {
            rT += eT[j] * eT[j];
            ++nT;
        }
        nT_all += E.obs()[j].T_evidence;
    }
    // Flagged points keep their (zero) residual in the count so both sides compare like with like.
    res.nll = profiled(rP, static_cast<int>(n), kFloorLoss) + profiled(rT, nT_all, kFloorTemp);
    res.rmse_loss = std::sqrt(res.rmse_loss / n);
    res.rmse_temp = nT ? std::sqrt(rT / nT) : 0.0;
    return res;
}

// Greedy: flag the points whose oil is furthest from the model until the BIC stops improving.
// A point is eligible only when its recorded oil temperature also disagrees with the heat
// balance of its *measured* loss: a real loss at one point heats the oil by what the heat
// path needs, and must not be explained away as a test that was still warming or cooling.
Fit Engine::fit_unstabilised(const Hypothesis& base, const std::vector<int>& idx, double loss_noise) const {
    Fit f;
    f.h = base;
    Pred p;
    predict(base, idx, p, 0);
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
    std::vector<std::pair<double, int>> resid;
    std::vector<double> lossres;
    for (int i : uniq) {
        lossres.push_back((obs_[i].loss - p.loss[i]) / obs_[i].scale);
        if (obs_[i].T_evidence && (base.unstabilised.empty() || !base.unstabilised[i]))
            resid.push_back({obs_[i].T_oil - p.temp[i], i});
    }
    if (resid.size() < 4) return f;
    std::vector<double> v;
    for (const auto& r : resid) v.push_back(r.first);
    const auto [med, scale] = robust_centre_scale(v, 2.0 * kFloorTemp);
    const double sP = loss_noise > 0 ? loss_noise : robust_centre_scale(lossres, 0.01).second;
    apply(base, 0);
    std::vector<std::pair<double, int>> cold;
    for (const auto& [r, i] : resid) {
        if (std::abs(r - med) / scale <= 4.0) continue;
        const Obs& o = obs_[i];
        const double T_true = (o.torque - base.art.torque_offset) / base.art.torque_gain;
        const double heat = o.loss - (o.torque - T_true) * o.w;  // what the rig really dissipated
        const double gap = heat - model(0, o.oil).heat_flow(o.T_oil, o.ambient, o.w);
        if (std::isfinite(gap) && std::abs(gap) <= std::max(4.0 * sP, 0.03) * o.scale) continue;
        cold.push_back({-std::abs(r - med), i});
    }
    std::sort(cold.begin(), cold.end());
    // Each flagged point costs a parameter (ln N) and the choice of which point (ln n).
    const double penalty = std::log(static_cast<double>(idx.size() + n_T_)) + std::log(static_cast<double>(uniq.size()));
    Hypothesis h = base;
    if (h.unstabilised.empty()) h.unstabilised.assign(obs_.size(), 0);
    double best_bic = 2 * f.nll;
    const size_t max_m = std::min<size_t>(cold.size(), std::max<size_t>(1, uniq.size() / 4));
    for (size_t k = 1; k <= max_m; ++k) {
        h.unstabilised[cold[k - 1].second] = 1;
        const double nll_m = score(h, p, idx).nll;
        const double bic = 2 * nll_m + static_cast<double>(k) * penalty;
        if (bic < best_bic) {
            best_bic = bic;
            f.nll = nll_m;
            f.k = static_cast<int>(k);
            f.extra_penalty = static_cast<double>(k) * std::log(static_cast<double>(uniq.size()));
            f.h = h;
        }
    }
    f.value = f.k;
    return f;
}

}  // namespace gearloss::diagnosis::detail
