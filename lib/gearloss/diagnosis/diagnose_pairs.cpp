// diagnose: two effects taken together when forward selection cannot reach them. Forward
// selection adds the best single effect first; two effects that partly cancel (a negative
// torque-sensor offset under a real drag) leave no single effect worth adding, and two that
// together imitate a third leave that third one as the best single. Every pair is screened
// on an additive surrogate of the first round's responses, the leading pairs refitted with
// the model, and a pair is taken only when it beats what forward selection can reach.
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>
#include <optional>
#include <random>

#include "gearloss/diagnosis/diagnose_select.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::diagnosis::detail {
namespace {

// The leading pairs of the surrogate's ranking refitted with the model before one is chosen.
// Eight: the surrogate misses what one member's heat does to the other through the oil
// temperature, and a pair it ranks seventh can lead once refitted (spur windage under a forced
// cooling: seventh on the surrogate, 16.7 better in ln L refitted, first by 10.8 in BIC).
constexpr size_t kPairsRefitted = 8;

struct PairFit {
    size_t a = 0, b = 0;
    double xa = 0, xb = 0, nll = kFailedNll;
};

// Two effects together approximated as the base plus each one's change, both responses built
// at the same base: exact for effects that only add to the recorded loss (artefacts, drags at
// a fixed oil temperature), first order where one's heat changes the other through the oil
// temperature. It costs no model evaluation; the pairs it ranks first are refitted with the model.
class PairSurrogate {
public:
    PairSurrogate(const Engine& E, const Response& a, const Response& b, const Pred& base, const Hypothesis& h)
        : E_(E), a_(a), b_(b), base_(base), flagged_(h.unstabilised) {}

    double nll(double xa, double xb, const std::vector<int>& idx) const {
        return score(idx, [&](int i, double& La, double& Ta, double& Lb, double& Tb) {
            a_.predict(xa, i, La, Ta);
            b_.predict(xb, i, Lb, Tb);
        });
    }

    // At knots of both responses: the model's own values, no interpolation (the screening of
    // every pair stays a few additions per point and knot pair).
    double nll_at_knots(size_t ka, size_t kb, const std::vector<int>& idx) const {
        const auto &la = a_.loss_at_knot(ka), &ta = a_.temp_at_knot(ka);
        const auto &lb = b_.loss_at_knot(kb), &tb = b_.temp_at_knot(kb);
        return score(idx, [&](int i, double& La, double& Ta, double& Lb, double& Tb) {
            La = la[i], Ta = ta[i], Lb = lb[i], Tb = tb[i];
        });
    }

    // The best knot pair (a form: its alternative knot only).
    PairFit grid(const std::vector<int>& idx) const {
        const auto knots = [](const Response& r) {
            std::vector<size_t> k;
            for (size_t j = r.discrete() ? r.knots().size() - 1 : 0; j < r.knots().size(); ++j) k.push_back(j);
            return k;
        };
        PairFit best;
        for (size_t ka : knots(a_))
            for (size_t kb : knots(b_)) {
                const double v = nll_at_knots(ka, kb, idx);
                if (v < best.nll) best = {0, 0, a_.knots()[ka], b_.knots()[kb], v};
            }
        return best;
    }

    // The best knot pair, then refined between the knots.
    PairFit minimise(const std::vector<int>& idx) const { return refine(grid(idx), idx); }

    // Coordinate minimisation (Brent) from a knot pair, between the neighbouring knots of each
    // continuous parameter; a form stays the alternative form (its only fitted value).
    PairFit refine(PairFit best, const std::vector<int>& idx) const {
        const auto bracket = [](const Response& r, double x) {
            const auto& k = r.knots();
            const size_t at = static_cast<size_t>(std::lower_bound(k.begin(), k.end(), x) - k.begin());
            return std::make_pair(k[at == 0 ? 0 : at - 1], k[std::min(at + 1, k.size() - 1)]);
        };
        for (int sweep = 0; sweep < 3; ++sweep) {
            const double before = best.nll;
            for (int axis = 0; axis < 2; ++axis) {
                const Response& r = axis == 0 ? a_ : b_;
                if (r.discrete()) continue;
                const auto [lo, hi] = bracket(r, axis == 0 ? best.xa : best.xb);
                std::uintmax_t iters = 40;
                const auto [x, fx] = boost::math::tools::brent_find_minima(
                    [&](double t) { return axis == 0 ? nll(t, best.xb, idx) : nll(best.xa, t, idx); }, lo, hi, 30,
                    iters);
                if (fx < best.nll) (axis == 0 ? best.xa : best.xb) = x, best.nll = fx;
            }
            if (before - best.nll < 1e-3) break;
        }
        return best;
    }

private:
    // The surrogate at point i: the base plus each effect's change.
    template <class Predict>
    double score(const std::vector<int>& idx, Predict&& predict) const {
        return score_points(E_.obs(), flagged_, idx, [&](int i, double& L, double& T) {
                   double La, Ta, Lb, Tb;
                   predict(i, La, Ta, Lb, Tb);
                   L = La + Lb - base_.loss[i];
                   T = Ta + Tb - base_.temp[i];
               }).nll;
    }

    const Engine& E_;
    const Response &a_, &b_;
    const Pred& base_;
    const std::vector<char>& flagged_;  // the base hypothesis' flagged points (outlives the surrogate)
};

// Whether a candidate can enter a pair: fitted, with a response, acting on these points.
bool pairable(const Effect& e, const Fit& f, const Response& r) {
    return e.kind != EffectKind::pointwise && f.failed.empty() && r.failed().empty() && !r.knots().empty() && !r.flat();
}

// Whether a fitted value sits at an end of its scan range [lo, hi] (within 0.1 % of the
// range, on a log scale for a factor) that is not the case's own value.
bool at_range_end(const Effect& e, double v, double lo, double hi) {
    auto coord = [&](double x) { return e.multiplicative && x > 0 ? std::log(x) : x; };
    const double span = coord(hi) - coord(lo);
    if (!(span > 0)) return false;
    const double tol = 1e-3 * span;
    return (coord(v) - coord(lo) < tol && lo != e.neutral) || (coord(hi) - coord(v) < tol && hi != e.neutral);
}

}  // namespace

bool select_pair(const Engine& E, const std::vector<Effect>& lib, const Hypothesis& neutral, const FirstRound& r,
                 const DiagnoseOptions& opt, Selection& S, std::vector<Term>& terms, std::vector<size_t>& lead_partners) {
    lead_partners.clear();
    if (opt.max_findings < 2 || r.order.empty()) return false;
    const size_t lead = r.order.front();
    const auto& all = E.all();
    const size_t N = n_observations(E, all);
    const double lnN = std::log(static_cast<double>(N));
    std::vector<size_t> eligible;
    for (size_t k = 0; k < lib.size(); ++k)
        if (pairable(lib[k], r.fits[k], r.responses[k])) eligible.push_back(k);
    const bool forward_stops = r.delta_bic[lead] < opt.bic_threshold;
    // Occam: a leading effect that leaves only noise is the explanation; no pair is sought.
    if (!forward_stops) {
        const Hypothesis& h = r.fits[lead].h;
        if (assess(E, E.predict_checked(h, all), h, 1, opt, opt.confidence_level).adequate) return false;
    }
    // Screen every pair on the surrogate.
    std::vector<PairFit> screened;
    for (size_t i = 0; i < eligible.size(); ++i)
        for (size_t j = i + 1; j < eligible.size(); ++j) {
            io::throw_if_interrupted();
            const size_t a = eligible[i], b = eligible[j];
            if (taken({{&lib[a], 0.0}}, lib[b])) continue;  // two forms of one axis, or an oil's copy of the other
            // Refined between the knots, every pair: on the knots alone a seal factor between two
            // of them left the pair of the truth (mixed-film rise + seal) 17th, 19 in ln L behind
            // its refined value and outside the pairs refitted with the model.
            PairFit p = PairSurrogate(E, r.responses[a], r.responses[b], r.base_pred, neutral).minimise(all);
            p.a = a, p.b = b;
            screened.push_back(p);
        }
    if (screened.empty()) return false;
    // Ranked by likelihood with the members' priors at their values (Effect::prior_penalty).
    const auto penalised = [&](const PairFit& p) {
        return p.nll + 0.5 * (lib[p.a].prior_penalty(p.xa) + lib[p.b].prior_penalty(p.xb));
    };
    const auto by_nll = [&](const PairFit& x, const PairFit& y) { return penalised(x) < penalised(y); };
    std::sort(screened.begin(), screened.end(), by_nll);
    for (const auto& p : screened)
        if ((p.a == lead || p.b == lead) && lead_partners.size() < 2) lead_partners.push_back(p.a == lead ? p.b : p.a);
    // What a pair costs in the information criteria: a parameter per member (a form too: the
    // choice of it), a member's profiled shape its prior over the grid (Effect::bic_penalty),
    // and the priors at the members' values.
    const auto cost = [&](const Effect& e, double value) {
        return std::max(lnN, e.bic_penalty(N)) + e.prior_penalty(value);
    };
    const auto terms_cost = [&](const std::vector<Term>& t) {
        return cost(*t[0].effect, t[0].value) + cost(*t[1].effect, t[1].value);
    };
    const auto refit = [&](const PairFit& p, std::vector<Term>& t) {
        t = {{&lib[p.a], p.xa}, {&lib[p.b], p.xb}};
        std::vector<char> none;
        return refit_jointly(E, neutral, t, none, opt, false, -1, true);
    };
    // The surrogate is first order where one member's heat changes the other through the oil
    // temperature (windage heating the oil that a forced cooling takes away: the surrogate put
    // that pair fifth, the model first, 12.3 ahead in 2 ln L). The leading pairs are refitted with the
    // model and ranked by their information criterion; each keeps its prediction, on which the
    // resamples compare them below.
    struct Refitted {
        std::vector<Term> terms;
        Pred pred;
        Hypothesis h;
        double criterion = std::numeric_limits<double>::infinity();
    };
    const size_t n_refitted = std::min<size_t>(screened.size(), kPairsRefitted);
    std::vector<Refitted> refitted(n_refitted);
    for (size_t c = 0; c < n_refitted; ++c) {
        io::throw_if_interrupted();
        Refitted& x = refitted[c];
        const double nll = refit(screened[c], x.terms);
        if (nll >= kFailedNll) continue;
        std::vector<char> none;
        x.h = with_terms(neutral, x.terms, none);
        x.pred = E.predict_checked(x.h, all);
        if (!x.pred.failure.empty()) continue;
        screened[c].xa = x.terms[0].value, screened[c].xb = x.terms[1].value, screened[c].nll = nll;
        x.criterion = 2.0 * nll + terms_cost(x.terms);
    }
    {
        std::vector<size_t> rank(n_refitted);
        std::iota(rank.begin(), rank.end(), size_t{0});
        std::stable_sort(rank.begin(), rank.end(),
                         [&](size_t x, size_t y) { return refitted[x].criterion < refitted[y].criterion; });
        std::vector<PairFit> head;
        std::vector<Refitted> heads;
        for (size_t c : rank) head.push_back(screened[c]), heads.push_back(std::move(refitted[c]));
        std::copy(head.begin(), head.end(), screened.begin());
        refitted = std::move(heads);
    }
    if (refitted.empty() || !std::isfinite(refitted.front().criterion)) return false;
    const PairFit& best = screened.front();
    const bool holds_lead = best.a == lead || best.b == lead;
    // Forward selection reaches a pair holding the leading single candidate: leave it to it.
    if (holds_lead && !forward_stops) return false;
    // The pair must promise at least the threshold for each of its two parameters.
    if (2.0 * (r.base_nll - best.nll) - cost(lib[best.a], best.xa) - cost(lib[best.b], best.xb) < 2.0 * opt.bic_threshold)
        return false;

    std::vector<Term> pair_terms = refitted.front().terms;
    const double nll_pair = best.nll;
    // A member held at an end of its range wants more than the physics allows: the two are
    // compensating each other (a viscosity five times the datasheet's against a negative
    // remainder), not two effects of credible size.
    for (int m = 0; m < 2; ++m) {
        std::vector<char> none;
        const Term& t = pair_terms[static_cast<size_t>(m)];
        const auto [lo, hi] = E.range(*t.effect, with_terms(neutral, pair_terms, none, m));
        if (at_range_end(*t.effect, t.value, lo, hi)) return false;
    }
    double nll_forward = r.base_nll;  // forward selection stops: it reaches the case alone (no parameter)
    double cost_forward = 0;
    if (!forward_stops) {
        // The best pair forward selection can reach: the leading candidate with its best partner.
        const auto q = std::find_if(screened.begin(), screened.end(),
                                    [&](const PairFit& p) { return p.a == lead || p.b == lead; });
        // (Refitted already when it is among the leading pairs.)
        const size_t at = static_cast<size_t>(q - screened.begin());
        std::vector<Term> q_terms;
        if (q == screened.end()) nll_forward = r.fits[lead].nll;
        else if (at < refitted.size() && std::isfinite(refitted[at].criterion))
            nll_forward = q->nll, q_terms = refitted[at].terms;
        else nll_forward = refit(*q, q_terms);
        cost_forward = q == screened.end() ? cost(lib[lead], r.fits[lead].value) : terms_cost(q_terms);
        if (nll_forward >= kFailedNll) return false;
    }
    const double margin = 2.0 * (nll_forward - nll_pair) - (terms_cost(pair_terms) - cost_forward);
    if (margin < opt.bic_threshold) return false;

    // Each member on top of the other: BIC, cross-validated gain, and the share of resamples
    // in which this pair beats the other leading pairs (their predictions as refitted on all points).
    std::vector<Finding> found;
    std::vector<size_t> contenders;
    for (size_t c = 0; c < std::min<size_t>(refitted.size(), 4); ++c)
        if (std::isfinite(refitted[c].criterion)) contenders.push_back(c);
    std::vector<int> wins(contenders.size(), 0);
    for (int bs = 0; bs < opt.bootstrap; ++bs) {
        io::throw_if_interrupted();
        std::mt19937_64 rng(opt.seed + 6151u * static_cast<unsigned>(bs) + 3u);
        std::uniform_int_distribution<int> pick(0, static_cast<int>(all.size()) - 1);
        std::vector<int> idx(all.size());
        for (auto& i : idx) i = pick(rng);
        size_t winner = 0;
        double low = kFailedNll;
        // Each contender as refitted on all points: its prediction scored on the resample.
        for (size_t c : contenders) {
            const PairFit& p = screened[c];
            const double v = E.score(refitted[c].h, refitted[c].pred, idx).nll +
                             0.5 * (lib[p.a].prior_penalty(p.xa) + lib[p.b].prior_penalty(p.xb));
            if (v < low) low = v, winner = c;
        }
        ++wins[winner];
    }
    double stability = static_cast<double>(wins[0]) / opt.bootstrap;
    for (int m = 0; m < 2; ++m) {
        const Effect& e = *pair_terms[static_cast<size_t>(m)].effect;
        std::vector<char> none;
        const Hypothesis others = with_terms(neutral, pair_terms, none, m);
        const Pred po = E.predict_checked(others, all);
        const double nll_o = E.score(others, po, all).nll;
        Response rm;
        const Fit fm = E.fit(e, others, &rm);
        if (!fm.failed.empty()) return false;
        const double dbm = delta_bic(nll_o, fm, N);
        const CvResult cv0 = cross_validate(E, nullptr, po, others), cvm = cross_validate(E, &rm, po, others);
        if (dbm < opt.bic_threshold || cv0.nll - cvm.nll < opt.cv_margin) return false;
        Finding f;
        f.effect = e.id;
        const Effect& partner = *pair_terms[static_cast<size_t>(1 - m)].effect;
        f.description = e.description + pair_clause(partner.id);
        f.parameter = {e.parameter, e.unit, pair_terms[static_cast<size_t>(m)].value, fm.uncertainty, e.form, e.case_form};
        f.delta_bic = dbm;
        f.cv_gain = cv0.nll - cvm.nll;
        // Near-tied pairs that keep the partner: the effect they swap in is an equivalent of this one.
        double shared = 0;
        for (size_t c = 1; c < contenders.size(); ++c) {
            const PairFit& p = screened[c];
            const Effect* pa = &lib[p.a];
            const Effect* pb = &lib[p.b];
            // (By name: a member refitted with its shape moved is one of its variants.)
            const Effect* other = pa->id == partner.id ? pb : pb->id == partner.id ? pa : nullptr;
            // As for a single effect: near-tied, or winning a quarter of the resamples.
            if (!other || (2.0 * (p.nll - best.nll) > opt.ambiguity_bic && !rival_in_resamples(stability, wins[c], opt)))
                continue;
            f.equivalent.push_back(other->id);
            shared += static_cast<double>(wins[c]) / opt.bootstrap;
            if (f.separating_measurement.empty())
                f.separating_measurement = separating_measurement(E.signature(e, others), E.signature(*other, others));
        }
        // The member's own share: the resamples won by a pair that holds it (with this partner or
        // another), as a single effect's is the share of resamples that choose it.
        double own = 0;
        for (size_t c = 0; c < contenders.size(); ++c)
            if (lib[screened[c].a].id == e.id || lib[screened[c].b].id == e.id) own += static_cast<double>(wins[c]) / opt.bootstrap;
        f.stability = own;
        f.mechanism_stability = own;
        if (own < opt.stability_min && (f.equivalent.empty() || own + shared < 0.8)) {
            // Not named, but said: the pair fits far better than any single effect or the pair
            // forward selection reaches, and only the resamples cannot tell it from another.
            std::vector<std::pair<std::string, int>> others;
            for (size_t c = 1; c < contenders.size(); ++c)
                others.emplace_back(lib[screened[c].a].id + " with " + lib[screened[c].b].id, wins[c]);
            const std::string rivals = resample_shares(others, opt);
            S.unsettled = fmt::format(
                "{} with {} fitted together are better than {} by a delta BIC of {:.1f}, but not named: they win "
                "{:.0f} % of {} resamples{}{}",
                pair_terms[0].effect->id, pair_terms[1].effect->id,
                forward_stops ? std::string("the case without an effect") : lib[lead].id + " with its best partner",
                margin, 100.0 * stability, opt.bootstrap, rivals.empty() ? "" : ", against ", rivals);
            return false;
        }
        record_fit(f, E, po, others, fm.h, cv0, cvm);
        found.push_back(std::move(f));
    }
    if (found[1].delta_bic > found[0].delta_bic) std::swap(found[0], found[1]);
    for (auto& f : found) S.findings.push_back(std::move(f));
    S.warnings.push_back(fmt::format(
        "{} and {} were fitted as a pair: together better than {} by a BIC of {:.1f} (an effect fitted alone cannot "
        "reach them: they partly cancel, or another effect imitates their sum)",
        pair_terms[0].effect->id, pair_terms[1].effect->id,
        forward_stops ? std::string("the case without an effect") : lib[lead].id + " with its best partner", margin));
    terms = pair_terms;
    return true;
}

}  // namespace gearloss::diagnosis::detail
