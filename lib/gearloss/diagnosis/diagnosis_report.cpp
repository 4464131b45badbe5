#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/case/mechanism_config.hpp"

// The diagnosis as text, JSON and a residuals table, and the calibrated case file.
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "gearloss/diagnosis/p_value_text.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/case/empirical_config.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/json_text.hpp"

namespace gearloss::diagnosis {

namespace {
// Multi-oil campaigns: which findings depend on the oil, and the recorded differences between
// oils against the model's (as `compare` gives them), before and after the findings.
std::string oils_text(const Diagnosis& d) {
    std::string s = "\noils tested: ";
    for (size_t j = 0; j < d.oils.size(); ++j) s += (j ? ", " : "") + d.oils[j];
    s += "\n";
    for (const auto& f : d.findings)
        s += fmt::format("  {}: {}\n", f.effect, f.oil.empty() ? "common to every oil" : "depends on the oil (" + f.oil + ")");
    if (d.oil_differences.empty()) return s + "  no operating point was recorded with two oils\n";
    s += "  loss difference between oils, B - A [W]:\n";
    s += fmt::format("  {:>9} {:>10}  {:<22} {:>10} {:>12} {:>12}\n", "speed_rpm", "torque_Nm", "B (A: first oil)", "recorded",
                     "model before", "model after");
    for (const auto& x : d.oil_differences)
        s += fmt::format("  {:>9.1f} {:>10.4g}  {:<22} {:>10.1f} {:>12.1f} {:>12.1f}\n", x.speed_rpm, x.torque, x.oil_b,
                         x.recorded, x.model_before, x.model_after);
    return s;
}

// The remainder formula: its terms with their uncertainty and form, the cross-validated
// residual against the noise, and what it resembles.
std::string remainder_text(const hypothesis::Proposal& r) {
    std::string s = fmt::format("\nhypothesis for what is left (not a finding): {}\n", r.formula);
    for (const auto& t : r.terms) {
        s += fmt::format("  {:>10.4g} +/- {:<9.2g} {} {}", t.coefficient, t.uncertainty, t.relative ? "x" : "W", t.basis);
        if (std::isfinite(t.exponent_low) && t.exponent_high > t.exponent_low)
            s += fmt::format(" (exponent {:.1f} to {:.1f}, 95 %)", t.exponent_low, t.exponent_high);
        if (std::isfinite(t.oil_temp_equivalent))
            s += fmt::format(" (the oil {} {:.4g} degC)", t.above ? "below" : "above", t.oil_temp_equivalent);
        s += "\n";
    }
    // The formula is fitted with weights 1/recorded loss^2, so its RMS is the weighted one (in W).
    s += fmt::format("  cross-validated loss RMSE (weighted as fitted, 1/loss^2) {:.3g} W -> {:.3g} W", r.cv_rmse_before,
                     r.cv_rmse_after);
    if (r.noise_W > 0)
        s += fmt::format(" against a noise of {:.3g} W: the final model leaves {:.2g} times the noise",
                         r.noise_W, r.cv_rmse_after / r.noise_W);
    s += "\n";
    if (r.on_case)
        s += fmt::format("  this formula is for the whole mismatch of the case as described: alone it predicts the "
                         "recordings {} the findings with a formula for what they leave (cross-validated "
                         "{:.3g} W against {:.3g} W), so the findings may stand in for an effect outside the library\n",
                         hypothesis::on_case_comparison(r), r.cv_rmse_after, r.findings_cv_rmse);
    for (const auto& n : r.nearest) s += "  resembles: " + n + "\n";
    return s;
}

nlohmann::ordered_json remainder_json(const hypothesis::Proposal& p) {
    nlohmann::ordered_json r;
    r["formula"] = p.formula;
    r["cv_rmse_before"] = p.cv_rmse_before;
    r["cv_rmse_after"] = p.cv_rmse_after;
    if (p.noise_W > 0) {
        r["noise_W"] = p.noise_W;
        // The findings are fixed while the formula is cross-validated on what they leave.
        r["final_cv_rmse_W"] = p.cv_rmse_after;
        r["final_cv_rmse_over_noise"] = p.cv_rmse_after / p.noise_W;
    }
    // on_case: the formula models the whole mismatch of the case as described, not what the
    // findings leave (it predicts the recordings better than findings + formula, or as well and more simply).
    r["on_case"] = p.on_case;
    if (p.on_case) r["findings_cv_rmse_W"] = p.findings_cv_rmse;
    auto& terms = r["terms"] = nlohmann::ordered_json::array();
    for (const auto& t : p.terms) {
        // A relative term's coefficient is a share of the model's loss, not watts.
        nlohmann::ordered_json o{{"basis", t.basis}};
        o[t.relative ? "coefficient_share" : "coefficient_W"] = t.coefficient;
        o[t.relative ? "uncertainty_share" : "uncertainty_W"] = t.uncertainty;
        if (t.relative) o["relative"] = true;
        o["shape"] = t.shape;
        o["variable"] = t.variable.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(t.variable);
        if (std::isfinite(t.exponent)) o["exponent"] = t.exponent;
        if (std::isfinite(t.exponent_low)) o["exponent_range"] = {t.exponent_low, t.exponent_high};
        if (std::isfinite(t.threshold)) {
            o["threshold"] = t.threshold;
            o["side"] = t.above ? "above" : "below";
        }
        if (std::isfinite(t.oil_temp_equivalent)) o["oil_temp_equivalent_C"] = t.oil_temp_equivalent;
        if (std::isfinite(t.lower)) o["lower"] = t.lower;
        if (std::isfinite(t.upper)) o["upper"] = t.upper;
        if (t.gate)
            o["gate"] = {{"variable", t.gate->variable}, {"threshold", t.gate->threshold}, {"side", t.gate->above ? "above" : "below"}};
        if (t.window) o["window"] = {{"variable", t.window->variable}, {"lower", t.window->lower}, {"upper", t.window->upper}};
        if (!t.oil.empty()) o["oil"] = t.oil;
        o["writable"] = t.empirical.has_value();
        terms.push_back(std::move(o));
    }
    r["nearest"] = p.nearest;
    return r;
}
}  // namespace

std::string diagnosis_text(const Diagnosis& d) {
    std::string s = fmt::format("verdict: {}\n\n{}\n\nwhere the model and the recordings differ ({} points):\n{}\n", d.verdict,
                                d.summary, d.points, d.location);
    for (const auto& f : d.findings) {
        s += fmt::format("\nfinding: {}{} — {}\n", f.effect, f.oil.empty() ? "" : " (oil " + f.oil + " only)",
                         f.description);
        if (f.effect == "unstabilised_test") {
            std::string rows;
            for (int r : f.rows) rows += (rows.empty() ? "" : ", ") + std::to_string(r);
            s += fmt::format("  rows still warming: {}\n", rows);
        } else if (!f.parameter.form.empty()) {
            s += fmt::format("  {} = {} (the case: {})\n", f.parameter.name, f.parameter.form, f.parameter.case_form);
        } else {
            // The uncertainty is not finite when the fit's curvature is flat or negative there (the
            // parameter is not determined by the data): said in words, never "+/- nan".
            s += fmt::format("  {} = {} {}\n", f.parameter.name, fmt_value(f.parameter.value, f.parameter.unit),
                             std::isfinite(f.parameter.uncertainty)
                                 ? "+/- " + fmt_value(f.parameter.uncertainty, f.parameter.unit)
                                 : std::string("(uncertainty not determined: the recordings do not constrain it)"));
            if (f.shape) s += fmt::format("  {}\n", shape_text(*f.shape));
        }
        s += fmt::format("  evidence: delta BIC {:.1f}, cross-validated log-likelihood gain {:.1f}, chosen in {:.0f} % of {} "
                         "bootstrap resamples\n",
                         f.delta_bic, f.cv_gain, 100 * f.stability, d.bootstrap);
        s += fmt::format("  loss RMSE {:.3g} -> {:.3g} W, cross-validated {:.3g} -> {:.3g} W\n", f.rmse_before, f.rmse_after,
                         f.cv_rmse_before, f.cv_rmse_after);
        if (d.has_temperature)
            s += fmt::format("  oil temperature RMSE {:.2f} -> {:.2f} K\n", f.temp_rmse_before, f.temp_rmse_after);
        for (const auto& e : f.equivalent)
            s += fmt::format("  equally good: {} — to separate them: {}\n", e, f.separating_measurement);
    }
    if (!d.oils.empty()) s += oils_text(d);
    if (!d.remaining.empty() && d.verdict != "unexplained_mismatch") s += "\n" + d.remaining + "\n";
    if (!d.unsettled.empty() && d.verdict != "unexplained_mismatch") s += "\nnot named: " + d.unsettled + "\n";
    if (d.remainder) s += remainder_text(*d.remainder);
    s += fmt::format("\nnoise: loss {:.3g} % ({}), test of what is left: fit {}, structure {}{}\n",
                     100 * d.adequacy_loss.noise, d.adequacy_loss.noise_source, p_value_text(d.adequacy_loss.fit_p),
                     p_value_text(d.adequacy_loss.structure_p),
                     d.adequacy_loss.structure_along.empty() ? "" : " (along " + d.adequacy_loss.structure_along + ")");
    if (d.has_temperature)
        s += fmt::format("       oil temperature {:.3g} K ({}), fit {}, structure {}{}\n", d.adequacy_temp.noise,
                         d.adequacy_temp.noise_source, p_value_text(d.adequacy_temp.fit_p),
                         p_value_text(d.adequacy_temp.structure_p),
                         d.adequacy_temp.structure_along.empty() ? "" : " (along " + d.adequacy_temp.structure_along + ")");
    if (std::isfinite(d.detectable))
        s += fmt::format("       power: a remainder of {:.2g} times the noise fails the fit test{} in half such campaigns\n",
                         d.detectable, d.has_temperature ? "s" : "");
    s += fmt::format("noise used: loss {:.3g} %, {}\n", 100 * d.noise_used.loss_relative, d.noise_used.why);
    if (d.has_temperature)
        s += fmt::format("            oil temperature {:.3g} K, {}\n", d.noise_used.temp_K, d.noise_used.temp_why);
    s += d.run_order.recorded
             ? fmt::format("run order: from the `{}` column\n", d.run_order.column)
             : std::string("run order: not recorded (no run, date or time column): the rows may be in any order, so no "
                           "drift or running-in hypothesis is formed\n");
    if (!d.main_finding.effect.empty())
        s += fmt::format("main finding: {} ({}){}{}\n", d.main_finding.effect, d.main_finding.confidence,
                         d.completeness.empty() ? "" : "; " + d.completeness,
                         d.remainder && d.remainder->on_case
                             ? "; the formula for the whole mismatch is the better account (see the hypothesis)"
                             : "");
    s += "\ncandidates (delta BIC, > 10 is very strong evidence):\n";
    for (const auto& c : d.candidates) {
        if (c.rejected.empty()) s += fmt::format("  {:<24} {:8.1f}   fitted {:.4g}\n", c.effect, c.delta_bic, c.value);
        else s += fmt::format("  {:<24} rejected: {}\n", c.effect, c.rejected);
    }
    if (!d.outliers.empty()) {
        s += "\noutliers:\n";
        for (const auto& o : d.outliers) s += fmt::format("  row {}: {}\n", o.row, o.reason);
    }
    for (const auto& w : d.warnings) s += "warning: " + w + "\n";
    return s;
}

std::string diagnosis_json(const Diagnosis& d) {
    nlohmann::ordered_json j;
    j["verdict"] = d.verdict;
    j["summary"] = d.summary;
    j["location"] = d.location;
    j["remaining"] = d.remaining;
    if (!d.unsettled.empty()) j["unsettled"] = d.unsettled;
    j["points"] = d.points;
    if (d.fit_points < d.points) j["fit_points"] = d.fit_points;  // a large campaign fitted on part of its points
    j["rmse_before"] = d.rmse_before;
    j["rmse_after"] = d.rmse_after;
    j["cv_rmse_after"] = d.cv_rmse_after;
    if (d.has_temperature) {
        j["temp_rmse_before"] = d.temp_rmse_before;
        j["temp_rmse_after"] = d.temp_rmse_after;
    }
    // The noise the remainder was tested against, and the tests' p-values.
    auto& adequacy = j["adequacy"] = nlohmann::ordered_json::object();
    auto channel = [&](const char* key, const Diagnosis::Channel& c) {
        auto& o = adequacy[key];
        o["noise"] = c.noise;
        o["noise_source"] = c.noise_source;
        o["fit_p"] = c.fit_p;
        if (std::isfinite(c.fit_detectable)) o["fit_detectable"] = c.fit_detectable;
        o["structure_p"] = c.structure_p;
        o["structure_along"] = c.structure_along;
    };
    channel("loss_relative", d.adequacy_loss);
    if (d.has_temperature) channel("oil_temperature_K", d.adequacy_temp);
    if (std::isfinite(d.detectable)) adequacy["detectable_remainder"] = d.detectable;
    // The noise the verdict was tested against and why (declared, estimated, or the floor).
    auto& noise = j["noise_used"];
    noise["loss_relative"] = d.noise_used.loss_relative;
    noise["source"] = d.noise_used.source;
    noise["why"] = d.noise_used.why;
    if (d.has_temperature) {
        noise["oil_temperature_K"] = d.noise_used.temp_K;
        noise["oil_temperature_source"] = d.noise_used.temp_source;
        noise["oil_temperature_why"] = d.noise_used.temp_why;
    }
    if (!d.main_finding.effect.empty())
        j["main_finding"] = {{"effect", d.main_finding.effect}, {"confidence", d.main_finding.confidence}};
    if (!d.completeness.empty()) j["completeness"] = d.completeness;
    if (d.remaining_structure)
        j["remaining_structure"] = {{"channel", d.remaining_structure->channel},
                                    {"rms_over_noise", d.remaining_structure->rms_over_noise},
                                    {"along", d.remaining_structure->along},
                                    {"text", d.remaining_structure->text}};
    j["run_order"] = {{"recorded", d.run_order.recorded},
                      {"column", d.run_order.recorded ? nlohmann::ordered_json(d.run_order.column) : nlohmann::ordered_json(nullptr)}};
    if (d.remainder) j["remainder_hypothesis"] = remainder_json(*d.remainder);
    if (!d.oils.empty()) {
        j["oils"] = d.oils;
        auto& diffs = j["oil_differences"] = nlohmann::ordered_json::array();
        for (const auto& x : d.oil_differences)
            diffs.push_back({{"speed_rpm", x.speed_rpm},
                             {"torque_Nm", x.torque},
                             {"oil_a", x.oil_a},
                             {"oil_b", x.oil_b},
                             {"recorded_W", x.recorded},
                             {"model_before_W", x.model_before},
                             {"model_after_W", x.model_after}});
    }
    auto& findings = j["findings"] = nlohmann::ordered_json::array();
    for (const auto& f : d.findings) {
        nlohmann::ordered_json o;
        o["effect"] = f.effect;
        o["description"] = f.description;
        // Multi-oil campaigns: the oil a finding concerns alone; null: every oil.
        o["oil"] = f.oil.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(f.oil);
        auto& p = o["parameters"][f.parameter.name];
        p["value"] = f.parameter.value;
        p["uncertainty"] = f.parameter.uncertainty;
        p["unit"] = f.parameter.unit;
        if (!f.parameter.form.empty()) {
            p["form"] = f.parameter.form;
            p["case_form"] = f.parameter.case_form;
        }
        if (f.shape) {  // a shape setting fitted with it on a grid: no uncertainty of its own
            auto& q = o["parameters"][f.shape->name];
            q["value"] = f.shape->value;
            q["uncertainty"] = nullptr;
            q["unit"] = "";
            q["profiled_over"] = f.shape->grid;
        }
        if (!f.rows.empty()) o["rows"] = f.rows;
        o["rmse_before"] = f.rmse_before;
        o["rmse_after"] = f.rmse_after;
        o["cv_rmse_before"] = f.cv_rmse_before;
        o["cv_rmse_after"] = f.cv_rmse_after;
        if (d.has_temperature) {
            o["temp_rmse_before"] = f.temp_rmse_before;
            o["temp_rmse_after"] = f.temp_rmse_after;
        }
        o["delta_bic"] = f.delta_bic;
        o["cv_loglik_gain"] = f.cv_gain;
        o["stability"] = f.stability;
        o["mechanism_stability"] = f.mechanism_stability;
        o["equivalent"] = f.equivalent;
        o["separating_measurement"] = f.separating_measurement;
        findings.push_back(std::move(o));
    }
    auto& outliers = j["outliers"] = nlohmann::ordered_json::array();
    for (const auto& o : d.outliers) {
        nlohmann::ordered_json x{{"row", o.row}};
        if (o.loss_deviation_over_noise) x["loss_deviation_over_noise"] = *o.loss_deviation_over_noise;
        if (o.temp_deviation_over_noise) x["temp_deviation_over_noise"] = *o.temp_deviation_over_noise;
        x["reason"] = o.reason;
        outliers.push_back(std::move(x));
    }
    auto& candidates = j["candidates"] = nlohmann::ordered_json::array();
    for (const auto& c : d.candidates) {
        nlohmann::ordered_json o;
        o["effect"] = c.effect;
        if (c.rejected.empty()) {
            o["delta_bic"] = c.delta_bic;
            o["fitted"] = c.value;
        } else {
            o["delta_bic"] = nullptr;
            o["fitted"] = nullptr;
            o["rejected"] = c.rejected;
        }
        candidates.push_back(std::move(o));
    }
    j["warnings"] = d.warnings;
    return io::json_line(j);
}

std::string residuals_csv(const Diagnosis& d) {
    std::string s =
        "row,speed_in_rpm,torque_in_Nm,P_loss_W,P_model_before_W,P_model_after_W,oil_temp_C,oil_temp_model_before_C,"
        "oil_temp_model_after_C";
    // Multi-oil campaigns: the oil of each test, quoted as CSV text (RFC 4180).
    const bool oils = !d.oils.empty();
    s += oils ? ",oil\n" : "\n";
    auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : std::string(); };
    auto quoted = [](const std::string& x) {
        std::string q = "\"";
        for (char c : x) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    for (const auto& r : d.residuals)
        s += fmt::format("{},{:.3f},{:.3f},{:.4f},{:.4f},{:.4f},{},{},{}{}\n", r.row, r.speed_rpm, r.torque, r.loss,
                         r.loss_before, r.loss_after, opt(r.temp), opt(r.temp_before), opt(r.temp_after),
                         oils ? "," + quoted(r.oil) : std::string());
    return s;
}

namespace {
// The calibrated case, written atomically with a first line saying where it came from.
void write_case_yaml(const YAML::Node& root, const std::string& config_in, const std::string& config_out) {
    YAML::Emitter em;
    em << root;
    io::AtomicFile f(config_out);
    f.write("# Written by gearloss diagnose from " + config_in + "\n");
    f.write(em.c_str());
    f.write("\n");
    f.commit();
}
}  // namespace

void write_calibrated_config(const std::string& config_in, const std::string& config_out, const Diagnosis& d) {
    namespace fs = std::filesystem;
    YAML::Node root = YAML::Load(io::read_input_file(config_in, io::kMaxYamlFileBytes));
    // Keep the oil file reachable from the new location.
    if (root["oil"] && root["oil"].IsScalar()) {
        std::error_code ec;
        const fs::path oil = fs::absolute(fs::path(config_in).parent_path() / root["oil"].as<std::string>(), ec);
        const fs::path out_dir = fs::absolute(fs::path(config_out), ec).parent_path();
        const fs::path rel = fs::relative(oil, out_dir, ec);
        root["oil"] = (ec || rel.empty() ? oil : rel).string();
    }
    YAML::Node cal = root["calibration"] ? root["calibration"] : YAML::Node(YAML::NodeType::Map);
    // A remainder formula for the whole mismatch replaces the findings: the case's own
    // calibration stays as it is, and the formula's terms follow any it carries.
    if (d.remainder && d.remainder->on_case) {
        std::vector<losses::EmpiricalTerm> terms;
        for (const auto& t : d.remainder->terms)
            if (t.empirical) terms.push_back(*t.empirical);
        YAML::Node list = cal["empirical"] && cal["empirical"]["terms"] ? cal["empirical"]["terms"]
                                                                        : YAML::Node(YAML::NodeType::Sequence);
        for (const auto& n : io::empirical_terms_yaml(terms)) list.push_back(n);
        if (!terms.empty()) cal["empirical"]["terms"] = list;
        std::string note = "calibrated by gearloss diagnose (" + d.verdict + "): the remainder formula " + d.remainder->formula +
                           " for the whole mismatch (fitted to the recordings, not a published law); the findings are not "
                           "written, the formula alone predicts the recordings " +
                           std::string(hypothesis::on_case_comparison(*d.remainder)) + " they do";
        cal["note"] = note;
        root["calibration"] = cal;
        write_case_yaml(root, config_in, config_out);
        return;
    }
    // Every calibration term is written afresh: the hypothesis started from the case's own
    // calibration, so it holds the terms read from this block (in either spelling).
    for (const char* k : {"windage", "churning_factor", "bearing_drag_f0", "seal_factor", "mesh_friction_factor",
                          "auxiliary", "viscosity_factor", "heat_rejection_factor", "cooling_per_1000rpm",
                          "cooling_speed_exponent", "heat_rejection_rise_slope"})
        cal.remove(k);
    const auto& mechs = d.calibrated.mechanisms;
    for (size_t i = 0; i < mechs.size(); ++i) cal.remove(std::string(mechs[i].name()));
    for (const auto& e : io::calibration_entries(mechs, d.calibrated.cal)) {
        const std::string v = fmt::format("{:.6g}", e.value) + (e.unit.empty() ? "" : " " + e.unit);
        if (e.mechanism.empty()) cal[e.key] = v;
        else cal[e.mechanism][e.key] = v;
    }
    std::string note = "calibrated by gearloss diagnose (" + d.verdict + ")";
    for (const auto& f : d.findings)
        if (!f.effect.empty()) note += "; " + f.effect;
    for (const auto& f : d.findings)
        if (!f.oil.empty()) note += "; " + f.effect + " found for oil " + f.oil + " only, not written (the case has one oil)";
    const auto& a = d.calibrated.art;
    if (a.torque_gain != 1 || a.torque_offset != 0)
        note += fmt::format("; recordings carried a torque-sensor error (gain {:.5g}, offset {:.4g} N*m), not written as physics",
                            a.torque_gain, a.torque_offset);
    // The remainder formula, as empirical terms after any the case carried (a fit, not physics).
    if (d.remainder) {
        std::vector<losses::EmpiricalTerm> terms;
        if (const auto* e = dynamic_cast<const losses::EmpiricalMechanism*>(mechs.find("empirical"))) terms = e->terms();
        int written = 0, order = 0;
        for (const auto& t : d.remainder->terms) {
            if (t.empirical) {
                terms.push_back(*t.empirical);
                ++written;
            } else {
                ++order;
            }
        }
        if (!terms.empty()) cal["empirical"]["terms"] = io::empirical_terms_yaml(terms);
        if (written)
            note += fmt::format("; empirical: {} term(s) of the remainder formula {} (fitted to the recordings, not a "
                                "published law)",
                                written, d.remainder->formula);
        if (order) note += fmt::format("; {} term(s) of the run order not written (no law of the operating point)", order);
    }
    cal["note"] = note;
    root["calibration"] = cal;
    // Forms found are physics: written under `mechanisms:` (read after `options:`, it wins).
    if (!d.calibrated.forms.empty()) {
        YAML::Node mechanisms = root["mechanisms"] ? root["mechanisms"] : YAML::Node(YAML::NodeType::Map);
        for (const auto& f : d.calibrated.forms) {
            YAML::Node block = mechanisms[f.mechanism] ? mechanisms[f.mechanism] : YAML::Node(YAML::NodeType::Map);
            block[f.axis] = f.form;
            mechanisms[f.mechanism] = block;
        }
        root["mechanisms"] = mechanisms;
    }
    write_case_yaml(root, config_in, config_out);
}

}  // namespace gearloss::diagnosis
