// gearloss report: one self-contained HTML page about a case (lib/gearloss/report/): a summary,
// maps of efficiency, oil temperature and the loss breakdown, the comparison with other oils,
// the model-form spread, the model forms, the case as given and its checks; --pdf prints it
// with headless Chromium (report/pdf_print.hpp).
#include "commands/command.hpp"
#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"
#include "gearloss/core/errors.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/io/output_paths.hpp"
#include "gearloss/map/map_runner.hpp"
#include "gearloss/report/html_report.hpp"
#include "gearloss/report/pdf_print.hpp"
#include "gearloss/report/report_run.hpp"

namespace gearloss::app {
namespace {

constexpr GridOverrides::Examples kReportExamples{"600,700,800rpm", "150,200,250Nm"};

class ReportCommand final : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* s = app.add_subcommand("report", "one self-contained HTML page (and its PDF): a summary (ratio, rated, best and "
                                               "worst points with the loss split, thermal limit, oils ranked), efficiency / "
                                               "oil-temperature / loss maps with their values, oil comparison, form spread, "
                                               "model forms, the case and its checks");
        s->add_option("config", common_.config, "gearbox case (YAML)")->required();
        s->add_option("--ratio", common_.ratio, "select a ratio defined under gearbox.ratios");
        s->add_option("--oil-temp", common_.oil_temp, "fixed oil temperature (e.g. 70degC): no thermal solve");
        s->add_option("--oil", oils_, "compare the case's oil with this oil file (YAML); give once per oil");
        grid_.add_to(*s, "override the input speeds, e.g. 600,700,800rpm", "override the input torques, e.g. 150,200,250Nm");
        s->add_option("-o,--output", out_, "output HTML file ('-' = stdout); -o, --pdf or both");
        s->add_option("--pdf", pdf_, "also print the page to this PDF file with headless Chromium (chromium --headless "
                                     "--print-to-pdf; $CHROMIUM names another browser)");
        s->add_option("--threads", threads_, "threads (default: all cores)")->check(CLI::Range(1, 1024));
        s->add_flag("--no-spread", no_spread_, "skip the model-form spread (it solves the map once per form combination)");
        spread_axes_option_ = s->add_option("--spread-axes", spread_axes_text_,
                                            "restrict the spread to these form axes, e.g. mesh.friction,windage.form");
        s->footer("Example: gearloss report configs/transfer-box.yaml --oil configs/oils/75W140-A.yaml -o report.html "
                  "--pdf report.pdf");
        return s;
    }

    int run() override {
        NamedPaths inputs = case_inputs(common_.config);
        for (const auto& f : oils_) inputs.emplace_back("--oil", f);
        if (out_.empty() && pdf_.empty()) throw InputError("", 0, 0, "--output", "required: name the HTML file (-o FILE) and/or the PDF (--pdf FILE)");
        if (pdf_ == "-") throw InputError("", 0, 0, "--pdf", "a PDF goes to a file, not to standard output");
        io::NamedFiles outputs;
        if (!out_.empty()) outputs.emplace_back("--output", out_);
        if (!pdf_.empty()) outputs.emplace_back("--pdf", pdf_);
        io::require_safe_outputs(outputs, inputs);
        // No browser, no run: the error comes before minutes of solving.
        if (!pdf_.empty() && report::find_chromium().empty()) report::print_pdf("", "--pdf");
        const bool axes_given = spread_axes_option_ && spread_axes_option_->count() > 0;
        if (axes_given && spread_axes_text_.empty())
            throw InputError("", 0, 0, "--spread-axes", "empty: name the axes, e.g. mesh.friction,windage.form");
        if (axes_given && no_spread_) throw InputError("", 0, 0, "--spread-axes", "--no-spread skips the spread");

        report::ReportRequest q;
        q.config = common_.config;
        if (!common_.ratio.empty()) q.ratio = common_.ratio;
        q.oils = oils_;
        q.overrides = grid_.case_overrides();
        q.overrides.oil_temp = common_.oil_temp;
        q.prepare = [this](io::Case c, const std::string& note) {
            try {
                c = with_options(std::move(c), common_);
                grid_.apply_checked(c, kReportExamples);
            } catch (const InputError& e) {
                if (note.empty()) throw;
                throw InputError(e.file, e.line, e.column, e.key, e.message + " (" + note + ")");
            }
            return c;
        };
        q.spread = !no_spread_;
        for (size_t a = 0; a < spread_axes_text_.size();) {
            const size_t e = std::min(spread_axes_text_.find(',', a), spread_axes_text_.size());
            if (e == a) throw InputError("", 0, 0, "--spread-axes", "an empty axis name (e.g. mesh.friction,windage.form)");
            q.spread_axes.push_back(spread_axes_text_.substr(a, e - a));
            a = e + 1;
        }
        q.map_options.threads = threads_;
        ProgressMeter meter;
        q.map_options.progress = meter.callback();
        q.command_line = command_line();
        const report::ReportData data = report::collect_report(q);
        io::throw_if_interrupted();
        const std::string page = report::html_report(data);
        std::string pdf;
        if (!pdf_.empty()) pdf = report::print_pdf(page, "--pdf");
        if (!out_.empty()) write_file(out_, page);  // the page and its PDF appear together (run_command's transaction)
        if (!pdf_.empty()) write_file(pdf_, pdf);
        return kOk;
    }

private:
    CommonOptions common_;  // config, --ratio, --oil-temp (its `oil` stays empty: --oil names oils to compare)
    GridOverrides grid_;
    std::vector<std::string> oils_;
    std::string out_, pdf_;
    int threads_ = 0;
    bool no_spread_ = false;
    std::string spread_axes_text_;
    CLI::Option* spread_axes_option_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> make_report_command() { return std::make_unique<ReportCommand>(); }

}  // namespace gearloss::app
