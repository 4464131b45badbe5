// diagnose(): the driver: baseline, rounds of candidate fits (BIC, cross-validation, stability), summary.
#include "gearloss/diagnosis/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>
#include <omp.h>
#include <random>
#include <stdexcept>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose_internal.hpp"
#include "gearloss/io/interrupt.hpp"

namespace gearloss::diagnosis {

using namespace detail;

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
        throw InputError(why);
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
