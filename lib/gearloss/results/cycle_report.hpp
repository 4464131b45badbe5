#pragma once
// `gearloss cycle`: the powertrain of a case, the cold/warm/pre-warmed runs and their
// outputs (trace CSV, summary text and JSON).
#include <functional>
#include <optional>
#include <string_view>
#include <string>

#include "gearloss/cycle/simulate.hpp"
#include "gearloss/case/config.hpp"

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
    // The runs' time series (cycle_trace_csv needs them; the summaries do not): without them a
    // cycle's memory does not grow with its length (~0.25 kB a step a run with them).
    bool keep_traces = true;
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
// The same text streamed, for a cycle of any length: the runs simulated again, the start run's
// rows formatted as they come and handed to `write` a chunk (~1 MB) at a time, the reference
// runs' cells kept (3 numbers a step), so memory holds no full trace (`study` needs none:
// keep_traces = false). Byte for byte cycle_trace_csv's text of a study with traces.
void write_cycle_trace(const cycle::Powertrain& pt, const cycle::DriveCycle& dc, const CycleStudy& study,
                       const CycleStudyOptions& o, const std::function<void(std::string_view)>& write);
// Its header line (with the newline), for the sidecar.
std::string cycle_trace_header(const cycle::Powertrain& pt, const CycleStudy& study);
inline constexpr size_t kTraceChunkBytes = 1 << 20;
// The warning for rows whose engine torque lies beyond the fuel map (empty when there are none).
std::string engine_beyond_map_warning(const cycle::CycleTotals::EngineBeyondData& b, std::string_view indent = {});
std::string cycle_summary_text(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o);
std::string cycle_summary_json(const cycle::Powertrain& pt, const CycleStudy& s, const CycleStudyOptions& o);

}  // namespace gearloss::io
