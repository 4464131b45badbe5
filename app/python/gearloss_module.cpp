// The compiled part of the Python module `gearloss` (gearloss._gearloss; docs/python.md): the
// second front end beside the CLI. Like app/commands/, it only calls the library: a case is
// loaded by io::load_case, a point solved by solver::solve_point, a grid by map::run_map, a
// campaign diagnosed by diagnosis::diagnose, and the checks are the CLI's (map::validate_case,
// map::validate_point); check, compare, spread, sweeps and cycle are in module_commands.cpp. The
// pure-Python package (app/python/gearloss/__init__.py) wraps these
// functions in the documented API (DataFrames, warnings, result objects).
//
// Errors: gearloss::InputError -> gearloss.InputError (a ValueError) with the CLI's
// "file:line:col: key: message" text and the attributes file, line, column, key, message;
// IoError -> gearloss.OutputError (an OSError); an interrupt (Ctrl-C during a long solve) ->
// KeyboardInterrupt; anything else -> RuntimeError. The GIL is released while the library
// computes.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/core/errors.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/diagnosis/synth.hpp"
#include "gearloss/case/case_plausibility.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/map/map_runner.hpp"
#include "module_case.hpp"
#include "module_commands.hpp"
#include "module_results.hpp"

namespace py = pybind11;

namespace gearloss::python {
namespace {

// ---------------------------------------------------------------------------------------
// Errors

PyObject* g_error = nullptr;        // gearloss.Error
PyObject* g_input_error = nullptr;  // gearloss.InputError(Error, ValueError)
PyObject* g_output_error = nullptr; // gearloss.OutputError(Error, OSError)

py::object or_none(const std::string& s) { return s.empty() ? py::none() : py::cast(s); }
py::object or_none(int v) { return v > 0 ? py::cast(v) : py::none(); }

// Raises the Python exception of `type` carrying e's text and location.
void raise_located(PyObject* type, const Error& e) {
    py::object exc = py::reinterpret_borrow<py::object>(type)(e.what());
    exc.attr("file") = or_none(e.file);
    exc.attr("line") = or_none(e.line);
    exc.attr("column") = or_none(e.column);
    exc.attr("key") = or_none(e.key);
    exc.attr("message") = e.message;
    PyErr_SetObject(type, exc.ptr());
}

// ---------------------------------------------------------------------------------------
// Cases

PyCase load_source(CaseSource source) {
    PyCase c{renaming_keys({{"--ratio", "ratio"}}, [&] { return read_case(source); }), {}, std::move(source)};
    check_loaded(c.k, "", "");
    return c;
}

PyCase load(const std::string& path, const std::optional<std::string>& ratio) {
    return load_source({.path = path, .text = {}, .name = {}, .base_dir = {}, .ratio = ratio});
}

PyCase load_text(const std::string& text, const std::string& name, const std::string& base_dir,
                 const std::optional<std::string>& ratio) {
    return load_source({.path = {}, .text = text, .name = name, .base_dir = base_dir, .ratio = ratio});
}

PyCase with_oil(const PyCase& base, const std::string& oil_path) {
    PyCase c = base;
    c.oil_file = oil_path;
    c.k.warnings.clear();
    io::replace_oil_file(c.k, oil_path);  // as the CLI's --oil
    check_loaded(c.k, oil_path, "");
    return c;
}

std::vector<double> axis_in(const std::vector<double>& v, double factor) {
    std::vector<double> out;
    for (double x : v) out.push_back(x / factor);
    return out;
}

py::dict point(const PyCase& c, double speed_rpm, double torque_Nm, const std::optional<double>& oil_temp_C) {
    const double w = speed_rpm * kRadSPerRpm;
    renaming_keys({{"--speed", "speed_rpm"}, {"--torque", "torque_Nm"}}, [&] { map::validate_point(w, torque_Nm); });
    const io::Case k = at_oil_temperature(c, oil_temp_C);
    solver::PointResult r;
    {
        py::gil_scoped_release free;
        r = solver::solve_point(k.model, w, torque_Nm, true);
    }
    py::dict values = point_values(k.model, r, true);
    values["warnings"] = k.warnings;
    return values;
}

py::dict grid(const PyCase& c, const std::optional<std::vector<double>>& speeds_rpm,
              const std::optional<std::vector<double>>& torques_Nm, const std::optional<double>& oil_temp_C,
              const std::optional<int>& threads, bool detail) {
    io::Case k = at_oil_temperature(c, oil_temp_C);
    k.grid = grid_of(k, speeds_rpm, torques_Nm);
    require_values(speeds_rpm, torques_Nm);
    map::MapOptions opt;
    opt.threads = threads.value_or(0);
    opt.detail = detail;
    const KeyNames names = {{"--speed", "speeds_rpm"}, {"--torque", "torques_Nm"}, {"--threads", "threads"},
                            {"--oil-temp", "oil_temp_C"}};
    renaming_keys(names, [&] {
        opt.validate();
        map::validate_case(k, {.oil_temp = oil_temp_C ? "oil_temp_C" : "", .oil = c.oil_file,
                               .speeds = speeds_rpm.has_value(), .torques = torques_Nm.has_value()});
        (void)map_columns(k.model, detail);  // a --detail column that would appear twice: before the solve
    });
    SignalWatch watch;
    opt.progress = [&watch](size_t, size_t) { watch.poll(); };
    std::vector<solver::PointResult> results;
    {
        py::gil_scoped_release free;
        results = map::run_map(k.model, k.grid, opt);
    }
    watch.finish();
    py::dict out;
    out["columns"] = grid_columns(k.model, results, detail);
    out["warnings"] = k.warnings;
    return out;
}

py::dict diagnose(const PyCase& c, const std::string& recordings, int bootstrap, const std::optional<int>& threads,
                  const std::optional<double>& loss_uncertainty, const std::optional<double>& temp_uncertainty_K) {
    const auto rec = diagnosis::read_recordings(recordings);
    diagnosis::DiagnoseOptions opt;
    opt.bootstrap = bootstrap;
    opt.threads = threads.value_or(0);
    if (loss_uncertainty) opt.loss_uncertainty = *loss_uncertainty;
    if (temp_uncertainty_K) opt.temp_uncertainty = *temp_uncertainty_K;
    SignalWatch watch;
    opt.progress = [&watch](const std::string&) { watch.poll(); };
    diagnosis::Diagnosis d;
    const KeyNames names = {{"--bootstrap", "bootstrap"}, {"--threads", "threads"},
                            {"--loss-uncertainty", "loss_uncertainty"}, {"--temp-uncertainty", "temp_uncertainty_K"}};
    try {
        renaming_keys(names, [&] {
            py::gil_scoped_release free;
            d = diagnosis::diagnose(c.k.model, rec, opt);
        });
    } catch (const InputError& e) {
        watch.finish();
        if (!e.file.empty() || e.where().known()) throw;
        throw InputError(recordings, 0, 0, e.key, e.message);  // about the recordings as a whole (as the CLI)
    } catch (const Interrupted&) {
        watch.finish();
        throw;
    }
    watch.finish();
    py::dict out = diagnosis_dict(d);
    py::list warnings;
    for (const auto& w : rec.warnings) warnings.append(w);
    out["recordings_warnings"] = warnings;
    return out;
}

std::string synth(const PyCase& c, const std::vector<std::string>& effects, double noise_loss, double noise_temp_K,
                  unsigned seed, bool log, const std::optional<std::vector<double>>& speeds_rpm,
                  const std::optional<std::vector<double>>& torques_Nm) {
    io::Case k = c.k;
    k.grid = grid_of(k, speeds_rpm, torques_Nm);
    renaming_keys({{"--speed", "speeds_rpm"}, {"--torque", "torques_Nm"}}, [&] {
        map::validate_case(k, {.oil_temp = "", .oil = c.oil_file, .speeds = speeds_rpm.has_value(), .torques = torques_Nm.has_value()});
    });
    diagnosis::SynthOptions so;
    renaming_keys({{"--effect", "effects"}, {"--noise-loss", "noise_loss"}, {"--noise-temp", "noise_temp_K"}}, [&] {
        for (const auto& e : effects) so.effects.push_back(diagnosis::parse_effect_assignment(k.model, e));
    });
    so.noise_loss = noise_loss;
    so.noise_temp = noise_temp_K;
    so.seed = seed;
    so.raw_log = log;
    py::gil_scoped_release free;
    return renaming_keys({{"--noise-loss", "noise_loss"}, {"--noise-temp", "noise_temp_K"}},
                         [&] { return diagnosis::synthesize(k.model, k.grid, so); });
}

// ---------------------------------------------------------------------------------------
// Case properties

py::dict case_info(const PyCase& c) {
    const auto& m = c.k.model;
    const auto& g = c.k.grid;
    py::dict d;
    d["file"] = c.k.file;
    d["name"] = m.name;
    d["ratio"] = or_none(m.ratio);
    d["ratios"] = m.ratio_names();
    py::list mechanisms, columns;
    for (size_t i = 0; i < m.mechanisms.size(); ++i) {
        mechanisms.append(std::string(m.mechanisms[i].name()));
        columns.append(std::string(m.mechanisms[i].column()));
    }
    d["mechanisms"] = mechanisms;
    d["mechanism_columns"] = columns;
    d["oil"] = m.oil.name;
    d["oil_file"] = or_none(c.oil_file);
    d["thermal_mode"] = m.thermal.mode == solver::ThermalMode::fixed ? "fixed" : "stabilised";
    d["oil_temp_C"] = m.thermal.mode == solver::ThermalMode::fixed ? py::cast(m.thermal.oil_temperature - kZeroCelsius)
                                                                   : py::none();
    d["ambient_temp_C"] = m.thermal.ambient - kZeroCelsius;
    d["is_grid"] = g.is_grid;
    d["speeds_rpm"] = axis_in(g.speeds, kRadSPerRpm);
    d["torques_Nm"] = g.torques;
    py::list points;
    for (const auto& [w, T] : g.points) points.append(py::make_tuple(w / kRadSPerRpm, T));
    d["points"] = points;
    py::list sweep;
    for (const auto& a : c.k.sweep) sweep.append(py::make_tuple(a.label, a.values));
    d["sweep"] = sweep;
    d["warnings"] = c.k.warnings;
    d["columns"] = map_columns(m, false);
    return d;
}

}  // namespace
}  // namespace gearloss::python

PYBIND11_MODULE(_gearloss, m) {
    using namespace gearloss::python;
    namespace gl = gearloss;
    m.doc() = "gearloss' compiled part: use the package `gearloss` (docs/python.md), not this module directly.";

    g_error = PyErr_NewExceptionWithDoc("gearloss.Error", "Root of the errors gearloss raises on purpose.",
                                        PyExc_Exception, nullptr);
    m.attr("Error") = py::handle(g_error);
    g_input_error = PyErr_NewExceptionWithDoc(
        "gearloss.InputError",
        "A case, an oil file, recordings or an argument that is wrong: str(e) is the CLI's "
        "'file:line:col: key: message'; e.file, e.line, e.column, e.key (None when unknown), e.message.",
        py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError)).release().ptr(), nullptr);
    g_output_error = PyErr_NewExceptionWithDoc("gearloss.OutputError", "An output that could not be written.",
                                               py::make_tuple(py::handle(g_error), py::handle(PyExc_OSError)).release().ptr(),
                                               nullptr);
    m.attr("InputError") = py::handle(g_input_error);
    m.attr("OutputError") = py::handle(g_output_error);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const gl::Interrupted&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        } catch (const gl::InputError& e) {
            raise_located(g_input_error, e);
        } catch (const gl::IoError& e) {
            raise_located(g_output_error, e);
        } catch (const gl::Error& e) {
            raise_located(g_error, e);
        }
    });

    py::class_<PyCase>(m, "_Case")
        .def_property_readonly("info", &case_info)
        .def("with_oil", &with_oil, py::arg("path"))
        .def("point", &point, py::arg("speed_rpm"), py::arg("torque_Nm"), py::arg("oil_temp_C") = py::none())
        .def("grid", &grid, py::arg("speeds_rpm") = py::none(), py::arg("torques_Nm") = py::none(),
             py::arg("oil_temp_C") = py::none(), py::arg("threads") = py::none(), py::arg("detail") = false);
    m.def("load_case", &load, py::arg("path"), py::arg("ratio") = py::none());
    m.def("load_case_text", &load_text, py::arg("text"), py::arg("name"), py::arg("base_dir"),
          py::arg("ratio") = py::none());
    m.def("check", &check, py::arg("case"), py::arg("json") = false);
    m.def("compare", &compare, py::arg("case"), py::arg("oils"), py::arg("speeds_rpm") = py::none(),
          py::arg("torques_Nm") = py::none(), py::arg("oil_temp_C") = py::none(), py::arg("threads") = py::none(),
          py::arg("detail") = false);
    m.def("spread", &spread, py::arg("case"), py::arg("axes") = py::none(), py::arg("speeds_rpm") = py::none(),
          py::arg("torques_Nm") = py::none(), py::arg("oil_temp_C") = py::none(), py::arg("threads") = py::none(),
          py::arg("detail") = false);
    m.def("sweeps", &sweeps, py::arg("case"), py::arg("speeds_rpm") = py::none(), py::arg("torques_Nm") = py::none(),
          py::arg("oil_temp_C") = py::none(), py::arg("threads") = py::none(), py::arg("detail") = false);
    m.def("cycle", &cycle, py::arg("case"), py::arg("cycle"), py::arg("start_temp_C"), py::arg("ambient_C") = py::none(),
          py::arg("prewarm_C") = py::none(), py::arg("heater_W") = 100.0, py::arg("warm_temp_C") = 90.0,
          py::arg("trace") = false);
    m.def("diagnose", &diagnose, py::arg("case"), py::arg("recordings"), py::arg("bootstrap") = 24,
          py::arg("threads") = py::none(), py::arg("loss_uncertainty") = py::none(),
          py::arg("temp_uncertainty_K") = py::none());
    m.def("synth", &synth, py::arg("case"), py::arg("effects"), py::arg("noise_loss") = 0.015,
          py::arg("noise_temp_K") = 0.4, py::arg("seed") = 1u, py::arg("log") = false,
          py::arg("speeds_rpm") = py::none(), py::arg("torques_Nm") = py::none());
    m.attr("__version__") = GEARLOSS_VERSION;
}
