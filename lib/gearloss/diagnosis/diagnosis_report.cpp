#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/io/mechanism_config.hpp"

// The diagnosis as text, JSON and a residuals table, and the calibrated case file.
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/json.hpp"

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
            s += fmt::format("  {} = {} +/- {}\n", f.parameter.name, fmt_value(f.parameter.value, f.parameter.unit),
                             fmt_value(f.parameter.uncertainty, f.parameter.unit));
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
    if (d.remainder) {
        s += fmt::format("\nhypothesis for what is left (not a finding): {}\n  cross-validated loss RMSE {:.3g} W -> {:.3g} W\n",
                         d.remainder->formula, d.remainder->cv_rmse_before, d.remainder->cv_rmse_after);
        for (const auto& n : d.remainder->nearest) s += "  resembles: " + n + "\n";
    }
    s += fmt::format("\nnoise: loss {:.3g} % ({}), test of what is left: fit p = {:.2g}, structure p = {:.2g}{}\n",
                     100 * d.adequacy_loss.noise, d.adequacy_loss.noise_source, d.adequacy_loss.fit_p,
                     d.adequacy_loss.structure_p,
                     d.adequacy_loss.structure_along.empty() ? "" : " (along " + d.adequacy_loss.structure_along + ")");
    if (d.has_temperature)
        s += fmt::format("       oil temperature {:.3g} K ({}), fit p = {:.2g}, structure p = {:.2g}{}\n", d.adequacy_temp.noise,
                         d.adequacy_temp.noise_source, d.adequacy_temp.fit_p, d.adequacy_temp.structure_p,
                         d.adequacy_temp.structure_along.empty() ? "" : " (along " + d.adequacy_temp.structure_along + ")");
    if (std::isfinite(d.detectable))
        s += fmt::format("       power: a remainder of {:.2g} times the noise fails the fit test{} in half such campaigns\n",
                         d.detectable, d.has_temperature ? "s" : "");
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
    io::Json j;
    j.begin_object();
    j.key("verdict").value(d.verdict);
    j.key("summary").value(d.summary);
    j.key("location").value(d.location);
    j.key("remaining").value(d.remaining);
    j.key("points").value(d.points);
    j.key("rmse_before").value(d.rmse_before);
    j.key("rmse_after").value(d.rmse_after);
    j.key("cv_rmse_after").value(d.cv_rmse_after);
    if (d.has_temperature) {
        j.key("temp_rmse_before").value(d.temp_rmse_before);
        j.key("temp_rmse_after").value(d.temp_rmse_after);
    }
    // The noise the remainder was tested against, and the tests' p-values.
    j.key("adequacy").begin_object();
    auto channel = [&](const char* key, const Diagnosis::Channel& c) {
        j.key(key).begin_object();
        j.key("noise").value(c.noise);
        j.key("noise_source").value(c.noise_source);
        j.key("fit_p").value(c.fit_p);
        if (std::isfinite(c.fit_detectable)) j.key("fit_detectable").value(c.fit_detectable);
        j.key("structure_p").value(c.structure_p);
        j.key("structure_along").value(c.structure_along);
        j.end_object();
    };
    channel("loss_relative", d.adequacy_loss);
    if (d.has_temperature) channel("oil_temperature_K", d.adequacy_temp);
    if (std::isfinite(d.detectable)) j.key("detectable_remainder").value(d.detectable);
    j.end_object();
    if (d.remainder) {
        j.key("remainder_hypothesis").begin_object();
        j.key("formula").value(d.remainder->formula);
        j.key("cv_rmse_before").value(d.remainder->cv_rmse_before);
        j.key("cv_rmse_after").value(d.remainder->cv_rmse_after);
        j.key("terms").begin_array();
        for (const auto& t : d.remainder->terms) {
            j.begin_object();
            j.key("basis").value(t.basis);
            j.key("coefficient_W").value(t.coefficient);
            j.key("uncertainty_W").value(t.uncertainty);
            j.end_object();
        }
        j.end_array();
        j.key("nearest").begin_array();
        for (const auto& n : d.remainder->nearest) j.value(n);
        j.end_array();
        j.end_object();
    }
    if (!d.oils.empty()) {
        j.key("oils").begin_array();
        for (const auto& o : d.oils) j.value(o);
        j.end_array();
        j.key("oil_differences").begin_array();
        for (const auto& x : d.oil_differences) {
            j.begin_object();
            j.key("speed_rpm").value(x.speed_rpm);
            j.key("torque_Nm").value(x.torque);
            j.key("oil_a").value(x.oil_a);
            j.key("oil_b").value(x.oil_b);
            j.key("recorded_W").value(x.recorded);
            j.key("model_before_W").value(x.model_before);
            j.key("model_after_W").value(x.model_after);
            j.end_object();
        }
        j.end_array();
    }
    j.key("findings").begin_array();
    for (const auto& f : d.findings) {
        j.begin_object();
        j.key("effect").value(f.effect);
        j.key("description").value(f.description);
        // Multi-oil campaigns: the oil a finding concerns alone; null: every oil.
        if (f.oil.empty()) j.key("oil").null();
        else j.key("oil").value(f.oil);
        j.key("parameters").begin_object();
        j.key(f.parameter.name).begin_object();
        j.key("value").value(f.parameter.value);
        j.key("uncertainty").value(f.parameter.uncertainty);
        j.key("unit").value(f.parameter.unit);
        if (!f.parameter.form.empty()) {
            j.key("form").value(f.parameter.form);
            j.key("case_form").value(f.parameter.case_form);
        }
        j.end_object();
        j.end_object();
        if (!f.rows.empty()) {
            j.key("rows").begin_array();
            for (int r : f.rows) j.value(r);
            j.end_array();
        }
        j.key("rmse_before").value(f.rmse_before);
        j.key("rmse_after").value(f.rmse_after);
        j.key("cv_rmse_before").value(f.cv_rmse_before);
        j.key("cv_rmse_after").value(f.cv_rmse_after);
        if (d.has_temperature) {
            j.key("temp_rmse_before").value(f.temp_rmse_before);
            j.key("temp_rmse_after").value(f.temp_rmse_after);
        }
        j.key("delta_bic").value(f.delta_bic);
        j.key("cv_loglik_gain").value(f.cv_gain);
        j.key("stability").value(f.stability);
        j.key("equivalent").begin_array();
        for (const auto& e : f.equivalent) j.value(e);
        j.end_array();
        j.key("separating_measurement").value(f.separating_measurement);
        j.end_object();
    }
    j.end_array();
    j.key("outliers").begin_array();
    for (const auto& o : d.outliers) {
        j.begin_object();
        j.key("row").value(o.row);
        j.key("reason").value(o.reason);
        j.end_object();
    }
    j.end_array();
    j.key("candidates").begin_array();
    for (const auto& c : d.candidates) {
        j.begin_object();
        j.key("effect").value(c.effect);
        if (c.rejected.empty()) {
            j.key("delta_bic").value(c.delta_bic);
            j.key("fitted").value(c.value);
        } else {
            j.key("delta_bic").null();
            j.key("fitted").null();
            j.key("rejected").value(c.rejected);
        }
        j.end_object();
    }
    j.end_array();
    j.key("warnings").begin_array();
    for (const auto& w : d.warnings) j.value(w);
    j.end_array();
    j.end_object();
    return j.str() + "\n";
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
    // Every calibration term is written afresh: the hypothesis started from the case's own
    // calibration, so it holds the terms read from this block (in either spelling).
    for (const char* k : {"windage", "churning_factor", "bearing_drag_f0", "seal_factor", "mesh_friction_factor",
                          "auxiliary", "viscosity_factor", "heat_rejection_factor", "cooling_per_1000rpm"})
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
    YAML::Emitter em;
    em << root;
    io::AtomicFile f(config_out);
    f.write("# Written by gearloss diagnose from " + config_in + "\n");
    f.write(em.c_str());
    f.write("\n");
    f.commit();
}

}  // namespace gearloss::diagnosis
