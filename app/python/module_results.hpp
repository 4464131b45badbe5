#pragma once
// What the library computes, as Python objects for the module (gearloss_module.cpp): a point's
// values and a grid's columns under the map CSV's column names (map::csv_header), and a
// diagnosis as nested dicts and lists. Numbers stay in the library's full precision; a value
// the CSV leaves empty is NaN here. No physics: every number is read from a result.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::python {

// The column names of a map CSV of model `m` (with the --detail columns when `detail`), in order.
std::vector<std::string> map_columns(const solver::Model& m, bool detail);

// One result as {column: value} (floats, NaN for an empty cell; "status" a str), the columns of
// map_columns(m, detail).
pybind11::dict point_values(const solver::Model& m, const solver::PointResult& r, bool detail);

// Results in grid order as {column: numpy array} ("status": a list of str).
pybind11::dict grid_columns(const solver::Model& m, const std::vector<solver::PointResult>& results, bool detail);

// Everything `gearloss diagnose` reports (its text, findings, candidates, residuals, ...).
pybind11::dict diagnosis_dict(const diagnosis::Diagnosis& d);

}  // namespace gearloss::python
