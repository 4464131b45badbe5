// diagnose: the verdict (is an effect present, and is it the whole cause: two questions), the
// noise it was judged against, and the outliers against that noise.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "gearloss/diagnosis/diagnose_internal.hpp"

namespace gearloss::diagnosis::detail {

namespace {

// A confident main finding may leave a smaller structure in the oil temperature when the loss
// is at the noise: its own tests pass with room (p at least the confidence level, not only
// Holm's bound) and its RMS is within this multiple of the noise.
constexpr double kLossAtNoise = 1.5;
// The share of a temperature remainder a heat path of another size (the oil's rise above the
// ambient scaled by a factor) must explain to be named as such.
constexpr double kHeatPathShare = 0.5;
// A remainder left after a confident main finding is smaller: at most this many times the noise
// (RMS beyond it), and at most kSmallerShare of what the findings explained (in units of each
// channel's noise, the larger channel); else the findings are a partial explanation.
constexpr double kSmallerMax = 3.0, kSmallerShare = 0.5;
// A remainder below this multiple of the noise (RMS beyond it) is described as within the noise's size.
constexpr double kWithinNoise = 0.1;

// The oil temperature left after the findings, against the oil's predicted rise above the
// ambient: a heat path (thermal resistance) that differs by a factor f leaves f times the rise.
// Returns f and the share of the remainder's sum of squares it explains.
std::pair<double, double> heat_path_factor(const Engine& E, const Pred& p, const Hypothesis& h) {
    double sxy = 0, sxx = 0, syy = 0;
    for (int i : E.all()) {
        const Obs& o = E.obs()[i];
        if (!o.T_evidence || (!h.unstabilised.empty() && h.unstabilised[i])) continue;
        const double rise = p.temp[i] - o.ambient, left = o.T_oil - p.temp[i];
        sxy += rise * left;
        sxx += rise * rise;
        syy += left * left;
    }
    if (!(sxx > 0) || !(syy > 0)) return {0.0, 0.0};
    const double f = sxy / sxx;
    return {f, f * sxy / syy};
}

}  // namespace

void judge(Diagnosis& d, const Adequacy& ad, const DiagnoseOptions& opt, const Engine& E, const Pred& pf,
           const Hypothesis& h, const std::string& remaining_location) {
    // The noise used, and why.
    d.noise_used.loss_relative = ad.noise_loss.sigma;
    d.noise_used.source = ad.noise_loss.source.empty() ? "none" : ad.noise_loss.source;
    d.noise_used.why = ad.noise_loss_why;
    if (E.has_temperature()) {
        d.noise_used.temp_K = ad.noise_temp.sigma;
        d.noise_used.temp_source = ad.noise_temp.source.empty() ? "none" : ad.noise_temp.source;
        d.noise_used.temp_why = ad.noise_temp_why;
    }
    if (d.findings.empty()) {
        d.verdict = ad.adequate ? "no_significant_mismatch" : "unexplained_mismatch";
        if (!ad.adequate) d.remaining = ad.text + "\n" + d.location;
        return;
    }
    // Present: the selection's evidence (BIC, cross-validation, resamples). The whole cause:
    // what the findings leave is noise. With the loss at the noise, a smaller remainder (in the
    // oil temperature, or one only the tests' combination sees) leaves the main finding
    // confident and is reported apart, sized and located.
    const double loss_noise = ad.noise_loss.sigma;
    const bool loss_at_noise = ad.noise_loss.known() && !ad.loss_fails && ad.rms_loss <= kLossAtNoise * loss_noise &&
                               ad.fit_loss.p_value >= opt.confidence_level &&
                               ad.structure_loss.p_value >= opt.confidence_level;
    // What fails with the loss at the noise: the oil temperature's own tests, or only the
    // combination of all (no single test), a structure smaller than any test alone sees.
    const bool temperature_left = !ad.adequate && ad.temp_fails && loss_at_noise && ad.noise_temp.known();
    const bool combination_left = !ad.adequate && !ad.temp_fails && loss_at_noise;
    // The remainder beyond the noise in its channel, against what the findings explained.
    double scale2 = 0;
    for (const Obs& o : E.obs()) scale2 += o.scale * o.scale / static_cast<double>(E.obs().size());
    const auto beyond = [](double rms, double sigma) { return std::sqrt(std::max(0.0, rms * rms / (sigma * sigma) - 1)); };
    const auto explained = [](double before, double after, double sigma) {
        return sigma > 0 ? std::sqrt(std::max(0.0, before * before - after * after)) / sigma : 0.0;
    };
    double explained_over_noise = explained(d.rmse_before, d.rmse_after, loss_noise * std::sqrt(scale2));
    if (E.has_temperature() && ad.noise_temp.known())
        explained_over_noise =
            std::max(explained_over_noise, explained(d.temp_rmse_before, d.temp_rmse_after, ad.noise_temp.sigma));
    const auto smaller = [&](double over_noise) {
        return over_noise <= std::min(kSmallerMax, kSmallerShare * explained_over_noise);
    };
    const double left_temp = ad.noise_temp.known() ? beyond(ad.rms_temp, ad.noise_temp.sigma) : 0.0;
    const double left_loss = ad.noise_loss.known() ? beyond(ad.rms_loss, loss_noise) : 0.0;
    const bool apart = (temperature_left && smaller(left_temp)) || (combination_left && smaller(std::max(left_temp, left_loss)));
    // The name itself must be earned: chosen in at least stability_min of the resamples (a
    // finding that wins in only half of them has runners-up as good; on 3 x 3 grids of synth
    // campaigns such names were wrong in half the cases).
    const Finding& main = d.findings.front();
    // The mechanism counts, not its form: mesh friction's level and its mixed-film rise that
    // split the resamples 54/46 on nine points name the mesh friction with confidence, and its
    // form as open (both listed, with the measurement that separates them).
    const bool form_open = main.stability < opt.stability_min && main.mechanism_stability >= opt.stability_min;
    const bool stable = main.stability >= opt.stability_min || form_open;
    d.verdict = (ad.adequate || apart) && stable ? "missing_physics" : "partly_explained";
    d.main_finding = {d.findings.front().effect, d.verdict == "missing_physics" ? "confident" : "tentative"};
    // The channel of a remainder only the combination sees: the one with the smaller p-value.
    const auto min_p = [](const adequacy::FitTest& f, const adequacy::StructureTest& st) {
        return std::min(f.p_value, st.p_value);
    };
    const bool in_temperature = temperature_left || (combination_left && E.has_temperature() && ad.noise_temp.known() &&
                                                     min_p(ad.fit_temp, ad.structure_temp) < min_p(ad.fit_loss, ad.structure_loss));
    if (apart && stable && combination_left && !in_temperature) {
        Diagnosis::RemainingStructure r;
        r.channel = "loss";
        r.rms_over_noise = left_loss;
        r.along = ad.structure_loss.p_value < opt.confidence_level ? ad.structure_loss.coordinate : "";
        r.text = r.rms_over_noise >= kWithinNoise
                     ? fmt::format("loss {:.2g} times the noise ({:.3g} %) RMS beyond it", r.rms_over_noise, 100 * loss_noise)
                     : fmt::format("a loss structure within the noise's size ({:.3g} %)", 100 * loss_noise);
        if (!r.along.empty()) r.text += ", along " + r.along;
        d.remaining = "the main finding is confident (the loss is at the noise); a smaller structure remains, apart from it: " +
                      r.text + "\n" + ad.text;
        d.remaining_structure = std::move(r);
    } else if (apart && stable && in_temperature) {
        Diagnosis::RemainingStructure r;
        r.channel = "oil_temperature";
        const double sigma = ad.noise_temp.sigma, excess = left_temp * sigma;  // K RMS beyond the noise
        r.rms_over_noise = left_temp;
        const auto [factor, share] = heat_path_factor(E, pf, h);
        if (share >= kHeatPathShare) {
            r.along = "power";
            r.text = fmt::format("oil temperature {:.2g} K RMS beyond the noise ({:.2g} K), along power (the oil's rise above "
                                 "the ambient): the heat path differs by ~{:.0f} % ({} of the rise than the model's)",
                                 excess, sigma, 100 * std::abs(factor), factor > 0 ? "more" : "less");
        } else {
            r.along = ad.structure_temp.p_value < opt.confidence_level ? ad.structure_temp.coordinate : "";
            r.text = r.rms_over_noise >= kWithinNoise
                         ? fmt::format("oil temperature {:.2g} K RMS beyond the noise ({:.2g} K)", excess, sigma)
                         : fmt::format("an oil temperature structure within the noise's size ({:.2g} K)", sigma);
            if (!r.along.empty()) r.text += ", along " + r.along;
        }
        d.remaining = "the main finding is confident (the loss is at the noise); a smaller structure remains, apart from it: " +
                      r.text + "\n" + ad.text;
        d.remaining_structure = std::move(r);
    } else if (!ad.adequate) {
        d.remaining = "a systematic residual remains after the findings:\n" + ad.text + "\n" + remaining_location;
    }
    if (form_open && (ad.adequate || apart))
        d.remaining = fmt::format("the main finding's mechanism is certain, its form is not: {} was chosen in {:.0f} % of {} "
                                  "bootstrap resamples, it or another form of the same mechanism in {:.0f} % (the "
                                  "equally good forms are listed with it){}",
                                  main.effect, 100 * main.stability, d.bootstrap, 100 * main.mechanism_stability,
                                  d.remaining.empty() ? std::string() : ".\n" + d.remaining);
    if (!stable && (ad.adequate || apart))
        d.remaining = fmt::format("the main finding is not certain: {} was chosen in {:.0f} % of {} bootstrap resamples "
                                  "(a confident name needs {:.0f} %); the candidates after it explain the recordings "
                                  "nearly as well{}",
                                  main.effect, 100 * main.stability, d.bootstrap, 100 * opt.stability_min,
                                  d.remaining.empty() ? std::string() : ".\n" + d.remaining);
    // Whole cause: the tests pass and could have seen a remainder of the noise's size.
    if (ad.adequate && ad.detectable <= opt.confident_detectable)
        d.completeness = "What the findings leave is noise, and the tests would have seen a remainder of the noise's size";
    else if (ad.adequate) {
        const bool estimated = ad.noise_loss.source != "declared" || (E.has_temperature() && ad.noise_temp.source != "declared");
        d.completeness = fmt::format(
            "What the findings leave passes the tests against the noise, but on {} points those tests see little: a "
            "remainder of {:.2g} times the noise would pass them in half such campaigns. The effect is present; whether "
            "it is the whole cause these points cannot show ({} to test that)",
            E.obs().size(), ad.detectable,
            estimated ? "declare the rig's measurement uncertainty (--loss-uncertainty, --temp-uncertainty) or record more points"
                      : "repeat points");
    }
}

std::vector<Outlier> noise_outliers(const Engine& F, const Pred& after, const Hypothesis& h, const Adequacy& ad,
                                    double loss_floor, double temp_floor) {
    // Each channel's residuals about their median, over the larger of their robust scale and
    // the noise known without them: a row is an outlier against the noise, never against a few
    // points' spread that happens to be smaller (a row 0.8 % off at 1.5 % noise is not one).
    // A declared noise is that noise; an estimated one is not used here, since the outlier
    // itself inflates it (one row 20 % off among 12 made neighbour differences of 6 %): the
    // robust scale stands for it, bounded below by what a rig resolves (the floor).
    std::vector<double> eP, eT;
    const auto temp_evidence = [&](int i) {
        const Obs& o = F.obs()[i];
        return o.T_evidence && (h.unstabilised.empty() || !h.unstabilised[i]);
    };
    for (int i : F.all()) {
        const auto& o = F.obs()[i];
        eP.push_back((o.loss - after.loss[i]) / o.scale);
        if (temp_evidence(i)) eT.push_back(o.T_oil - after.temp[i]);
    }
    const double nP = ad.noise_loss.source == "declared" ? ad.noise_loss.sigma : loss_floor;
    const double nT = ad.noise_temp.source == "declared" ? ad.noise_temp.sigma : temp_floor;
    const auto [mP, sP] = robust_centre_scale(eP, std::max(0.004, nP));
    const auto [mT, sT] = robust_centre_scale(eT, std::max(0.15, nT));
    std::vector<Outlier> out;
    for (int i : F.all()) {
        const auto& o = F.obs()[i];
        std::vector<std::string> why;
        Outlier x{o.row, "", std::nullopt, std::nullopt};
        if (!o.stabilised)
            why.push_back(fmt::format("never stabilised: (T_oil - T_room) varied {:.2f} K over the last 30 min", o.drift));
        if (!h.unstabilised.empty() && h.unstabilised[i])
            why.push_back(fmt::format("oil {:.1f} K {} than the heat balance of its measured loss: the test was still "
                                      "{} (unstabilised)",
                                      std::abs(after.temp[i] - o.T_oil), o.T_oil < after.temp[i] ? "colder" : "hotter",
                                      o.T_oil < after.temp[i] ? "warming up" : "cooling down"));
        const double dP = (o.loss - after.loss[i]) / o.scale - mP, zP = dP / sP;
        if (std::abs(zP) > kOutlierSigmas) {
            const double noise = sP;  // the scale the row was judged against
            x.loss_deviation_over_noise = dP / noise;
            why.push_back(fmt::format("loss {:+.1f} W ({:+.1f} %) away from the model, {:.1f} times the noise of {:.2g} %",
                                      o.loss - after.loss[i], 100 * (o.loss - after.loss[i]) / o.scale, std::abs(dP) / noise,
                                      100 * noise));
        }
        if (temp_evidence(i)) {
            const double dT = o.T_oil - after.temp[i] - mT, zT = dT / sT;
            if (std::abs(zT) > kOutlierSigmas) {
                x.temp_deviation_over_noise = dT / sT;
                why.push_back(fmt::format("oil temperature {:+.1f} K away from the model{}", o.T_oil - after.temp[i],
                                          (o.T_oil < after.temp[i] && zP > -1) ? " while its loss is not low: loss and "
                                                                                 "temperature disagree (still warming up?)"
                                                                               : ""));
            }
        }
        if (why.empty()) continue;
        x.reason = why[0];
        for (size_t k = 1; k < why.size(); ++k) x.reason += "; " + why[k];
        out.push_back(std::move(x));
    }
    return out;
}

}  // namespace gearloss::diagnosis::detail
