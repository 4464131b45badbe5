#pragma once
// START:STOP:STEP ranges in lists of values ("300:3000:10rpm", "20:100:20degC"), as people type
// them: the one place a range item is recognised and expanded, for every list of speeds, torques
// and temperatures (the command-line lists of io::parse_value_list and map::parse_temperature_list,
// a case's grid axes and the numeric values of a sweep).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gearloss::units {

// At most this many values in one list (a range or the whole list), so that a slip
// ("1:1e9:1rpm") is an error naming the option or key, not minutes of work or an exhausted memory.
constexpr std::size_t kMaxListItems = 1000000;

// True when `item` is written as a range: three parts separated by ':', each starting with a
// number ("300:3000:10rpm", "300rpm:3000rpm:10rpm", "0.5:2:0.25 mm").
bool is_range(std::string_view item);

// The unit written on a range's last part ("rpm" in "300:3000:10rpm"), empty when none.
std::string range_unit(std::string_view item);

// The items of the range `item` as texts "<number> <unit>" (parsed as if typed one by one):
// START, START+STEP, ... up to STOP inclusive (STOP is reached when it lies within 1e-9 of a
// STEP of it, so "0:1:0.1" ends with 1, not 0.9), each number rounded to the decimals START and
// STEP were written with (0.1 + 0.2 is "0.3"). The unit is the one written on the parts (on the
// last one only, or the same on every part), else `default_unit` (the unit of the list's last
// item). The numbers are counted in the written unit, so a range of temperatures in degC steps
// by degrees Celsius. Throws UnitError: not a range of three numbers, units that differ between
// the parts, a STEP that is zero, negative or not finite, STOP below START (an empty range), or
// more than `max_items` items (the message says how many and the bound).
std::vector<std::string> expand_range(std::string_view item, std::string_view default_unit,
                                      std::size_t max_items = kMaxListItems);

}  // namespace gearloss::units
