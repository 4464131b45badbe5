#pragma once
// Duty spectra: the operation of a gearbox over its life or a recorded run, read from a CSV file
// whose header says which kind it is and in which units (as the recordings and drive-cycle files):
//  - time at level (the load spectra of ISO 6336-6:2019, §4: bins of speed and torque, each with
//    its time): `speed_in_<unit>, torque_in_<unit>` and one of `duration_<time unit>`, `hours`
//    (= duration_h), `share` (a fraction) or `share_%` (per cent; shares are normalised and scaled
//    to a total time given by the caller);
//  - time series: `time_<unit>, speed_in_<unit>, torque_in_<unit>`, the input's speed and torque
//    sampled in time (no vehicle).
// A negative torque is the gearbox driven from its output (recuperation, a wind turbine idling
// on the grid): power leaves at the input. Every failure is an InputError naming file, line,
// column and header.
#include <string>
#include <vector>

namespace gearloss::duty {

enum class SpectrumKind { time_at_level, time_series };

struct Spectrum {
    SpectrumKind kind = SpectrumKind::time_at_level;
    std::string file;
    std::vector<double> speed;     // rad/s, input
    std::vector<double> torque;    // N m, input (signed)
    std::vector<double> duration;  // s per bin (time at level); shares already scaled
    std::vector<double> time;      // s per sample (time series)
    std::vector<int> line;         // 1-based line of each row
    bool from_share = false;       // the durations came from shares (scaled to the total given)
    // Where each quantity stands (1-based column) and its header, for messages about a row.
    int speed_column = 0, torque_column = 0, weight_column = 0;
    std::string speed_header, torque_header, weight_header;
    std::vector<std::string> warnings;  // unknown columns ignored ("file:line:col: ...")
    double total_time() const;          // s: the sum of the durations, or the series' span
};

// Time-series samples further apart than kMaxGapFactor times the median interval are a gap in
// the record (a logger stopped): an error, since holding one sample over it invents the load.
inline constexpr double kMaxGapFactor = 10.0;

// Reads a spectrum file; `share_total` [s] is the total time the shares of a `share` column are
// scaled to. Checks: a known header; finite numbers; speeds and torques within the model's
// stated range; no negative duration; durations or shares not summing to 0; times increasing,
// without gaps; at least one bin (two samples).
Spectrum read_spectrum(const std::string& file, double share_total);
// The same from text; `name` appears in messages.
Spectrum read_spectrum_text(const std::string& text, const std::string& name, double share_total);

}  // namespace gearloss::duty
