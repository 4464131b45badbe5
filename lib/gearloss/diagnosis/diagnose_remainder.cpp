// Model the remainder (diagnose_remainder.hpp).
#include "gearloss/diagnosis/diagnose_remainder.hpp"

#include <algorithm>
#include <cmath>

namespace gearloss::diagnosis::detail {

namespace {

// The formula for recorded - predicted loss under hypothesis h, over the operating point as
// the model under h sees it (the viscosity with h's viscosity factor, so that the terms a
// calibration gets evaluate to what was fitted).
hypothesis::Proposal fit_on(const Engine& E, const CampaignOils& oils, const Hypothesis& h, const Pred& p,
                            double noise_relative) {
    std::vector<double> resid, scale;
    hypothesis::Features f;
    for (int i : E.all()) {
        const auto& o = E.obs()[static_cast<size_t>(i)];
        const double T = o.has_T ? o.T_oil : p.temp[static_cast<size_t>(i)];
        resid.push_back(o.loss - p.loss[static_cast<size_t>(i)]);
        scale.push_back(o.scale);
        f.speed_rpm.push_back(std::abs(o.w) * to_rpm);
        f.torque_Nm.push_back(o.torque);
        f.oil_temp_C.push_back(T - 273.15);
        f.viscosity_cSt.push_back(point_viscosity(E, o, T) * h.cal.viscosity_factor);
        if (std::isfinite(o.run)) f.order.push_back(o.run);  // only where a run order is recorded
        f.model_loss_W.push_back(p.loss[static_cast<size_t>(i)]);
        if (oils.count_tested() >= 2) f.oil.push_back(oils.models[static_cast<size_t>(o.oil)].oil.name);
    }
    if (f.order.size() != f.speed_rpm.size()) f.order.clear();  // no run-order term without a recorded order
    if (f.order.empty()) f.model_loss_W.clear();                  // used by the run-order terms only
    hypothesis::Settings s;
    s.noise_relative = noise_relative;
    return hypothesis::propose(resid, scale, f, s);
}

}  // namespace

std::optional<hypothesis::Proposal> model_remainder(const Engine& E, const CampaignOils& oils, const Hypothesis& neutral,
                                                    const Pred& p0, const Hypothesis& base, const Pred& pf,
                                                    int findings, double noise_relative) {
    hypothesis::Proposal after = fit_on(E, oils, base, pf, noise_relative);
    if (findings > 0) {
        hypothesis::Proposal whole = fit_on(E, oils, neutral, p0, noise_relative);
        // The findings were fitted on every point, so their share of `after` is not
        // cross-validated: a model of p parameters fitted on n points predicts new points
        // with (n + p)/(n - p) times its mean square error on them (the final prediction error,
        // Akaike 1970).
        const double n = static_cast<double>(E.all().size());
        auto optimism = [n](double p) { return n > p ? std::sqrt((n + p) / (n - p)) : 1e9; };
        bool replace = false;
        if (after.found) {
            // p: the findings' parameters plus the terms `after` needs beyond `whole`, so that
            // the simpler explanation stands unless the richer one beats it by more than its
            // extra parameters buy on any data.
            const double p = std::max(1.0, static_cast<double>(findings) + static_cast<double>(after.terms.size()) -
                                               static_cast<double>(whole.terms.size()));
            replace = whole.found && whole.cv_rmse_after <= optimism(p) * after.cv_rmse_after;
        } else {
            // The findings leave nothing a formula models: they stand unless the formula alone
            // predicts a fifth better than they do (a finding of the right physics and a
            // formula of its shape predict alike; the finding names the physics).
            // Nor do several findings stand against one formula of fewer terms that predicts
            // as well (a constant parasitic loss plus a seal friction for one power of speed,
            // n^0.5): the simpler account of the same data is the formula, and the findings
            // are then not shown to be the cause.
            const double findings_cv = after.cv_rmse_before * optimism(static_cast<double>(findings));
            replace = whole.found && (whole.cv_rmse_after <= 0.8 * findings_cv ||
                                      (whole.terms.size() < static_cast<std::size_t>(findings) &&
                                       whole.cv_rmse_after <= findings_cv));
        }
        if (replace) {
            whole.on_case = true;
            whole.findings_cv_rmse = after.found ? after.cv_rmse_after : after.cv_rmse_before * optimism(findings);
            return whole;
        }
    }
    if (!after.found) return std::nullopt;
    return after;
}

}  // namespace gearloss::diagnosis::detail
