#pragma once
// The outputs of gearloss duty: the per-row CSV (docs/duty.md), the text summary and the JSON one.
#include <string>

#include "gearloss/duty/duty.hpp"

namespace gearloss::duty {

// The CSV's header line (with its line end) and the whole table.
std::string duty_csv_header(const DutyResult& d);
std::string duty_csv(const DutyResult& d);
// The summary for standard output, and as one line of JSON.
std::string duty_summary_text(const DutyResult& d, const Spectrum& s);
std::string duty_summary_json(const DutyResult& d, const Spectrum& s);

}  // namespace gearloss::duty
