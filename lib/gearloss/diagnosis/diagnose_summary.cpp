// diagnose: the summary paragraph that opens the report (the findings, the verdict's reason,
// or why there is none).
#include <cmath>
#include <fmt/format.h>

#include "gearloss/diagnosis/diagnose_internal.hpp"

namespace gearloss::diagnosis::detail {

std::string summary_paragraph(const Diagnosis& d, const std::string& baseline_clause, const std::string& adequacy_text,
                              bool completeness_unshown) {
    if (d.verdict == "missing_physics" || d.verdict == "partly_explained") {
        std::string s;
        for (size_t k = 0; k < d.findings.size(); ++k) {
            const auto& f = d.findings[k];
            if (k == 0) s += baseline_clause + " -> ";
            else s += "; then ";
            const char* verb = d.verdict == "missing_physics" ? "was left out" : "explains part of it";
            const std::string name = f.oil.empty() ? f.effect : f.effect + " of oil " + f.oil;
            if (f.equivalent.empty()) {
                s += fmt::format("{} {} ({})", name, verb, f.description);
            } else {
                std::string eq;
                for (const auto& x : f.equivalent) eq += " or " + x;
                s += fmt::format("{}{} {} — the data cannot tell which ({})", name, eq, verb, f.description);
            }
            if (f.effect == "unstabilised_test") {
                std::string rows;
                for (int r : f.rows) rows += (rows.empty() ? "" : ", ") + std::to_string(r);
                s += fmt::format("; rows {} excluded from the temperature evidence", rows);
            } else if (!f.parameter.form.empty()) {
                s += fmt::format("; {} = {} instead of {}", f.parameter.name, f.parameter.form, f.parameter.case_form);
            } else {
                s += fmt::format("; added {} = {}", f.parameter.name, fmt_value(f.parameter.value, f.parameter.unit));
                if (std::isfinite(f.parameter.uncertainty))
                    s += fmt::format(" +/- {}", fmt_value(f.parameter.uncertainty, f.parameter.unit));
                if (f.shape) s += " with " + shape_text(*f.shape);
            }
            s += fmt::format("; loss RMSE {:.3g} W -> {:.3g} W (cross-validated {:.3g} W)", f.rmse_before, f.rmse_after,
                             f.cv_rmse_after);
            if (d.has_temperature)
                s += fmt::format(", oil temperature RMSE {:.2f} K -> {:.2f} K", f.temp_rmse_before, f.temp_rmse_after);
            if (!f.equivalent.empty()) s += fmt::format(". To separate them: {}", f.separating_measurement);
        }
        if (d.remaining_structure)
            s += ". The main finding is confident; apart from it a smaller structure remains: " + d.remaining_structure->text;
        else if (d.verdict == "missing_physics" && !d.completeness.empty() && completeness_unshown)
            s += ". " + d.completeness;
        else if (d.verdict == "partly_explained" && (d.remaining.rfind("the main finding is not certain", 0) == 0 ||
                                                     d.remaining.rfind("not shown to be the cause", 0) == 0 ||
                                                     adequacy_text.empty()))
            s += ". But " + d.remaining;
        else if (d.verdict == "partly_explained")
            s += ". But what is left is not measurement noise: " + adequacy_text +
                 ". The names above are partial explanations, not the cause of the whole mismatch";
        if (d.remainder && d.remainder->on_case && d.remaining.rfind("not shown to be the cause", 0) != 0)
            s += fmt::format(". A formula of the operating point for the whole mismatch ({}) predicts the recordings {} "
                             "the findings under cross-validation ({:.3g} W against {:.3g} W): they may stand in for an "
                             "effect outside the library",
                             d.remainder->formula, hypothesis::on_case_comparison(*d.remainder),
                             d.remainder->cv_rmse_after, d.remainder->findings_cv_rmse);
        return s + ".";
    } else if (d.verdict == "unexplained_mismatch") {
        const auto& c = d.candidates.front();
        return fmt::format(
            "the recordings differ systematically from the model, but no candidate effect explains it ({}); the "
            "unexplained residual: {}; {}",
            !d.unsettled.empty() ? d.unsettled
            : c.rejected.empty() ? fmt::format("best: {} with delta BIC {:.1f}", c.effect, c.delta_bic)
                                 : std::string("no candidate could be evaluated"),
            baseline_clause, adequacy_text);
    } else if (!d.candidates.front().rejected.empty()) {
        return fmt::format("no significant missing physics: the residuals are consistent with measurement noise "
                                "(loss RMSE {:.3g} W); no candidate could be evaluated on these recordings (see the "
                                "candidates)",
                                d.rmse_before);
    } else {
        return fmt::format("no significant missing physics: the residuals are consistent with measurement noise "
                                "(loss RMSE {:.3g} W{}); best candidate {} (delta BIC {:.1f}) is below the evidence threshold",
                                d.rmse_before,
                                d.has_temperature ? fmt::format(", oil temperature RMSE {:.2f} K", d.temp_rmse_before) : "",
                                d.candidates.front().effect, d.candidates.front().delta_bic);
    }
}

}  // namespace gearloss::diagnosis::detail
