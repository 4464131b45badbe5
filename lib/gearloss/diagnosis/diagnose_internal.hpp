#pragma once
// Internals shared by the diagnosis files (Engine, responses, fits, statistics).
#include <boost/math/interpolators/pchip.hpp>
#include <exception>
#include <memory>
#include <numbers>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/diagnosis/adequacy.hpp"
#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::diagnosis::detail {

constexpr double to_rpm = 30.0 / std::numbers::pi;
constexpr double kFloorLoss = 0.002;  // relative loss residual floor (0.2 %)
constexpr double kFloorTemp = 0.05;   // K
// A noise estimated with fewer degrees of freedom than this is a small campaign's: bounded
// below by DiagnoseOptions::loss_noise_floor / temp_noise_floor (assess).
constexpr double kSmallCampaignDof = 10;

struct Obs {
    int row;
    double w, torque, loss, ambient, scale;
    bool has_T;        // measured oil temperature known: the loss is compared at it
    bool T_evidence;   // the temperature is an equilibrium value: compared with the coupled solve
    double T_oil;
    bool stabilised;
    double drift;
    int oil = 0;       // index into the campaign's oils (0: the case's oil)
    double run = std::numeric_limits<double>::quiet_NaN();  // run order where recorded (else NaN)
};

struct Pred {
    std::vector<double> loss, temp;
    std::string failure;  // the first point the hypothesis could not be evaluated at (then the values are void)
};

struct Score {
    double nll = 0;
    int nP = 0, nT = 0;
};

// One accepted or candidate effect with its value (a hypothesis is the case plus these).
struct Term {
    const Effect* effect = nullptr;
    double value = 0;
};

struct Fit {
    double value = 0, nll = 0, uncertainty = 0;
    int k = 0;                 // parameters added
    double extra_penalty = 0;  // selection penalty beyond k ln N (choice of flagged points)
    Hypothesis h;
    std::string failed;        // why the candidate could not be evaluated (it is then rejected)
};

// Objective of a hypothesis that could not be evaluated: finite (Brent's arithmetic stays
// defined), far above any likelihood.
constexpr double kFailedNll = 1e100;
constexpr double kRejectedBic = -1e300;  // delta BIC of a rejected or already used candidate

std::string point_name(const Obs& o);

// The model at one recorded point under a hypothesis (loss as recorded, coupled oil temperature);
// returns why it cannot be evaluated, or an empty string (diagnose_engine.cpp).
std::string evaluate_point(solver::Model& m, solver::PointState& p, const Hypothesis& h, const Obs& o, double& loss,
                           double& temp);

// The first exception thrown in the iterations of a parallel region, rethrown after it
// (an exception must not leave an OpenMP region: that would be std::terminate).
class RegionErrors {
public:
    void capture() noexcept {
#pragma omp critical(diagnose_region_errors)
        if (!first_) first_ = std::current_exception();
    }
    void rethrow() const {
        io::throw_if_interrupted();
        if (first_) std::rethrow_exception(first_);
    }

private:
    std::exception_ptr first_;
};

// Median and robust scale (1.4826 x median absolute deviation, at least `floor`) of v;
// (0, floor) for an empty v (diagnose_residuals.cpp).
std::pair<double, double> robust_centre_scale(std::vector<double> v, double floor);

// Negative log-likelihood of n residuals with their variance profiled out (floored).
double profiled(double rss, int n, double floor);

// The score of predictions at the points idx (with repeats): the loss residual relative to
// each point's scale, the oil temperature where it is equilibrium evidence (a point flagged
// unstabilised has its own temperature: residual 0), each channel's variance profiled out.
// `predict(i, loss, temp)` gives point i's prediction: the model's, a response's, or a sum.
// One point's residuals under a prediction (L, T): the loss relative to the point's scale;
// the oil temperature where it is equilibrium evidence (0 for a point flagged unstabilised).
struct ScaledResidual {
    double loss = 0, temp = 0;
    bool has_temp = false;
};
inline ScaledResidual scaled_residual(const Obs& o, const std::vector<char>& flagged, int i, double L, double T) {
    ScaledResidual r;
    r.loss = (o.loss - L) / o.scale;
    r.has_temp = o.T_evidence;
    if (r.has_temp) r.temp = !flagged.empty() && flagged[i] ? 0.0 : o.T_oil - T;
    return r;
}

template <class Predict>
Score score_points(const std::vector<Obs>& obs, const std::vector<char>& flagged, const std::vector<int>& idx,
                   Predict&& predict) {
    double rP = 0, rT = 0;
    Score s;
    for (int i : idx) {
        const Obs& o = obs[i];
        double L, T;
        predict(i, L, T);
        const ScaledResidual r = scaled_residual(o, flagged, i, L, T);
        rP += r.loss * r.loss;
        ++s.nP;
        if (r.has_temp) {
            rT += r.temp * r.temp;
            ++s.nT;
        }
    }
    s.nll = profiled(rP, s.nP, kFloorLoss) + profiled(rT, s.nT, kFloorTemp);
    return s;
}

class Engine;

// The per-point predictions of one effect along its parameter, everything else held at
// `base`: knots evaluated with the coupled model, a monotone cubic (Fritsch & Carlson 1980,
// Boost.Math's pchip) in between. Fits on any subset of the points (cross-validation folds,
// bootstrap resamples) then need no model evaluation at all: this is what keeps a
// diagnosis linear in the number of points.
class Response {
public:
    Response() = default;
    // Evaluates the knots (in parallel over them); `failed` says why none could be.
    Response(const Engine& E, const Effect& e, const Hypothesis& base);
    // The same on given knots (sorted; a part of scan_values around a known optimum).
    Response(const Engine& E, const Effect& e, const Hypothesis& base, const std::vector<double>& grid);
    const std::string& failed() const { return failed_; }
    // Why the scan stops short of the parameter's range (a value the model cannot be evaluated at), or empty.
    const std::string& narrowed() const { return narrowed_; }
    bool flat() const { return flat_; }  // the parameter changes neither channel at any point
    bool discrete() const { return discrete_; }  // two forms: predictions at the knots only
    // Negative log-likelihood on idx (with repeats) at x, from the interpolants.
    double nll(double x, const std::vector<int>& idx) const;
    // Minimises nll over the knots' span on idx: value and nll.
    std::pair<double, double> minimise(const std::vector<int>& idx) const;
    void predict(double x, int i, double& loss, double& temp) const;
    // Adds a knot evaluated with the model (near an optimum, where interpolation matters most).
    void refine(double x);
    double lo() const { return knots_.front(); }
    double hi() const { return knots_.back(); }
    const std::vector<double>& loss_at_knot(size_t k) const { return loss_[k]; }
    const std::vector<double>& temp_at_knot(size_t k) const { return temp_[k]; }
    const std::vector<double>& knots() const { return knots_; }

private:
    void build();
    const Engine* E_ = nullptr;
    const Effect* e_ = nullptr;
    std::shared_ptr<const Hypothesis> base_;
    std::vector<double> knots_;
    using Interpolant = boost::math::interpolators::pchip<std::vector<double>>;
    std::vector<std::vector<double>> loss_, temp_;  // [knot][point]
    std::vector<Interpolant> iloss_, itemp_;        // per point
    std::string failed_, narrowed_;
    bool flat_ = false, discrete_ = false;
};

// The recorded points, and one working copy of the model per thread (diagnose_engine.cpp).
class Engine {
public:
    // `per_oil`: the case with each of the campaign's oils, by Obs::oil (empty: `m` alone).
    // `campaign`: the points the scan ranges are relative to (mean loss, highest speed), when
    // `obs` is a subset of them (a large campaign fitted on part of its points); null: `obs`.
    Engine(const solver::Model& m, std::vector<Obs> obs, int threads, bool physical_range,
           const std::vector<solver::Model>& per_oil = {}, const std::vector<Obs>* campaign = nullptr);
    int oils() const { return n_oils_; }
    const lubricant::Oil& oil(int j) const { return work_[static_cast<size_t>(j)].oil; }
    int threads() const { return threads_; }
    const std::vector<Obs>& obs() const { return obs_; }
    const std::vector<int>& all() const { return all_; }
    bool has_temperature() const { return n_T_ > 0; }
    double mean_loss() const { return mean_loss_; }

    // Never throws (it runs inside parallel regions): a point that cannot be evaluated, or an
    // interrupt (polled per point), ends the prediction with `out.failure` set.
    void predict(const Hypothesis& h, const std::vector<int>& idx, Pred& out, int tid) const;
    // Predictions at every point of `count` hypotheses (make(c) builds the c-th), using every
    // thread: over the hypotheses, or over the points for a single one (same values as
    // predict(): each point is solved on its own). Not from inside a parallel region.
    std::vector<Pred> predict_many(size_t count, const std::function<Hypothesis(size_t)>& make) const;
    // A prediction outside parallel regions of a hypothesis evaluated before: an interrupt throws.
    Pred predict_checked(const Hypothesis& h, const std::vector<int>& idx) const;
    Score score(const Hypothesis& h, const Pred& p, const std::vector<int>& idx) const;
    // kFailedNll when the hypothesis cannot be evaluated at a point of idx (why: *failure, if given).
    double nll(const Hypothesis& h, const std::vector<int>& idx, int tid, std::string* failure = nullptr) const;
    // The scan range of a parameter for this campaign: its physical bounds, narrowed to where
    // the model stays physical and to an added loss of at most a few times the recorded one
    // (the bounds scale with the gearbox, never absolute numbers).
    std::pair<double, double> range(const Effect& e, const Hypothesis& base) const;
    std::vector<double> scan_values(const Effect& e, const Hypothesis& base) const;
    // How the effect shows at this campaign's points (measured on the model).
    Signature signature(const Effect& e, const Hypothesis& base) const;
    // Fits one effect's parameter on top of `base` using all points, with its response.
    Fit fit(const Effect& e, const Hypothesis& base, Response* response = nullptr) const;
    // The same starting from a value known to be near the optimum (a joint refit, where the
    // others moved a little): the scan's knots around `near` only, the whole scan when the
    // optimum leaves them. Same result within the refinement's tolerance, fewer model solves.
    Fit refit(const Effect& e, const Hypothesis& base, double near) const;
    Fit fit_unstabilised(const Hypothesis& base, const std::vector<int>& idx, double loss_noise) const;

private:
    // fit() on the given knots (empty: the whole scan).
    Fit fit(const Effect& e, const Hypothesis& base, Response* response, std::vector<double> knots) const;
    // The working model of thread `tid` for the tests of oil `oil`, and a hypothesis written
    // into every oil's model of that thread.
    solver::Model& model(int tid, int oil) const { return work_[static_cast<size_t>(tid * n_oils_ + oil)]; }
    void apply(const Hypothesis& h, int tid) const;
    // The mean |dL/dtheta| over the points at the base value (finite difference), W per unit.
    double loss_sensitivity(const Effect& e, const Hypothesis& base) const;
    // range() for a known loss sensitivity (scan_values computes it once for both).
    std::pair<double, double> range_for(const Effect& e, double sensitivity) const;
    bool relative_bounds(const Effect& e) const;
    std::vector<Obs> obs_;
    std::vector<int> all_;
    int threads_ = 1;
    mutable std::vector<solver::Model> work_;
    mutable std::vector<solver::PointState> states_;
    double mean_loss_ = 0, mean_power_ = 0, mean_omega_ = 0, max_rpm_ = 0;
    bool physical_range_ = true;
    // The case's heat path already changes with speed, so a diagnosis may find that it
    // overstates it (negative speed_dependent_cooling); otherwise cooling can only grow.
    bool heat_path_speed_dependent_ = false;
    int n_T_ = 0, n_oils_ = 1;
};

// diagnose_engine.cpp
double delta_bic(double nll_base, const Fit& f, size_t n_obs);
size_t n_observations(const Engine& E, const std::vector<int>& idx);

// K-fold cross-validation (K = min(n, 10), folds interleaved in row order): refit on the
// other folds through the response, predict the held-out points.
struct CvResult {
    double nll = 0, rmse_loss = 0, rmse_temp = 0;
};
CvResult cross_validate(const Engine& E, const Response* r, const Pred& base_pred, const Hypothesis& base);
// Each effect with a shape setting (Effect::shape) fitted at every value of its grid on `base`
// and replaced by the best (the case's own value on a tie): the campaign's shape, chosen once
// before the selection; the effect then counts the setting as a parameter.
void profile_shapes(const Engine& E, std::vector<Effect>& lib, const Hypothesis& base);

// diagnose_residuals.cpp
struct ChannelStats {
    double rmse_loss = 0, rmse_temp = 0;
};

ChannelStats channel_rmse(const Engine& E, const Pred& p, const Hypothesis& h);
// Every point carries its run order (a `run`, `date` or `time` column, or a raw log).
bool run_order_recorded(const Engine& E);

// The adequacy of a hypothesis' residuals against the noise (adequacy.hpp), per channel.
struct Adequacy {
    adequacy::NoiseEstimate noise_loss, noise_temp;   // relative; K
    adequacy::FitTest fit_loss, fit_temp;
    adequacy::StructureTest structure_loss, structure_temp;
    double combined_p = 1;  // Fisher's combination of the tests' p-values
    // The fit tests' joint power at the confidence level (adequacy::detectable_remainder).
    double detectable = std::numeric_limits<double>::infinity();
    bool adequate = true;
    bool loss_fails = false, temp_fails = false;  // the channel's own tests reject (Holm)
    double rms_loss = 0, rms_temp = 0;            // RMS of the residuals (relative; K)
    std::string noise_loss_why, noise_temp_why;   // which noise, and why that one
    std::string text;  // what is left and where, when not adequate
};
// Each test at opt.adequacy_level, and Fisher's combination of the tests' p-values
// (adequacy::combined_p) at `combined_level`: it sees a remainder that leaves several tests
// each short of failing.
Adequacy assess(const Engine& E, const Pred& p, const Hypothesis& h, int fitted, const DiagnoseOptions& opt,
                double combined_level);

// Where the mismatch lives: per channel, mean, RMSE, and its dependence on
// speed, torque and oil viscosity.
struct Location {
    std::string text, clause;  // clause: short form for the summary sentence
};

Location locate(const Engine& E, const Pred& p, const Hypothesis& h, const solver::Model& model);
// The kinematic viscosity [mm^2/s] of a point's oil at T (the point's own oil in a multi-oil campaign).
double point_viscosity(const Engine& E, const Obs& o, double T);

// diagnose_verdict.cpp. The verdict from the findings and the adequacy of what they leave, with
// the noise used, the main finding's confidence, a smaller structure left after it and whether
// the findings were shown to be the whole cause (`remaining_location`: where the residual after
// them lives, for a partial explanation). Needs d.findings and d.location.
// The report's opening paragraph: `baseline_clause` where the case misses, `adequacy_text` the
// tests of what is left, `completeness_unshown` when they could not see a remainder of the noise's size.
std::string summary_paragraph(const Diagnosis& d, const std::string& baseline_clause, const std::string& adequacy_text,
                              bool completeness_unshown);
void judge(Diagnosis& d, const Adequacy& ad, const DiagnoseOptions& opt, const Engine& E, const Pred& pf,
           const Hypothesis& h, const std::string& remaining_location);
// A residual beyond this many times the noise in use (or the residuals' robust spread, when larger).
constexpr double kOutlierSigmas = 4.5;
// Rows whose residuals after the findings are outliers against the noise in use, and rows
// flagged as never stabilised or unstabilised.
std::vector<Outlier> noise_outliers(const Engine& F, const Pred& after, const Hypothesis& h, const Adequacy& ad,
                                    double loss_floor, double temp_floor);

// diagnose_oils.cpp: multi-oil campaigns. The oils of a campaign: [0] the case's, then each
// oil file of the recordings' `oil` column (paths relative to the recordings file).
struct CampaignOils {
    std::vector<solver::Model> models;  // the case with each oil (io::replace_oil)
    std::vector<std::string> names;  // as written in the column
    std::vector<int> of_point;       // per recorded point
    std::vector<char> tested;        // per oil: some usable point was recorded with it (mark_tested)
    int count_tested() const;
};
CampaignOils campaign_oils(const solver::Model& model, const Recordings& rec);
// The oils with a usable point (after the rows the model cannot compare were set aside).
void mark_tested(CampaignOils& oils, const Engine& E);
// Per-oil copies of the oil-dependent candidates, when two or more oils were tested.
void add_per_oil_candidates(std::vector<Effect>& lib, const CampaignOils& oils);
// Recorded vs model loss differences between oils at the operating points tested with several.
std::vector<OilDifference> oil_differences(const Engine& E, const Pred& before, const Pred& after,
                                           const CampaignOils& oils);
// Findings (and their equivalents, and the candidate list) of a per-oil candidate report the
// effect's own id and the oil.
void name_oil_findings(std::vector<Finding>& findings, std::vector<Candidate>& candidates, const std::vector<Effect>& lib);

// Why a recorded point cannot be compared with the model (empty: it can).
std::string recorded_fault(const solver::Model& model, const Obs& o);

}  // namespace gearloss::diagnosis::detail
