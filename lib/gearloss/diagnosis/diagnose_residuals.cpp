// diagnose: residual analysis: channel RMSE, structure left for a generic fit, where the mismatch lives.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>

#include "gearloss/diagnosis/diagnose_internal.hpp"
#include "gearloss/diagnosis/p_value_text.hpp"
#include "gearloss/model/validate.hpp"

namespace gearloss::diagnosis::detail {

// The upper of the two middle values for an even count (not their mean as in
// boost::math::statistics::median and median_absolute_deviation): a value of the sample, and
// the thresholds of the fits were tuned with it.
std::pair<double, double> robust_centre_scale(std::vector<double> v, double floor) {
    if (v.empty()) return {0.0, floor};
    std::sort(v.begin(), v.end());
    const double med = v[v.size() / 2];
    for (double& x : v) x = std::abs(x - med);
    std::sort(v.begin(), v.end());
    return {med, std::max(1.4826 * v[v.size() / 2], floor)};
}

bool run_order_recorded(const Engine& E) {
    for (const auto& o : E.obs())
        if (!std::isfinite(o.run)) return false;
    return !E.obs().empty();
}

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

// What the hypothesis leaves, per channel, against the noise: declared, or estimated from
// the recordings (replicates, neighbour differences); goodness of fit and structure.
Adequacy assess(const Engine& E, const Pred& p, const Hypothesis& h, int fitted, const DiagnoseOptions& opt,
                double combined_level) {
    const double level = opt.adequacy_level;
    Adequacy A;
    adequacy::Channel cl, ct;
    std::vector<int> oil_l, oil_t;  // the oil of each channel entry (multi-oil campaigns)
    const bool ordered = run_order_recorded(E);  // else no test along the run order
    for (int i : E.all()) {
        const auto& o = E.obs()[i];
        const double T = o.has_T ? o.T_oil : p.temp[i];
        // Coordinates rounded far below any recorded resolution: the same campaign in other
        // units (rad/s instead of rpm) gives the same ties, so the same test.
        auto q = [](double x, double step) { return std::round(x / step) * step; };
        auto add = [&](adequacy::Channel& c, double r) {
            c.residual.push_back(r);
            c.speed.push_back(q(std::abs(o.w) * to_rpm, 1e-4));
            c.torque.push_back(q(o.torque, 1e-6));
            c.oil_temp.push_back(q(T, 1e-6));
            if (ordered) c.order.push_back(o.run);
        };
        add(cl, (o.loss - p.loss[i]) / o.scale);
        oil_l.push_back(o.oil);
        if (o.T_evidence && (h.unstabilised.empty() || !h.unstabilised[i])) {
            add(ct, o.T_oil - p.temp[i]);
            oil_t.push_back(o.oil);
        }
    }
    // Replicates and neighbours are points of one oil: with several oils the noise is
    // estimated per oil and pooled (variances weighted by their degrees of freedom).
    auto estimate = [&](const adequacy::Channel& c, const std::vector<int>& oil) {
        if (E.oils() < 2) return adequacy::estimate_noise(c);
        adequacy::NoiseEstimate pooled;
        double ss = 0;
        for (int j = 0; j < E.oils(); ++j) {
            adequacy::Channel cj;
            for (size_t k = 0; k < c.residual.size(); ++k)
                if (oil[k] == j) {
                    cj.residual.push_back(c.residual[k]);
                    cj.speed.push_back(c.speed[k]);
                    cj.torque.push_back(c.torque[k]);
                    cj.oil_temp.push_back(c.oil_temp[k]);
                    if (!c.order.empty()) cj.order.push_back(c.order[k]);
                }
            if (cj.residual.empty()) continue;
            const adequacy::NoiseEstimate n = adequacy::estimate_noise(cj);
            if (!n.known()) continue;
            ss += n.dof * n.sigma * n.sigma;
            pooled.dof += n.dof;
            pooled.pairs += n.pairs;
            if (pooled.source.empty() || pooled.source == n.source) pooled.source = n.source;
            else pooled.source = "replicates and neighbour differences";
        }
        if (pooled.dof > 0) pooled.sigma = std::sqrt(ss / pooled.dof);
        else pooled.source = "none";
        return pooled;
    };
    // The noise a channel is tested against, and why that one (Adequacy::noise_*_why). Declared:
    // known. Estimated: at least `floor` (what any record resolves), and on a small campaign
    // (fewer than kSmallCampaignDof degrees of freedom in the estimate) at least `small_floor`:
    // a few neighbour differences of smooth residuals can come out far below the real noise
    // (0.3 % on a 3 x 3 grid recorded at 1.5 %), and testing against that reads the noise itself
    // as structure. The bound keeps the estimate's degrees of freedom (Fisher's F), since it
    // states a lower limit, not a known value.
    auto noise = [&](const adequacy::Channel& c, const std::vector<int>& oil, double declared, double floor,
                     double small_floor, double unit_scale, const char* unit, const char* option, std::string& why) {
        adequacy::NoiseEstimate n;
        if (declared > 0) {
            n.sigma = declared;
            n.dof = std::numeric_limits<double>::infinity();
            n.source = "declared";
            why = fmt::format("declared ({} {:.3g} {})", option, declared * unit_scale, unit);
            return n;
        }
        n = estimate(c, oil);
        if (!n.known()) {
            why = "too few points to estimate it";
            return n;
        }
        const double estimated = n.sigma;
        n.sigma = std::max(n.sigma, floor);
        why = fmt::format("estimated from the recordings ({}), {:.1f} degrees of freedom", n.source, n.dof);
        if (n.dof < kSmallCampaignDof && n.sigma < small_floor) {
            n.sigma = small_floor;
            n.source = "floor";
            n.contrasts.reset();  // no longer the contrasts' own scale: F, not the drawn null
            why = fmt::format("the estimate from {} points ({:.3g} {}, {:.1f} degrees of freedom) is below what a campaign "
                              "this small resolves; bounded below by the stated floor of {:.3g} {} ({} declares the rig's own)",
                              c.residual.size(), estimated * unit_scale, unit, n.dof, small_floor * unit_scale, unit, option);
        }
        return n;
    };
    // Each channel's tests (goodness of fit, structure): the family is judged at `level` as a
    // whole (Holm 1979: the k-th smallest p against level / (m - k + 1)), so that a campaign
    // of pure noise is called a mismatch at the stated level, not at m times it.
    struct Result {
        std::string what, unit, noise_text;
        double rms = 0, unit_scale = 1;
        const adequacy::FitTest* fit = nullptr;        // null when the noise is unknown
        const adequacy::StructureTest* structure = nullptr;
        bool bad_fit = false, bad_structure = false;
    };
    std::vector<Result> results;
    results.reserve(2);
    std::vector<double> p_values;
    std::vector<std::string> tested;  // "loss fit p = 0.03", ... for the combined test's sentence
    auto test = [&](const adequacy::Channel& c, const std::vector<int>& oil, adequacy::NoiseEstimate& n, adequacy::FitTest& fit,
                    adequacy::StructureTest& st, double declared, double floor, double small_floor, const char* what,
                    double unit_scale, const char* unit, const char* option, std::string& why, double& rms) {
        if (c.residual.size() < 6) return;
        n = noise(c, oil, declared, floor, small_floor, unit_scale, unit, option, why);
        if (n.known()) fit = adequacy::goodness_of_fit(c.residual, n, fitted, opt.confidence_level);
        st = adequacy::structure(c, 999);
        Result r{what, unit, "", 0.0, unit_scale, n.known() ? &fit : nullptr, &st};
        for (double x : c.residual) r.rms += x * x / c.residual.size();
        r.rms = std::sqrt(r.rms);
        rms = r.rms;
        r.noise_text = n.known() ? fmt::format("{:.3g} {} ({})", n.sigma * unit_scale, unit, n.source) : "unknown";
        if (n.known()) {
            p_values.push_back(fit.p_value);
            tested.push_back(fmt::format("{} fit {}", what, p_value_text(fit.p_value)));
        }
        p_values.push_back(st.p_value);
        tested.push_back(fmt::format("{} structure {}", what, p_value_text(st.p_value)));
        results.push_back(std::move(r));
    };
    test(cl, oil_l, A.noise_loss, A.fit_loss, A.structure_loss, opt.loss_uncertainty, kFloorLoss, opt.loss_noise_floor, "loss",
         100.0, "%", "--loss-uncertainty", A.noise_loss_why, A.rms_loss);
    if (E.has_temperature())
        test(ct, oil_t, A.noise_temp, A.fit_temp, A.structure_temp, opt.temp_uncertainty, kFloorTemp, opt.temp_noise_floor,
             "oil temperature", 1.0, "K", "--temp-uncertainty", A.noise_temp_why, A.rms_temp);
    // The claim that there is a mismatch at all (the combination no laxer than the tests' own
    // level) is made at `level` as a whole (adequacy::claim_levels); what findings leave is
    // judged by each test at `level` and by the combination at the laxer `combined_level`.
    const bool mismatch_claim = combined_level <= level;
    const adequacy::ClaimLevels claim = adequacy::claim_levels(level);
    const double holm_level = mismatch_claim ? claim.holm : level;
    const double fisher_level = mismatch_claim ? claim.combination : combined_level;
    const double threshold = adequacy::holm_threshold(p_values, holm_level);  // p-values below it are rejected
    std::vector<std::string> left;
    for (auto& r : results) {
        r.bad_fit = r.fit && r.fit->p_value < threshold;
        r.bad_structure = r.structure->p_value < threshold;
        if (!r.bad_fit && !r.bad_structure) continue;
        A.adequate = false;
        (r.what == std::string("loss") ? A.loss_fails : A.temp_fails) = true;
        // A residual within the noise fails only by its structure: say so, not "against".
        std::string s = fmt::format("{} residual RMS {:.3g} {} {} a noise of {}", r.what, r.rms * r.unit_scale, r.unit,
                                    r.bad_fit ? "against" : "within", r.noise_text);
        if (!r.bad_fit) s += ", but";
        if (r.bad_fit) s += ", " + p_value_text(r.fit->p_value);
        if (r.bad_structure)
            s += fmt::format("{} systematic along {} (a smoother explains {:.0f} % of it, {})", r.bad_fit ? ";" : "",
                             r.structure->coordinate,
                             100 * r.structure->gain, p_value_text(r.structure->p_value));
        left.push_back(s);
    }
    if (p_values.size() > 1) {
        A.combined_p = adequacy::combined_p(p_values);
        if (A.adequate && A.combined_p < fisher_level) {
            A.adequate = false;
            std::string list;
            for (const auto& t : tested) list += (list.empty() ? "" : ", ") + t;
            left.push_back(fmt::format("no single test fails at {:g} (Holm over {} tests), but together they do (Fisher's "
                                       "combination, {} < {:g}): {}",
                                       holm_level, p_values.size(), p_value_text(A.combined_p), fisher_level, list));
        }
    }
    for (const auto& s : left) A.text += (A.text.empty() ? "" : "\n") + s;
    std::vector<const adequacy::FitTest*> fits;
    for (const auto& r : results)
        if (r.fit) fits.push_back(r.fit);
    A.detectable = adequacy::detectable_remainder(fits, opt.confidence_level);
    return A;
}

namespace {

// Pearson's r by the two-pass sums, 0 for fewer than three points or a constant variable
// (boost::math::statistics::correlation_coefficient updates running means instead, so other
// last digits, and gives 1 when both are constant).
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

}  // namespace

Location locate(const Engine& E, const Pred& p, const Hypothesis& h, const solver::Model& /*model*/) {
    const auto& obs = E.obs();
    std::vector<double> lnn, tq, visc, dL, dT, lnnT, tqT, viscT;
    for (size_t i = 0; i < obs.size(); ++i) {
        const auto& o = obs[i];
        const double T = o.has_T ? o.T_oil : p.temp[i];
        lnn.push_back(std::log(std::max(o.w * to_rpm, 1e-3)));
        tq.push_back(o.torque);
        visc.push_back(std::log(point_viscosity(E, o, T)));
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

}  // namespace gearloss::diagnosis::detail
