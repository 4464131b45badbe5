#pragma once
// `gearloss cycle`: the powertrain of a case, the cold/warm/pre-warmed runs and their
// outputs (trace CSV, summary text and JSON).
#include <optional>
#include <string>

#include "gearloss/cycle/simulate.hpp"
#include "gearloss/io/config.hpp"

namespace gearloss::io {

// One gearbox model per vehicle gear (the case re-read with each ratio), the oil replaced
// by `oil_file` when given.
cycle::Powertrain load_powertrain(const Case& c, const std::optional<std::string>& oil_file);

struct CycleStudyOptions {
    double start_temperature = 263.15;   // K, all nodes (cold soak)
    double ambient = 263.15;             // K
    double warm_temperature = 363.15;    // K, reference warm start
    std::optional<double> prewarm_target;  // K
    double heater_power = 100.0;         // W
    // Ceres-style check of the options (run_cycle_study calls it): throws InputError naming the
    // option. Temperatures within the stated ambient range (-100..300 degC), the pre-warm target
    // above the start, the heater power positive and at most 1 MW.
    void validate() const;
};

struct CycleStudy {
    std::string cycle_name;
    cycle::CycleResult cold;             // from the start temperature
    cycle::CycleTotals warm;             // from the warm temperature
    std::vector<cycle::TraceRow> warm_trace;  // its time series (the same time steps as cold.trace)
    std::optional<cycle::PrewarmResult> prewarm;
    std::optional<cycle::CycleTotals> prewarmed;  // from the pre-warmed state
    std::vector<cycle::TraceRow> prewarmed_trace;  // its time series (empty without pre-warming)
    double ideal_prewarm_time = 0;       // s, C_oil dT / P without heat loss
    double seconds_per_run = 0;          // wall-clock time of the run from the start temperature
};

CycleStudy run_cycle_study(const cycle::Powertrain& pt, const cycle::DriveCycle& dc, const CycleStudyOptions& o);

// Time series of the run from the start temperature (its columns first, as they have always
// been), then the warm-start reference run's oil temperature and transmission losses
// (`warm_oil_temp_C`, `warm_P_gearbox_W`, `warm_P_converter_W` with a converter) and, after
// pre-warming, the pre-warmed run's (`prewarmed_...`), on the same time steps, so that one file
// holds what the summary compares.
std::string cycle_trace_csv(const cycle::Powertrain& pt, const CycleStudy& s);
std::string cycle_summary_text(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o);
std::string cycle_summary_json(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o);

}  // namespace gearloss::io
