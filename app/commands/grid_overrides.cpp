#include "commands/grid_overrides.hpp"

#include "commands/common.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::app {

void GridOverrides::add_to(CLI::App& sub, const std::string& speed_help, const std::string& torque_help) {
    // Every list takes ranges too (units/ranges.hpp): say so once, here.
    speed_option_ = sub.add_option("--speed", speeds_, speed_help + " (a list, a range START:STOP:STEP such as "
                                                                    "300:3000:100rpm, or both: 0,300:3000:100rpm)");
    torque_option_ = sub.add_option("--torque", torques_, torque_help + " (a list or a range, e.g. 50:400:50Nm)");
}

bool GridOverrides::speeds_given() const { return speed_option_ && speed_option_->count() > 0; }
bool GridOverrides::torques_given() const { return torque_option_ && torque_option_->count() > 0; }

void GridOverrides::apply(io::Case& k, Examples ex) const {
    if (!given()) return;
    auto& g = k.grid;
    if (!g.is_grid) {
        g.is_grid = true;
        for (const auto& [w, T] : g.points) {
            g.speeds.push_back(w);
            g.torques.push_back(T);
        }
    }
    if (speeds_given()) g.speeds = io::parse_value_list(speeds_, units::dim::angular_speed, "--speed", ex.speeds);
    if (torques_given()) g.torques = io::parse_value_list(torques_, units::dim::torque, "--torque", ex.torques);
}

map::CaseOverrides GridOverrides::case_overrides() const {
    map::CaseOverrides o;
    o.speeds = speeds_given();
    o.torques = torques_given();
    return o;
}

void GridOverrides::apply_checked(io::Case& k, Examples ex, size_t max_points) const {
    apply(k, ex);
    auto o = case_overrides();
    o.max_points = max_points;
    map::validate_case(k, o);
}

double point_speed(const std::string& text, const char* example) {
    return single_value(text, units::dim::angular_speed, "--speed", example);
}

double point_torque(const std::string& text, const char* example) {
    return single_value(text, units::dim::torque, "--torque", example);
}

}  // namespace gearloss::app
