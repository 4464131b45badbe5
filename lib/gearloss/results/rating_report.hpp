#pragma once
// `gearloss rating`: the thermal power limit curve of a case (one row per input speed) and the
// cooler duty at a target oil temperature (one row per grid point), as CSV, text and JSON.
#include <string>
#include <vector>

#include "gearloss/case/config.hpp"
#include "gearloss/rating/thermal_rating.hpp"

namespace gearloss::io {

struct RatingStudy {
    rating::RatingOptions options;
    std::vector<rating::RatingPoint> curve;       // the thermal power limit per speed
    double target = 0;                            // K, --target-oil-temp (0: none)
    std::vector<rating::CoolerDutyPoint> duty;    // the cooler duty per grid point (with a target)
};

// The input speeds a rating covers: the grid's speeds (or the point list's), positive, sorted,
// each once.
std::vector<double> rating_speeds(const OperatingGrid& g);
// The largest positive torque of the grid (0 when none).
double largest_torque(const OperatingGrid& g);

// The limit curve (no target) or the cooler duty table (a target): header line first.
std::string rating_csv(const Case& k, const RatingStudy& s);
std::string rating_text(const Case& k, const RatingStudy& s);
std::string rating_json(const Case& k, const RatingStudy& s);

}  // namespace gearloss::io
