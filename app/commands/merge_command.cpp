// gearloss merge: the shards of `map --shard K/N` joined into the file a single run writes.
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/job.hpp"

namespace gearloss::app {
namespace {

class MergeCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("merge", "join the shards of `map --shard K/N` into the file a single run writes");
        s->add_option("shards", shards_, "shard CSV files, any order")->required();
        s->add_option("-o,--output", out_, "output CSV ('-' = stdout)");
        s->footer("Example:\n  for k in 1 2 3 4; do gearloss map configs/transfer-box.yaml --shard $k/4 -o part$k.csv; done\n"
                  "  gearloss merge part*.csv -o map.csv");
        return s;
    }

    int run() override {
        std::vector<std::pair<std::string, std::string>> inputs;
        for (const auto& f : shards_) {
            inputs.emplace_back("shards", f);
            inputs.emplace_back("shards (metadata)", map::sidecar_path(f));
        }
        io::require_safe_outputs({{"--output", out_}, sidecar_output("--output", out_)}, inputs);
        io::AtomicFile f(out_);
        std::string header;
        map::merge_shards(shards_, [&](std::string_view s) {
            if (header.empty()) header = map::header_line(s);
            f.write(s);
        });
        f.commit();
        // The merged file's sidecar, from the first shard's (nothing for standard output).
        if (map::wants_sidecar(out_)) map::write_sidecar(out_, map::merged_metadata(shards_, command_line(), header));
        return kOk;
    }

private:
    std::vector<std::string> shards_;
    std::string out_ = "-";
};

}  // namespace

std::unique_ptr<Command> make_merge_command() { return std::make_unique<MergeCommand>(); }

}  // namespace gearloss::app
