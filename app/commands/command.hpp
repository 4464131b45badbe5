#pragma once
// One subcommand of gearloss: its options (the members of the implementing class), their
// registration with the command line and its run. Each command lives in its own file
// (commands/<name>_command.cpp); main.cpp is the table of them.
#include <CLI/CLI.hpp>
#include <memory>

namespace gearloss::app {

class Command {
public:
    virtual ~Command() = default;
    // Adds the subcommand with its options, help texts and footer to `app`; returns it.
    virtual CLI::App* add_to(CLI::App& app) = 0;
    // Runs the parsed subcommand: its exit code. Errors are thrown (run_command, common.hpp,
    // turns them into exit codes and messages); output files go through io::AtomicFile.
    virtual int run() = 0;
};

// In the order of `gearloss --help`.
std::unique_ptr<Command> make_map_command();
std::unique_ptr<Command> make_point_command();
std::unique_ptr<Command> make_diagnose_command();
std::unique_ptr<Command> make_synth_command();
std::unique_ptr<Command> make_compare_command();
std::unique_ptr<Command> make_mesh_profile_command();
std::unique_ptr<Command> make_cycle_command();
std::unique_ptr<Command> make_duty_command();
std::unique_ptr<Command> make_rating_command();
std::unique_ptr<Command> make_merge_command();
std::unique_ptr<Command> make_check_command();
std::unique_ptr<Command> make_report_command();
std::unique_ptr<Command> make_import_command();

}  // namespace gearloss::app
