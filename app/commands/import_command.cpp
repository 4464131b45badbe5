// gearloss import: a REXS model (.rexs, .rexsj, .rexsz) as a gearloss case and its oil file.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "commands/command.hpp"
#include "commands/common.hpp"
#include "gearloss/io/atomic_file.hpp"
#include "gearloss/case/config.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/rexs/case_mapper.hpp"
#include "gearloss/rexs/reader.hpp"

namespace gearloss::app {
namespace {

namespace fs = std::filesystem;

class ImportCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("import", "a REXS gearbox model (.rexs, .rexsj, .rexsz) as a gearloss case");
        s->add_option("model", model_, "REXS model file (REXS 1.0 to 1.6)")->required();
        s->add_option("-o,--output", out_, "case file to write (YAML); the model's lubricant goes to CASE.oil.yaml beside it")
            ->required();
        s->add_option("--oil", oil_, "an existing oil file for the case instead of the model's lubricant");
        s->footer("Cylindrical gear stages are mapped; worm, bevel, hypoid, crossed-axis and planetary stages are refused\n"
                  "naming their component. Values REXS does not carry (oil level, oil volume, housing surface) are\n"
                  "assumed and commented. See docs/rexs.md.\n"
                  "Example:\n  gearloss import gearbox.rexs -o gearbox.yaml && gearloss check gearbox.yaml && gearloss map gearbox.yaml -o map.csv");
        return s;
    }

    int run() override {
        if (out_ == "-") throw InputError({}, 0, 0, "--output", "give a file name: the case refers to its oil file beside it");
        const fs::path case_path(out_);
        const fs::path dir = case_path.has_parent_path() ? case_path.parent_path() : fs::path(".");
        rexs::ImportOptions o;
        std::string oil_out;
        if (oil_.empty()) {
            fs::path oil = case_path;
            oil.replace_extension(".oil.yaml");
            oil_out = oil.string();
            o.oil_reference = oil.filename().string();
            o.write_oil = true;
        } else {
            if (!fs::is_regular_file(oil_)) throw InputError({}, 0, 0, "--oil", "'" + oil_ + "' is not an oil file");
            o.oil_reference = fs::proximate(fs::absolute(oil_), fs::absolute(dir)).string();
            o.write_oil = false;
        }
        io::NamedFiles outputs{{"--output", out_}};
        if (!oil_out.empty()) outputs.push_back({"--output (oil file)", oil_out});
        io::NamedFiles inputs{{"model", model_}};
        if (!oil_.empty()) inputs.push_back({"--oil", oil_});
        io::require_safe_outputs(outputs, inputs);
        const rexs::Model model = rexs::read_model(model_);
        const rexs::ImportResult r = rexs::map_to_case(model, o);
        verify_loads(r, oil_out, dir);
        for (const auto& w : r.warnings) std::fprintf(stderr, "gearloss: warning: %s\n", w.c_str());
        io::OutputTransaction transaction;
        io::AtomicFile c(out_);
        c.write(r.case_yaml);
        c.commit();
        if (!oil_out.empty()) {
            io::AtomicFile f(oil_out);
            f.write(r.oil_yaml);
            f.commit();
        }
        transaction.publish();
        return kOk;
    }

private:
    // The case must be one `check` accepts: it is loaded before anything is written (the oil file
    // from a private temporary folder). A value the model gives that the case loader refuses (a
    // negative module, say) is an error naming the model, the line of the case and the REXS
    // component and attribute that line came from (its comment).
    void verify_loads(const rexs::ImportResult& r, const std::string& oil_out, const fs::path& dir) const {
        fs::path tmp;
        std::error_code ec_ignored;  // the temporary folder is removed when it can be
        std::string base = dir.string();
        if (!oil_out.empty()) {
            std::error_code ec;
            tmp = fs::temp_directory_path(ec) / ("gearloss-import-" + std::to_string(::getpid()));
            fs::create_directories(tmp, ec);
            if (ec) throw IoError("cannot create a temporary folder to check the imported case: " + ec.message());
            std::ofstream f(tmp / fs::path(oil_out).filename(), std::ios::binary);
            f << r.oil_yaml;
            if (!f.flush()) throw IoError("cannot write a temporary oil file to check the imported case");
            base = tmp.string();
        }
        try {
            (void)io::load_case_text(r.case_yaml, out_, base);
        } catch (const InputError& e) {
            if (!tmp.empty()) fs::remove_all(tmp, ec_ignored);
            std::string origin;
            const std::string& text = e.file == out_ ? r.case_yaml : r.oil_yaml;
            // The comment of the line the error names: "REXS 15 normal_module [mm]".
            std::istringstream lines(text);
            std::string line;
            for (int i = 0; i < e.line && std::getline(lines, line); ++i) {
            }
            if (const auto hash = line.find("# "); e.line > 0 && hash != std::string::npos)
                origin = " (that value: " + line.substr(hash + 2) + ")";
            const std::string shown = e.file == out_ ? out_ : oil_out;  // not the temporary folder
            throw InputError(model_, 0, 0, "",
                             "the imported case does not load: " + Error::format(shown, e.line, e.column, e.key, e.message) + origin);
        } catch (...) {
            if (!tmp.empty()) fs::remove_all(tmp, ec_ignored);
            throw;
        }
        if (!tmp.empty()) fs::remove_all(tmp, ec_ignored);
    }

    std::string model_, out_, oil_;
};

}  // namespace

std::unique_ptr<Command> make_import_command() { return std::make_unique<ImportCommand>(); }

}  // namespace gearloss::app
