#pragma once
// --speed and --torque: the one place the operating grid of a case is overridden from the
// command line (map, its --format vecto, synth, compare), and the single operating point of
// `point` and `mesh-profile`.
#include <CLI/CLI.hpp>
#include <string>

#include "gearloss/case/config.hpp"
#include "gearloss/map/map_runner.hpp"

namespace gearloss::app {

class GridOverrides {
public:
    // The examples quoted in the messages about a value that does not parse.
    struct Examples {
        const char* speeds;
        const char* torques;
    };

    // Adds --speed and --torque to `sub` with these help texts.
    void add_to(CLI::App& sub, const std::string& speed_help, const std::string& torque_help);

    // Given on the command line (even as an empty value: that is an error, never ignored).
    bool speeds_given() const;
    bool torques_given() const;
    bool given() const { return speeds_given() || torques_given(); }

    // Replaces the grid of `k` by the overrides. A case whose operating block is a point list
    // becomes the grid of its points' speeds x its points' torques first, and the given
    // option(s) then replace that axis (what map has done; compare and synth now do the same):
    // an override always applies. A value that does not parse (or is empty) is an InputError
    // naming the option. Values out of the stated range: map::validate_case with case_overrides()
    // (apply_checked does both).
    void apply(io::Case& k, Examples ex) const;

    // What map::validate_case needs to name --speed / --torque for the values they set.
    map::CaseOverrides case_overrides() const;

    // apply(), then map::validate_case(k) on the grid (naming --speed / --torque).
    void apply_checked(io::Case& k, Examples ex, size_t max_points = map::kMaxGridPoints) const;

private:
    std::string speeds_, torques_;
    CLI::Option* speed_option_ = nullptr;
    CLI::Option* torque_option_ = nullptr;
};

// --speed / --torque of a single operating point (point, mesh-profile): one value each.
double point_speed(const std::string& text, const char* example);
double point_torque(const std::string& text, const char* example);

}  // namespace gearloss::app
