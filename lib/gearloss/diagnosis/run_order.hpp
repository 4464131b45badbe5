#pragma once
// The run order of a campaign, where it is recorded. Rows of a recordings file may be sorted
// by anything (speed, torque, the order of an export), so the diagnosis takes the row order
// as the order of the tests only from a column that records it: `run` (a test number), `date`
// (a calendar date, optionally with a clock time) or `time` (a clock time of day, a date and
// time, or a number that grows with time). A raw log (`time_s`) records it by its time stamps.
// Without one, no drift or running-in hypothesis is formed.
#include <optional>
#include <string>

namespace gearloss::diagnosis {

// The column names that record the run order, in the order they are preferred.
inline constexpr const char* kRunOrderColumns[] = {"run", "date", "time"};

// A cell of one of those columns as a number that grows with the run order (seconds for a
// date or a clock time); nullopt when the cell is not such a value. Accepted:
//   run:  a number (1, 2, 17.5);
//   date: YYYY-MM-DD, optionally followed by 'T' or a space and a clock time;
//   time: hh:mm[:ss[.fff]], a date as above with a clock time, or a plain number.
std::optional<double> run_order_key(const std::string& column, const std::string& cell);

}  // namespace gearloss::diagnosis
