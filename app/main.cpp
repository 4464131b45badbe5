// gearloss command-line interface: a thin layer over the library. This file is the table of
// subcommands; each one is a class in commands/<name>_command.cpp (commands/command.hpp),
// the pieces they share are in commands/common.hpp and commands/grid_overrides.hpp.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/io/csv_read.hpp"
#include "gearloss/io/interrupt.hpp"

namespace app = gearloss::app;

int main(int argc, char** argv) {
    // SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE (a reader closed a pipe written to) end a run
    // alike: its loops stop, no output file is written, exit 128 + the signal.
    // A SIGHUP ignored from the start (`nohup gearloss ...`) stays ignored: the run is to outlive
    // its terminal.
    for (const int sig : gearloss::io::kInterruptSignals)
        if (std::signal(sig, gearloss::io::on_interrupt_signal) == SIG_IGN && sig == SIGHUP) std::signal(sig, SIG_IGN);
    // A file-size limit (or quota) must fail the write (EFBIG) so the partial
    // temporary file is removed, rather than kill the process mid-write.
    std::signal(SIGXFSZ, SIG_IGN);
    app::set_command_line(argc, argv);  // for the sidecar metadata of outputs

    CLI::App cli{"gearloss — where the power goes in a gearbox: mesh, churning, bearing and seal losses with the\n"
                 "thermally stabilised oil temperature, from a YAML description.\n\n"
                 "Examples:\n"
                 "  gearloss check configs/transfer-box.yaml\n"
                 "  gearloss point configs/transfer-box.yaml --speed 800rpm --torque 250Nm\n"
                 "  gearloss map configs/transfer-box.yaml -o map.csv\n"
                 "  gearloss cycle configs/automatic-6speed.yaml --cycle wltc --start-temp -10degC\n"
                 "  gearloss map configs/fzg-c40-paor.yaml --speed 500,1000,1500rpm --torque 100,200Nm --oil-temp 90degC"};
    cli.footer("Exit codes: 0 success, 1 usage error, 2 input error (file:line:column: key: message), 3 output not "
               "writable, 4 internal error, 128+signal interrupted by SIGINT/SIGTERM/SIGHUP/SIGQUIT/SIGPIPE or a closed "
               "output pipe (130/143/129/131/141; no output file written; a pipe stops part-way).\nEvery command: gearloss COMMAND --help");
    cli.set_version_flag("--version", std::string("gearloss ") + GEARLOSS_VERSION);
    cli.require_subcommand(1);

    // The subcommands, in the order of `gearloss --help`.
    struct Entry {
        std::unique_ptr<app::Command> command;
        CLI::App* sub = nullptr;
    };
    std::vector<Entry> table;
    for (auto make : {app::make_map_command, app::make_point_command, app::make_diagnose_command, app::make_synth_command,
                      app::make_compare_command, app::make_mesh_profile_command, app::make_cycle_command, app::make_duty_command,
                      app::make_rating_command,
                      app::make_merge_command, app::make_check_command, app::make_report_command,
                      app::make_import_command})
        table.push_back({make(), nullptr});
    for (auto& e : table) e.sub = e.command->add_to(cli);

    // A first word that is neither an option nor a command is a misspelt command: say so, rather
    // than CLI11's "A subcommand is required".
    if (argc > 1 && argv[1][0] != '-') {
        const std::string word = argv[1];
        std::string names;
        bool known = false;
        for (const auto& e : table) {
            known = known || e.sub->check_name(word);
            names += (names.empty() ? "" : ", ") + e.sub->get_name();
        }
        if (!known) {
            std::fprintf(stderr, "gearloss: usage error: unknown command '%s'; the commands are %s (see gearloss --help)\n",
                         gearloss::io::excerpt(word).c_str(), names.c_str());
            return app::kUsage;
        }
    }
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "gearloss: usage error: %s (see gearloss --help)\n", app::usage_error_line(e).c_str());
        return app::kUsage;
    }

    for (auto& e : table)
        if (e.sub->parsed())
            return app::run_command([&] {
                app::check_option_values(*e.sub);
                return e.command->run();
            });
    return app::kOk;  // not reached: require_subcommand(1)
}
