// diagnose: which effects, jointly. Forward selection (BIC, cross-validated gain, bootstrap
// stability), each addition followed by a joint refit of every accepted parameter and a
// test of whether each earlier effect is still needed (backward elimination).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>
#include <random>

#include "gearloss/diagnosis/diagnose_select.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::diagnosis::detail {

Hypothesis with_terms(const Hypothesis& neutral, const std::vector<Term>& terms, const std::vector<char>& flags,
                      int skip) {
    Hypothesis h = neutral;
    for (size_t j = 0; j < terms.size(); ++j)
        if (static_cast<int>(j) != skip && terms[j].effect->apply) terms[j].effect->apply(h, terms[j].value);
    if (!flags.empty() && (skip < 0 || terms[static_cast<size_t>(skip)].effect->kind != EffectKind::pointwise)) {
        bool any = false;
        for (const auto& t : terms) any |= t.effect->kind == EffectKind::pointwise;
        if (any) h.unstabilised = flags;
    }
    return h;
}

// Whether e is already among the terms or excluded by one of them: another form of the same
// axis, or the same effect for every oil and for one (per-oil copies of different oils
// coexist); `skip`: a term being replaced.
bool taken(const std::vector<Term>& terms, const Effect& e, int skip) {
    for (size_t j = 0; j < terms.size(); ++j) {
        if (static_cast<int>(j) == skip) continue;
        const Effect& t = *terms[j].effect;
        if (&t == &e) return true;
        if (!e.group.empty() && t.group == e.group && (t.oil < 0 || e.oil < 0 || t.oil == e.oil)) return true;
    }
    return false;
}

void record_fit(Finding& f, const Engine& E, const Pred& pb, const Hypothesis& without, const Hypothesis& h,
                const CvResult& cv_without, const CvResult& cv_with) {
    const ChannelStats sb = channel_rmse(E, pb, without);
    const ChannelStats sa = channel_rmse(E, E.predict_checked(h, E.all()), h);
    f.rmse_before = sb.rmse_loss;
    f.rmse_after = sa.rmse_loss;
    f.cv_rmse_before = cv_without.rmse_loss;
    f.cv_rmse_after = cv_with.rmse_loss;
    f.temp_rmse_before = sb.rmse_temp;
    f.temp_rmse_after = sa.rmse_temp;
}

bool rival_in_resamples(double leader_stability, int rival_wins, const DiagnoseOptions& opt) {
    return leader_stability < opt.stability_min && rival_wins >= 0.25 * opt.bootstrap;
}

std::string resample_shares(const std::vector<std::pair<std::string, int>>& rivals, const DiagnoseOptions& opt) {
    std::string s;
    for (const auto& [name, wins] : rivals)
        if (wins > 0) s += fmt::format("{}{} in {:.0f} %", s.empty() ? "" : ", ", name, 100.0 * wins / opt.bootstrap);
    return s;
}

std::string pair_clause(const std::string& partner) {
    return "; found together with " + partner + ": neither alone accounts for the mismatch, the two fitted jointly do";
}

namespace {

// A finding named as a pair with `dropped` no longer says it was found with it: the pair's
// clause names who took its place.
void forget_partner(std::vector<Finding>& findings, const std::string& dropped, const std::string& by) {
    const std::string clause = pair_clause(dropped);
    for (auto& f : findings)
        if (const auto at = f.description.find(clause); at != std::string::npos)
            f.description.replace(at, clause.size(),
                                  "; found first as a pair with " + dropped + ", which " + by + " made unnecessary");
}

// How many of a refinement's values, the best alone, are scanned beside each candidate.
constexpr size_t kRefinementLeads = 3;

int parameters_of(const std::vector<Term>& terms, const std::vector<char>& flags) {
    int k = 0;
    for (const auto& t : terms)
        k += t.effect->kind == EffectKind::pointwise ? static_cast<int>(std::count(flags.begin(), flags.end(), 1))
                                                   : t.effect->fitted_parameters();
    return k;
}

// Parameters of the laws (the flagged points excluded: they only remove their own temperature
// evidence, which the adequacy test does not count; a published form has none).
int law_parameters(const std::vector<Term>& terms) {
    int k = 0;
    for (const auto& t : terms)
        if (t.effect->kind != EffectKind::pointwise) k += t.effect->fitted_parameters();
    return k;
}

// Exchange: an earlier effect, chosen when it stood alone, may have been a substitute that
// absorbed part of a later one (windage taking churning's share). Each earlier effect is
// replaced in turn by the first round's strong alternatives and everything refitted jointly;
// a replacement with a clearly better likelihood (same number of parameters: > 1 nat, i.e.
// BIC better by > 2) is taken, and its finding carries its own evidence on top of the others.
double exchange(const Engine& E, const std::vector<Effect>& lib, const Hypothesis& neutral, std::vector<Term>& terms,
                std::vector<char>& flags, double nll_full, Selection& S, const DiagnoseOptions& opt) {
    const size_t N = n_observations(E, E.all());
    for (size_t j = 0; j + 1 < terms.size(); ++j) {
        if (terms[j].effect->kind == EffectKind::pointwise) continue;
        const Effect* best = nullptr;
        double best_nll = kFailedNll;
        std::vector<Term> best_terms;
        std::vector<char> best_flags;
        // The BIC of the swap: a replacement with a parameter more than the one it replaces (a
        // scale factor for a form) pays for it, and each for its prior at its value.
        auto penalty = [&](const Term& t) { return t.effect->bic_penalty(N, t.value); };
        double best_bic = 2.0 * (nll_full - 1.0);
        int tried = 0;
        for (const auto& c : S.candidates) {
            if (tried >= 4 || !c.rejected.empty() || c.delta_bic < 0.5 * opt.bic_threshold) continue;
            const auto it = std::find_if(lib.begin(), lib.end(), [&](const Effect& x) { return x.id == c.effect; });
            if (it == lib.end() || it->kind == EffectKind::pointwise) continue;
            if (&*it == terms[j].effect || taken(terms, *it, static_cast<int>(j))) continue;  // itself, or excluded
            ++tried;
            std::vector<Term> swapped = terms;
            swapped[j] = {&*it, c.value};
            std::vector<char> fl = flags;
            const double nll = refit_jointly(E, neutral, swapped, fl, opt, false, -1, true);
            // The candidate as the refit left its shape.
            const double bic = 2.0 * nll + penalty(swapped[j]) - penalty(terms[j]);
            if (bic < best_bic) {
                best_bic = bic;
                best_nll = nll;
                best = &*it;
                best_terms = swapped;
                best_flags = fl;
            }
        }
        if (!best) continue;
        const std::string old = terms[j].effect->id;
        const double gain = nll_full - best_nll;
        // The exchanged finding's evidence, on top of the other accepted effects.
        const Hypothesis others = with_terms(neutral, best_terms, best_flags, static_cast<int>(j));
        Pred po = std::move(E.predict_many(1, [&](size_t) { return others; })[0]);
        io::throw_if_interrupted();
        if (!po.failure.empty()) continue;
        const double nll_o = E.score(others, po, E.all()).nll;
        Response rc, rj;
        const Fit fc = E.fit(*best, others, &rc);
        if (!fc.failed.empty()) continue;  // cannot be evaluated on its own on top of the others: keep the old one
        const Effect* replaced = nullptr;
        for (const auto& x : lib)
            if (x.id == old) replaced = &x;
        if (replaced) E.fit(*replaced, others, &rj);
        terms = best_terms;
        flags = best_flags;
        nll_full = best_nll;
        const CvResult cv0 = cross_validate(E, nullptr, po, others), cvc = cross_validate(E, &rc, po, others);
        int wins = 0;
        for (int b = 0; b < opt.bootstrap; ++b) {
            std::mt19937_64 rng(opt.seed + 31u * static_cast<unsigned>(b) + 7u);
            std::uniform_int_distribution<int> pick(0, static_cast<int>(E.all().size()) - 1);
            std::vector<int> idx(E.all().size());
            for (auto& i : idx) i = pick(rng);
            wins += rj.failed().empty() && !rj.knots().empty() ? rc.minimise(idx).second < rj.minimise(idx).second : 1;
        }
        for (auto& f : S.findings) {
            if (f.effect != old) continue;
            f.effect = best->id;
            f.description = best->description + "; chosen over " + old + " when fitted jointly with the other findings";
            f.parameter = {best->parameter, best->unit, fc.value, fc.uncertainty, best->form, best->case_form};
            f.delta_bic = delta_bic(nll_o, fc, N);
            f.cv_gain = cv0.nll - cvc.nll;
            f.stability = static_cast<double>(wins) / opt.bootstrap;
            f.mechanism_stability = f.stability;
            record_fit(f, E, po, others, fc.h, cv0, cvc);
            f.equivalent.clear();
            f.separating_measurement.clear();
        }
        forget_partner(S.findings, old, best->id);
        S.warnings.push_back(
            fmt::format("{} replaced {} in the joint fit (log-likelihood better by {:.1f})", best->id, old, gain));
    }
    return nll_full;
}

}  // namespace

Selection select_effects(const Engine& E, const std::vector<Effect>& lib, const Hypothesis& neutral,
                         const DiagnoseOptions& opt) {
    Selection S;
    const auto& all = E.all();
    const size_t N = n_observations(E, all);
    std::vector<Term> terms;
    std::vector<char> flags;
    Hypothesis base = neutral;
    auto report = [&](const std::string& what) {
        if (opt.progress) opt.progress(what);
    };
    std::vector<size_t> lead_partners;  // the first round's leader's best partners (select_pair)
    bool refinement_tried = false;      // a finding's refinement was scanned beside the candidates
    // The first round's responses and delta BIC of the model forms: a form far worse than the
    // case's there is screened in later rounds on an additive surrogate (what it changed at
    // each point added to the round's base prediction) instead of a model evaluation, which
    // for a form such as the local thermal EHL costs as much as all other candidates together.
    std::vector<Response> form_response(lib.size());
    std::vector<double> form_dbic(lib.size(), 0.0);
    auto screened_out = [&](size_t k, const Pred& pb, double nll_base) {
        const Response& R = form_response[k];
        if (!lib[k].discrete() || !R.discrete() || R.knots().size() != 2 || !(form_dbic[k] < 0)) return false;
        const size_t c = std::abs(R.knots()[0] - lib[k].neutral) <= std::abs(R.knots()[1] - lib[k].neutral) ? 0 : 1;
        Pred sp = pb;
        for (int i : all) {
            sp.loss[i] += R.loss_at_knot(1 - c)[i] - R.loss_at_knot(c)[i];
            sp.temp[i] += R.temp_at_knot(1 - c)[i] - R.temp_at_knot(c)[i];
            if (!std::isfinite(sp.loss[i]) || !std::isfinite(sp.temp[i])) return false;
        }
        Fit f;
        f.k = 0;
        f.nll = E.score(base, sp, all).nll;
        // Generous for the surrogate's error: half of what the form changed on its own.
        return delta_bic(nll_base, f, N) < -(opt.bic_threshold + 0.5 * std::abs(form_dbic[k]));
    };
    for (int round = 0; round < opt.max_findings; ++round) {
        const Pred pb = E.predict_checked(base, all);
        const double nll_base = E.score(base, pb, all).nll;
        std::vector<Fit> fits(lib.size());
        std::vector<Response> resp(lib.size());
        std::vector<double> dbic(lib.size(), kRejectedBic);
        // A candidate judged on top of the accepted effects refitted with it: those values.
        std::vector<std::vector<Term>> refitted(lib.size());
        for (size_t k = 0; k < lib.size(); ++k) {
            io::throw_if_interrupted();
            if (taken(terms, lib[k])) continue;
            if (round > 0 && screened_out(k, pb, nll_base)) {
                fits[k].failed = "far worse than the case's form in the first round and on this round's surrogate";
                fits[k].value = std::nan("");
                continue;
            }
            report(fmt::format("diagnose: finding {}: candidate {} of {} ({})", round + 1, k + 1, lib.size(), lib[k].id));
            fits[k] = lib[k].kind == EffectKind::pointwise ? E.fit_unstabilised(base, all, opt.loss_uncertainty)
                                                           : E.fit(lib[k], base, &resp[k]);
            if (fits[k].failed.empty() && lib[k].kind != EffectKind::pointwise && resp[k].flat())
                fits[k].failed = "not applicable: it changes neither the loss nor the oil temperature at these points";
            if (round == 0 && !resp[k].narrowed().empty())
                S.warnings.push_back(fmt::format("candidate {} scanned only where the model can be evaluated; beyond: {}",
                                                 lib[k].id, resp[k].narrowed()));
            if (fits[k].failed.empty()) dbic[k] = delta_bic(nll_base, fits[k], N);
            else fits[k].value = std::nan("");
        }
        std::vector<size_t> order(lib.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return dbic[a] > dbic[b]; });
        // Beyond the first effect, the leading candidates are fitted jointly with the accepted
        // ones: an effect fitted alone absorbs part of a second one (mesh friction taking some
        // windage), which a candidate held against it cannot win back. Each is then judged on
        // top of the refitted others (its response, cross-validation and resamples).
        if (!terms.empty()) {
            // The leaders here, and in the second round the first leader's best partners on the
            // pair screening: an effect the first one partly cancels shows little on top of it.
            std::vector<size_t> joint_candidates(order.begin(), order.begin() + std::min<size_t>(order.size(), 4));
            // A finding with a refinement (a friction factor that may act on thin films only) is
            // refined beside each law of the library: the partner its refined form leaves room
            // for shows little on top of its first form. In the first round after it is named
            // only: later rounds hold the refinement beside a candidate (each scan is a series of
            // joint refits; on the spur box the refinement named second tripled the time).
            const bool refinable = !refinement_tried && std::any_of(terms.begin(), terms.end(), [](const Term& t) {
                return t.effect->shape && t.effect->shape->deferred && t.effect->shape->variants;
            });
            refinement_tried = refinement_tried || refinable;
            // Beside each, the refinement is scanned where it fits best alone (three of the nine
            // values of its full scan) and stepped from the best of those.
            const std::vector<size_t> leads =
                refinable ? refinement_leads(E, neutral, terms, flags, opt, kRefinementLeads) : std::vector<size_t>{};
            // (The six leading laws beyond those already here: each such fit scans the refinement.)
            for (size_t r = 0, added = 0; refinable && r < order.size() && added < 6; ++r) {
                const size_t k = order[r];
                if (std::find(joint_candidates.begin(), joint_candidates.end(), k) == joint_candidates.end() &&
                    dbic[k] > -opt.bic_threshold && !lib[k].discrete() && lib[k].kind != EffectKind::pointwise &&
                    !taken(terms, lib[k]))
                    joint_candidates.push_back(k), ++added;
            }
            if (round == 1)
                for (size_t k : lead_partners)
                    if (std::find(joint_candidates.begin(), joint_candidates.end(), k) == joint_candidates.end() &&
                        !taken(terms, lib[k]))
                        joint_candidates.push_back(k);
            for (size_t k : joint_candidates) {
                if ((dbic[k] <= 0 && round != 1 && !refinable) || dbic[k] <= kRejectedBic ||
                    lib[k].kind == EffectKind::pointwise)
                    continue;
                report(fmt::format("diagnose: finding {}: {} fitted jointly with {} accepted", round + 1, lib[k].id,
                                   terms.size()));
                std::vector<Term> joint = terms;
                joint.push_back({&lib[k], fits[k].value});
                std::vector<char> fl = flags;
                if (refit_jointly(E, neutral, joint, fl, opt, false, -1, !refinable, refinable ? &leads : nullptr) >=
                    kFailedNll)
                    continue;
                const Hypothesis others = with_terms(neutral, joint, fl, static_cast<int>(joint.size() - 1));
                Response rk;
                // With the shape the joint refit gave it (it moves with the others).
                Fit fk = E.fit(*joint.back().effect, others, &rk);
                if (!fk.failed.empty()) continue;
                // A refinement of a finding moved beside the candidate is paid by the candidate, and
                // so is what the findings' priors say of the values the joint refit gave them.
                for (size_t j = 0; j + 1 < joint.size(); ++j) {
                    if (joint[j].effect->shape && joint[j].effect->shape->deferred)
                        fk.extra_penalty += joint[j].effect->shape_penalty() - terms[j].effect->shape_penalty();
                    fk.extra_penalty += joint[j].effect->prior_penalty(joint[j].value) -
                                        terms[j].effect->prior_penalty(terms[j].value);
                }
                const double dk = delta_bic(nll_base, fk, N);
                if (dk > dbic[k]) {
                    dbic[k] = dk;
                    joint.back().value = fk.value;
                    fits[k] = std::move(fk);
                    resp[k] = std::move(rk);
                    refitted[k] = std::move(joint);
                }
            }
            std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return dbic[a] > dbic[b]; });
        }
        if (round == 0) {
            for (size_t k = 0; k < lib.size(); ++k)
                if (lib[k].discrete() && fits[k].failed.empty()) form_response[k] = resp[k], form_dbic[k] = dbic[k];
            for (size_t k : order) S.candidates.push_back({lib[k].id, fits[k].value, dbic[k], fits[k].failed});
            report("diagnose: pairs of candidates");
            if (select_pair(E, lib, neutral, {fits, resp, dbic, order, pb, nll_base}, opt, S, terms, lead_partners)) {
                base = with_terms(neutral, terms, flags);
                ++round;  // two findings: the next round looks for a third
                continue;
            }
        }
        // Candidates over the BIC threshold, gated by cross-validation in BIC order.
        const CvResult cv0 = cross_validate(E, nullptr, pb, base);
        int chosen = -1;
        CvResult cv_chosen;
        for (size_t r = 0; r < std::min<size_t>(order.size(), 3); ++r) {
            const size_t k = order[r];
            if (dbic[k] < opt.bic_threshold) break;
            // The pointwise candidate has no response: its cross-validated gain is its BIC gain's.
            const CvResult cv = lib[k].kind == EffectKind::pointwise
                                    ? CvResult{cv0.nll - 0.5 * dbic[k], cv0.rmse_loss, cv0.rmse_temp}
                                    : cross_validate(E, &resp[k], pb, base);
            if (cv0.nll - cv.nll >= opt.cv_margin) {
                chosen = static_cast<int>(k);
                cv_chosen = cv;
                break;
            }
        }
        if (chosen < 0) break;
        // Stability: the leading candidates refitted on bootstrap resamples through their responses.
        std::vector<size_t> contenders;
        for (size_t r = 0; r < std::min<size_t>(order.size(), 4); ++r)
            if (dbic[order[r]] > 0) contenders.push_back(order[r]);
        std::vector<int> wins(lib.size(), 0);
        for (int b = 0; b < opt.bootstrap; ++b) {
            io::throw_if_interrupted();
            std::mt19937_64 rng(opt.seed + 7919u * static_cast<unsigned>(b) + 104729u * static_cast<unsigned>(round));
            std::uniform_int_distribution<int> pick(0, static_cast<int>(all.size()) - 1);
            std::vector<int> idx(all.size());
            for (auto& i : idx) i = pick(rng);
            const double nb = E.score(base, pb, idx).nll;
            const size_t Nb = n_observations(E, idx);
            int winner = -1;
            double best = opt.bic_threshold;
            for (size_t k : contenders) {
                Fit f;
                if (lib[k].kind == EffectKind::pointwise) f = E.fit_unstabilised(base, idx, opt.loss_uncertainty);
                else {
                    // The effect whose response this is (its shape as the joint refit left it); its
                    // costs beyond k ln N (shape, prior) as on all points.
                    const Effect& ek = refitted[k].empty() ? lib[k] : *refitted[k].back().effect;
                    f.k = ek.bic_parameters();
                    f.extra_penalty = fits[k].extra_penalty;
                    f.nll = resp[k].minimise(idx).second;
                }
                if (!f.failed.empty()) continue;
                const double db = delta_bic(nb, f, Nb);
                if (db > best) {
                    best = db;
                    winner = static_cast<int>(k);
                }
            }
            if (winner >= 0) ++wins[winner];
        }
        // A lead within the ambiguity margin says nothing; the resamples may: a near-tied
        // candidate chosen in as many of them as a confident name needs is named, the leader in
        // BIC stays its equivalent (bootstrap selection frequencies, Buckland et al. 1997).
        for (size_t k : contenders)
            if (static_cast<int>(k) != chosen && wins[k] >= opt.stability_min * opt.bootstrap &&
                dbic[k] >= opt.bic_threshold && dbic[chosen] - dbic[k] <= opt.ambiguity_bic &&
                lib[k].kind != EffectKind::pointwise)
                if (const CvResult cv = cross_validate(E, &resp[k], pb, base); cv0.nll - cv.nll >= opt.cv_margin)
                    chosen = static_cast<int>(k), cv_chosen = cv;
        const double stability = static_cast<double>(wins[chosen]) / opt.bootstrap;
        const Effect& e = lib[chosen];
        Finding f;
        const Signature sig = E.signature(e, base);
        // Equally good alternatives: within the ambiguity margin in BIC; and, when the resamples
        // split between near-tied candidates, those that together win them.
        double shared = stability;
        auto unobservable_difference = [&](const Signature& x, const Signature& y) {
            return !E.has_temperature() && x.heats_oil != y.heats_oil && x.thermal_path == y.thermal_path &&
                   x.load_dependent == y.load_dependent && x.viscosity_dependent == y.viscosity_dependent &&
                   std::abs(x.speed_exponent - y.speed_exponent) < 0.4 && x.pointwise == y.pointwise;
        };
        for (size_t k : order) {
            if (static_cast<int>(k) == chosen || dbic[k] < opt.bic_threshold) continue;
            const Signature sk = E.signature(lib[k], base);
            const bool near_tie =
                dbic[chosen] - dbic[k] <= opt.ambiguity_bic ||
                (stability < opt.stability_min && dbic[chosen] - dbic[k] <= 3 * opt.ambiguity_bic && wins[k] > 0) ||
                rival_in_resamples(stability, wins[k], opt);
            if (near_tie || unobservable_difference(sig, sk)) {
                f.equivalent.push_back(lib[k].id);
                shared += static_cast<double>(wins[k]) / opt.bootstrap;
                if (f.separating_measurement.empty()) f.separating_measurement = separating_measurement(sig, sk);
            }
        }
        if (stability < opt.stability_min && (f.equivalent.empty() || shared < 0.8)) {
            // Not named, but said: which effect, how strong, and what took the other resamples.
            std::vector<std::pair<std::string, int>> others;
            for (size_t k : contenders)
                if (static_cast<int>(k) != chosen) others.emplace_back(lib[k].id, wins[k]);
            const std::string rivals = resample_shares(others, opt);
            S.unsettled += fmt::format("{}{} fits better than {} by a delta BIC of {:.1f}, but is not named: it wins "
                                       "{:.0f} % of {} resamples{}{}",
                                       S.unsettled.empty() ? "" : "; ", e.id,
                                       terms.empty() ? std::string("the case without an effect")
                                                     : std::string("the findings before it"),
                                       dbic[chosen], 100.0 * stability, opt.bootstrap, rivals.empty() ? "" : ", against ",
                                       rivals);
            break;
        }
        f.effect = e.id;
        f.description = e.description;
        f.parameter = {e.parameter, e.unit, fits[chosen].value, fits[chosen].uncertainty, e.form, e.case_form};
        f.delta_bic = dbic[chosen];
        f.stability = stability;
        f.mechanism_stability = stability;
        for (size_t k : contenders)
            if (static_cast<int>(k) != chosen && !e.mechanism.empty() && lib[k].mechanism == e.mechanism)
                f.mechanism_stability += static_cast<double>(wins[k]) / opt.bootstrap;
        f.cv_gain = cv0.nll - cv_chosen.nll;
        record_fit(f, E, pb, base, fits[chosen].h, cv0, cv_chosen);
        S.findings.push_back(f);
        S.cv_rmse_after = cv_chosen.rmse_loss;
        // Taken with the accepted effects as refitted with it (a joint refit restarted from the
        // values they had alone would creep along a valley of compensating parameters).
        if (!refitted[chosen].empty()) terms = refitted[chosen];
        else terms.push_back({&e, fits[chosen].value});
        if (e.kind == EffectKind::pointwise) flags = fits[chosen].h.unstabilised;
        // Joint refit, then: is every earlier effect still needed?
        report(fmt::format("diagnose: finding {}: {} — refitting {} effect(s) jointly", round + 1, e.id, terms.size()));
        {
            const std::vector<Term> before = terms;
            const std::vector<char> flags_before = flags;
            if (refit_jointly(E, neutral, terms, flags, opt, true) >= kFailedNll) {
                terms = before;  // the joint optimum left the model's range: keep the values fitted in turn
                flags = flags_before;
                S.warnings.push_back("the joint refit of " + e.id + " with the earlier findings could not be evaluated; "
                                     "the values fitted one at a time are kept");
            }
        }
        // An unstabilised-test term whose points the joint refit no longer flags is gone.
        if (std::none_of(flags.begin(), flags.end(), [](char c) { return c != 0; })) {
            const auto pw = std::find_if(terms.begin(), terms.end(),
                                         [](const Term& t) { return t.effect->kind == EffectKind::pointwise; });
            if (pw != terms.end()) {
                const std::string id = pw->effect->id;
                terms.erase(pw);
                S.findings.erase(std::remove_if(S.findings.begin(), S.findings.end(),
                                                [&](const Finding& x) { return x.effect == id; }),
                                 S.findings.end());
            }
            flags.clear();
        }
        double nll_full = E.nll(with_terms(neutral, terms, flags), all, 0);
        for (bool dropped = true; dropped && terms.size() >= 2;) {
            dropped = false;
            for (size_t j = 0; j + 1 < terms.size(); ++j) {
                std::vector<Term> without = terms;
                std::vector<char> fl = flags;
                const double nll_wo = refit_jointly(E, neutral, without, fl, opt, false, static_cast<int>(j));
                if (nll_wo >= kFailedNll) continue;  // needed: without it the model cannot be evaluated
                const double penalty =
                    terms[j].effect->kind == EffectKind::pointwise
                        ? parameters_of({terms[j]}, flags) *
                              (std::log(static_cast<double>(N)) + std::log(static_cast<double>(all.size())))
                        : terms[j].effect->bic_penalty(N, terms[j].value);
                const double need = 2.0 * (nll_wo - nll_full) - penalty;
                if (need < opt.bic_threshold) {
                    S.warnings.push_back(fmt::format("{} is no longer needed once {} is fitted with it (delta BIC {:.1f}); "
                                                     "dropped",
                                                     terms[j].effect->id, e.id, need));
                    const std::string id = terms[j].effect->id;
                    terms.erase(terms.begin() + static_cast<long>(j));
                    S.findings.erase(std::remove_if(S.findings.begin(), S.findings.end(),
                                                    [&](const Finding& x) { return x.effect == id; }),
                                     S.findings.end());
                    forget_partner(S.findings, id, e.id);
                    if (std::none_of(terms.begin(), terms.end(),
                                     [](const Term& t) { return t.effect->kind == EffectKind::pointwise; }))
                        flags.clear();
                    const double again = refit_jointly(E, neutral, terms, flags, opt, true);
                    nll_full = again < kFailedNll ? again : E.nll(with_terms(neutral, terms, flags), all, 0);
                    dropped = true;
                    break;
                }
            }
        }
        if (terms.size() >= 2) nll_full = exchange(E, lib, neutral, terms, flags, nll_full, S, opt);
        base = with_terms(neutral, terms, flags);
    }
    // The findings carry the jointly refitted values (uncertainty: conditional on the others).
    for (auto& f : S.findings)
        for (size_t j = 0; j < terms.size(); ++j)
            if (terms[j].effect->id == f.effect && terms[j].effect->kind != EffectKind::pointwise) {
                // The value is the jointly refitted one (the calibrated case carries it); the
                // uncertainty is conditional on the others.
                f.parameter.value = terms[j].value;
                const Fit g = E.fit(*terms[j].effect, with_terms(neutral, terms, flags));
                f.parameter.uncertainty = g.failed.empty() ? g.uncertainty : std::nan("");
                if (const auto& sh = terms[j].effect->shape; sh && std::isfinite(sh->chosen) && sh->fitted())
                    f.shape = ShapeEstimate{sh->parameter, sh->chosen, sh->grid};
            } else if (terms[j].effect->id == f.effect) {
                f.rows.clear();
                for (int i : all)
                    if (!flags.empty() && flags[i]) f.rows.push_back(E.obs()[i].row);
                f.parameter.value = static_cast<double>(f.rows.size());
                f.parameter.uncertainty = 0;
            }
    S.h = with_terms(neutral, terms, flags);
    S.fitted = law_parameters(terms);
    // Cross-validated error of the final hypothesis: the last law refitted per fold on top of the others.
    if (!terms.empty() && terms.back().effect->kind != EffectKind::pointwise) {
        const int last = static_cast<int>(terms.size()) - 1;
        const Hypothesis others = with_terms(neutral, terms, flags, last);
        Response r;
        if (E.fit(*terms.back().effect, others, &r).failed.empty())
            S.cv_rmse_after = cross_validate(E, &r, E.predict_checked(others, all), others).rmse_loss;
    }
    return S;
}

}  // namespace gearloss::diagnosis::detail
