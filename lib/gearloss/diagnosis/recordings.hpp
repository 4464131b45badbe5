#pragma once
// Rig recordings: steady points, or a raw log split into tests and reduced by
// the stabilisation criterion of seed 001 (Pereira 2017, §3.5.2).
#include <optional>
#include <string>
#include <vector>

namespace gearloss::diagnosis {

struct RecordedPoint {
    int row = 0;                  // data row in the source file (1 = first data line); tests: test number
    int line = 0;                 // line in the file (for messages)
    std::string label;
    // The oil of the test: an oil file as written in the `oil` column (a path relative to the
    // recordings file, or absolute); empty: the case's oil.
    std::string oil;
    double speed_in = 0;          // rad/s
    double torque_in = 0;         // N m (as recorded)
    double loss = 0;              // W (as recorded)
    std::optional<double> oil_temp;      // K
    std::optional<double> ambient_temp; // K
    std::optional<double> torque_out, speed_out;
    // Where the run order is recorded (Recordings::run_order_column): a number that grows with it.
    std::optional<double> run_order;
    bool stabilised = true;       // false: a log test that failed the criterion
    double stabilisation_drift = 0;  // K over the last 30 min (log tests)
};

struct Recordings {
    std::string file;
    bool from_log = false;
    std::vector<RecordedPoint> points;
    // Findings about the recordings themselves (each names file:line, and the column where one
    // cell is at fault), and unknown or repeated rows.
    std::vector<std::string> warnings;
    // The column that records the order of the tests (run_order.hpp): "run", "date" or "time"
    // (a raw log: "time", its time stamps); empty: not recorded, the row order means nothing.
    std::string run_order_column;
    int speed_out_column = 0;      // 1-based; 0: no output speed recorded
    std::string speed_out_header;  // as written
};

struct StabilisationCriterion {
    double window_s = 1800;      // 30 min
    double block_s = 300;        // 5-min blocks averaged, then compared
    double max_variation = 0.5;  // K of (T_oil - T_room) over the window
};

// Reads either format (a `time_s` column selects the raw log). Malformed rows
// and missing columns are InputErrors with the file and line; unknown columns
// become warnings. Each steady point is checked against the power balance before any fit
// (recordings.cpp check_point): a loss above the input power and an output standing still
// while the input turns are InputErrors at their cell; a loss over half the input power, a
// loss column contradicting the output torque and speed, and oil colder than the ambient are
// warnings naming file:line:column.
Recordings read_recordings(const std::string& file, const StabilisationCriterion& crit = {});
// Same from text; `name` appears in messages.
Recordings read_recordings_text(const std::string& text, const std::string& name, const StabilisationCriterion& crit = {});

}  // namespace gearloss::diagnosis
