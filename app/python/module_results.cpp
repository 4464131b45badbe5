#include "module_results.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "gearloss/map/map_runner.hpp"

namespace py = pybind11;

namespace gearloss::python {
namespace {

constexpr double kRpmPerRadS = 30.0 / std::numbers::pi;  // as the map CSV's speed column
constexpr double kZeroCelsius = 273.15;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A CSV cell as a number: NaN where the CSV leaves the cell empty (not finite, or absent).
double cell(bool present, double v) { return present && std::isfinite(v) ? v : kNaN; }

// Where each --detail column of a model reads its value: mechanism, component, quantity and
// the CSV's scale, in the order of map::csv_header (mechanism, component, quantity).
struct DetailCell {
    size_t mechanism, component, quantity;
    double scale;
};

std::vector<DetailCell> detail_cells(const solver::Model& m) {
    std::vector<DetailCell> out;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        const auto quantities = m.mechanisms[i].quantities();
        const size_t components = m.mechanisms[i].components(m).size();
        for (size_t c = 0; c < components; ++c)
            for (size_t q = 0; q < quantities.size(); ++q)
                if (!quantities[q].column.empty()) out.push_back({i, c, q, quantities[q].csv_scale});
    }
    return out;
}

// The layout of one model's rows: the column names and where "status" sits among them.
struct RowLayout {
    std::vector<std::string> names;  // every column, "status" included
    size_t status_at = 0;            // index of "status" in names
    std::vector<DetailCell> detail;  // the --detail columns (empty without)

    RowLayout(const solver::Model& m, bool with_detail) : names(map_columns(m, with_detail)) {
        status_at = 5 + m.mechanisms.size() + 5;
        if (with_detail) detail = detail_cells(m);
        if (names.size() != status_at + 1 + detail.size() || names[status_at] != "status")
            throw std::logic_error("gearloss module: the map CSV's columns changed; update app/python/module_results.cpp");
    }

    // The numbers of a row in column order, "status" left out.
    void numbers(const solver::Model& m, const solver::PointResult& r, std::vector<double>& v) const {
        v.clear();
        const bool ok = solver::has_values(r.status);
        const auto& L = r.losses;
        v.push_back(cell(true, r.speed_in * kRpmPerRadS));
        v.push_back(cell(true, r.torque_in));
        v.push_back(cell(true, r.power_in));
        v.push_back(cell(true, r.ambient - kZeroCelsius));
        v.push_back(cell(ok, r.oil_temperature - kZeroCelsius));
        for (size_t i = 0; i < m.mechanisms.size(); ++i) v.push_back(cell(ok && i < L.power.size(), ok ? L.power[i] : 0));
        v.push_back(cell(ok, L.total()));
        v.push_back(cell(ok, r.power_out));
        v.push_back(cell(ok, r.torque_out));
        v.push_back(cell(ok && r.has_efficiency, r.efficiency));
        v.push_back(cell(ok && L.has_lambda, L.lambda_min));
        const bool have = ok && L.detail.size() == m.mechanisms.size();
        for (const auto& d : detail)
            v.push_back(have ? cell(true, L.detail[d.mechanism].at(d.component, d.quantity) * d.scale) : kNaN);
    }
};

}  // namespace

std::vector<std::string> map_columns(const solver::Model& m, bool detail) {
    // The CSV header itself (it also refuses a model whose --detail columns would collide).
    std::string h = map::csv_header(m, detail);
    if (!h.empty() && h.back() == '\n') h.pop_back();
    std::vector<std::string> out;
    for (size_t a = 0; a <= h.size();) {
        const size_t e = std::min(h.find(',', a), h.size());
        out.push_back(h.substr(a, e - a));
        a = e + 1;
    }
    return out;
}

py::dict point_values(const solver::Model& m, const solver::PointResult& r, bool detail) {
    const RowLayout layout(m, detail);
    std::vector<double> v;
    layout.numbers(m, r, v);
    py::dict out;
    for (size_t c = 0, n = 0; c < layout.names.size(); ++c) {
        if (c == layout.status_at) out[py::str(layout.names[c])] = solver::status_text(r);
        else out[py::str(layout.names[c])] = v[n++];
    }
    return out;
}

py::dict grid_columns(const solver::Model& m, const std::vector<solver::PointResult>& results, bool detail) {
    const RowLayout layout(m, detail);
    const size_t rows = results.size(), numbers = layout.names.size() - 1;
    std::vector<py::array_t<double>> arrays;
    std::vector<double*> data;
    for (size_t c = 0; c < numbers; ++c) {
        arrays.emplace_back(static_cast<py::ssize_t>(rows));
        data.push_back(arrays.back().mutable_data());
    }
    py::list status(rows);
    std::vector<double> v;
    for (size_t i = 0; i < rows; ++i) {
        layout.numbers(m, results[i], v);
        for (size_t c = 0; c < numbers; ++c) data[c][i] = v[c];
        status[i] = py::str(solver::status_text(results[i]));
    }
    py::dict out;
    for (size_t c = 0, n = 0; c < layout.names.size(); ++c) {
        if (c == layout.status_at) out[py::str(layout.names[c])] = status;
        else out[py::str(layout.names[c])] = arrays[n++];
    }
    return out;
}

namespace {

py::dict channel_dict(const diagnosis::Diagnosis::Channel& c) {
    py::dict d;
    d["noise"] = c.noise;
    d["noise_source"] = c.noise_source;
    d["fit_p"] = c.fit_p;
    d["fit_detectable"] = std::isfinite(c.fit_detectable) ? py::cast(c.fit_detectable) : py::none();
    d["structure_p"] = c.structure_p;
    d["structure_along"] = c.structure_along;
    return d;
}

py::dict finding_dict(const diagnosis::Finding& f, bool temperature) {
    py::dict d;
    d["effect"] = f.effect;
    d["description"] = f.description;
    d["oil"] = f.oil.empty() ? py::none() : py::cast(f.oil);
    py::dict p;
    p["name"] = f.parameter.name;
    p["value"] = f.parameter.value;
    p["uncertainty"] = f.parameter.uncertainty;
    p["unit"] = f.parameter.unit;
    p["form"] = f.parameter.form.empty() ? py::none() : py::cast(f.parameter.form);
    p["case_form"] = f.parameter.case_form.empty() ? py::none() : py::cast(f.parameter.case_form);
    d["parameter"] = p;
    // A shape setting fitted with the parameter on a grid (where mixed friction sets in), or None.
    if (f.shape) {
        py::dict s;
        s["name"] = f.shape->name;
        s["value"] = f.shape->value;
        s["grid"] = f.shape->grid;
        d["shape"] = s;
    } else {
        d["shape"] = py::none();
    }
    d["rows"] = f.rows;
    d["rmse_before_W"] = f.rmse_before;
    d["rmse_after_W"] = f.rmse_after;
    d["cv_rmse_before_W"] = f.cv_rmse_before;
    d["cv_rmse_after_W"] = f.cv_rmse_after;
    d["temp_rmse_before_K"] = temperature ? py::cast(f.temp_rmse_before) : py::none();
    d["temp_rmse_after_K"] = temperature ? py::cast(f.temp_rmse_after) : py::none();
    d["delta_bic"] = f.delta_bic;
    d["cv_loglik_gain"] = f.cv_gain;
    d["stability"] = f.stability;
    d["mechanism_stability"] = f.mechanism_stability;
    d["equivalent"] = f.equivalent;
    d["separating_measurement"] = f.separating_measurement;
    return d;
}

// The residuals as columns (the names of `gearloss diagnose --residuals`).
py::dict residual_columns(const diagnosis::Diagnosis& d) {
    py::list row, speed, torque, loss, before, after, temp, temp_before, temp_after, oil;
    for (const auto& r : d.residuals) {
        row.append(r.row);
        speed.append(r.speed_rpm);
        torque.append(r.torque);
        loss.append(r.loss);
        before.append(r.loss_before);
        after.append(r.loss_after);
        temp.append(r.temp ? *r.temp : kNaN);
        temp_before.append(r.temp_before ? *r.temp_before : kNaN);
        temp_after.append(r.temp_after ? *r.temp_after : kNaN);
        oil.append(r.oil);
    }
    py::dict c;
    c["row"] = row;
    c["speed_in_rpm"] = speed;
    c["torque_in_Nm"] = torque;
    c["P_loss_W"] = loss;
    c["P_model_before_W"] = before;
    c["P_model_after_W"] = after;
    c["oil_temp_C"] = temp;
    c["oil_temp_model_before_C"] = temp_before;
    c["oil_temp_model_after_C"] = temp_after;
    if (!d.oils.empty()) c["oil"] = oil;
    return c;
}

}  // namespace

py::dict diagnosis_dict(const diagnosis::Diagnosis& d) {
    py::dict out;
    out["verdict"] = d.verdict;
    out["summary"] = d.summary;
    out["location"] = d.location;
    out["remaining"] = d.remaining;
    out["points"] = d.points;
    out["rmse_before_W"] = d.rmse_before;
    out["rmse_after_W"] = d.rmse_after;
    out["cv_rmse_after_W"] = d.cv_rmse_after;
    out["temp_rmse_before_K"] = d.has_temperature ? py::cast(d.temp_rmse_before) : py::none();
    out["temp_rmse_after_K"] = d.has_temperature ? py::cast(d.temp_rmse_after) : py::none();
    py::dict adequacy;
    adequacy["loss_relative"] = channel_dict(d.adequacy_loss);
    adequacy["oil_temperature_K"] = d.has_temperature ? py::object(channel_dict(d.adequacy_temp)) : py::none();
    adequacy["detectable_remainder"] = std::isfinite(d.detectable) ? py::cast(d.detectable) : py::none();
    out["adequacy"] = adequacy;
    py::list findings;
    for (const auto& f : d.findings) findings.append(finding_dict(f, d.has_temperature));
    out["findings"] = findings;
    py::list candidates;
    for (const auto& c : d.candidates) {
        py::dict x;
        x["effect"] = c.effect;
        x["delta_bic"] = c.rejected.empty() ? py::cast(c.delta_bic) : py::none();
        x["fitted"] = c.rejected.empty() ? py::cast(c.value) : py::none();
        x["rejected"] = c.rejected.empty() ? py::none() : py::cast(c.rejected);
        candidates.append(x);
    }
    out["candidates"] = candidates;
    py::list outliers;
    for (const auto& o : d.outliers) outliers.append(py::make_tuple(o.row, o.reason));
    out["outliers"] = outliers;
    // The noise the verdict was judged against, the main finding's confidence, a smaller
    // structure left apart from it, and the run order (as in `diagnose --json`).
    py::dict noise;
    noise["loss_relative"] = d.noise_used.loss_relative;
    noise["source"] = d.noise_used.source;
    noise["why"] = d.noise_used.why;
    noise["oil_temperature_K"] = d.has_temperature ? py::cast(d.noise_used.temp_K) : py::none();
    out["noise_used"] = noise;
    if (d.main_finding.effect.empty()) {
        out["main_finding"] = py::none();
    } else {
        py::dict m;
        m["effect"] = d.main_finding.effect;
        m["confidence"] = d.main_finding.confidence;
        out["main_finding"] = m;
    }
    out["completeness"] = d.completeness;
    out["unsettled"] = d.unsettled.empty() ? py::object(py::none()) : py::cast(d.unsettled);
    if (d.remaining_structure) {
        py::dict r;
        r["channel"] = d.remaining_structure->channel;
        r["rms_over_noise"] = d.remaining_structure->rms_over_noise;
        r["along"] = d.remaining_structure->along;
        r["text"] = d.remaining_structure->text;
        out["remaining_structure"] = r;
    } else {
        out["remaining_structure"] = py::none();
    }
    py::dict run_order;
    run_order["recorded"] = d.run_order.recorded;
    run_order["column"] = d.run_order.recorded ? py::cast(d.run_order.column) : py::none();
    out["run_order"] = run_order;
    if (d.remainder) {
        py::dict r;
        r["formula"] = d.remainder->formula;
        r["cv_rmse_before_W"] = d.remainder->cv_rmse_before;
        r["cv_rmse_after_W"] = d.remainder->cv_rmse_after;
        py::list terms;
        for (const auto& t : d.remainder->terms) terms.append(py::make_tuple(t.basis, t.coefficient, t.uncertainty));
        r["terms"] = terms;
        r["nearest"] = d.remainder->nearest;
        out["remainder_hypothesis"] = r;
    } else {
        out["remainder_hypothesis"] = py::none();
    }
    out["oils"] = d.oils;
    py::list differences;
    for (const auto& x : d.oil_differences) {
        py::dict o;
        o["speed_rpm"] = x.speed_rpm;
        o["torque_Nm"] = x.torque;
        o["oil_a"] = x.oil_a;
        o["oil_b"] = x.oil_b;
        o["recorded_W"] = x.recorded;
        o["model_before_W"] = x.model_before;
        o["model_after_W"] = x.model_after;
        differences.append(o);
    }
    out["oil_differences"] = differences;
    out["warnings"] = d.warnings;
    out["residuals"] = residual_columns(d);
    out["text"] = diagnosis::diagnosis_text(d);
    return out;
}

}  // namespace gearloss::python
