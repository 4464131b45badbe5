#pragma once
// Internals shared by diagnose.cpp, diagnose_engine.cpp and diagnose_residuals.cpp (Engine, fits, statistics).
#include <exception>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/io/interrupt.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::diagnosis::detail {

constexpr double to_rpm = 30.0 / std::numbers::pi;
constexpr double kFloorLoss = 0.002;  // relative loss residual floor (0.2 %)
constexpr double kFloorTemp = 0.05;   // K

struct Obs {
    int row;
    double w, torque, loss, ambient, scale;
    bool has_T;        // measured oil temperature known: the loss is compared at it
    bool T_evidence;   // the temperature is an equilibrium value: compared with the coupled solve
    double T_oil;
    bool stabilised;
    double drift;
};

struct Pred {
    std::vector<double> loss, temp;
    std::string failure;  // the first point the hypothesis could not be evaluated at (then the values are void)
};

struct Score {
    double nll = 0;
    int nP = 0, nT = 0;
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

// Negative log-likelihood of n residuals with their variance profiled out (floored).
double profiled(double rss, int n, double floor);

// The recorded points, and one working copy of the model per thread (diagnose_engine.cpp).
class Engine {
public:
    Engine(const solver::Model& m, std::vector<Obs> obs, int threads, bool physical_range);
    int threads() const { return threads_; }
    const std::vector<Obs>& obs() const { return obs_; }
    const std::vector<int>& all() const { return all_; }
    bool has_temperature() const { return n_T_ > 0; }

    // Never throws (it runs inside parallel regions): a point that cannot be evaluated, or an
    // interrupt (polled per point), ends the prediction with `out.failure` set.
    void predict(const Hypothesis& h, const std::vector<int>& idx, Pred& out, int tid) const;
    // A prediction outside parallel regions of a hypothesis evaluated before: an interrupt throws.
    Pred predict_checked(const Hypothesis& h, const std::vector<int>& idx) const;
    Score score(const Hypothesis& h, const Pred& p, const std::vector<int>& idx) const;
    // kFailedNll when the hypothesis cannot be evaluated at a point of idx (why: *failure, if given).
    double nll(const Hypothesis& h, const std::vector<int>& idx, int tid, std::string* failure = nullptr) const;
    // The scan range of a parameter (its bounds, narrowed to where the model stays physical).
    std::pair<double, double> range(const Effect& e) const;
    std::vector<double> scan_values(const Effect& e) const;
    // Fits one effect's parameter on top of `base` using the points `idx`.
    Fit fit(const Effect& e, const Hypothesis& base, const std::vector<int>& idx, int tid, bool with_uncertainty) const;
    Fit fit_unstabilised(const Hypothesis& base, const std::vector<int>& idx, int tid) const;

private:
    std::vector<Obs> obs_;
    std::vector<int> all_;
    int threads_ = 1;
    mutable std::vector<solver::Model> work_;
    mutable std::vector<solver::PointState> states_;
    double mean_loss_ = 0, mean_n29_ = 0, max_rpm_ = 0;
    bool physical_range_ = true;
    int n_T_ = 0;
};

// diagnose_engine.cpp
double delta_bic(double nll_base, const Fit& f, size_t n_obs);
size_t n_observations(const Engine& E, const std::vector<int>& idx);

// Leave-one-out: refit on all other points, predict the held-out one.
struct CvResult {
    double nll = 0, rmse_loss = 0, rmse_temp = 0;
    std::string failed;  // a fold whose fit or prediction could not be evaluated (the candidate is rejected)
};

CvResult cross_validate(const Engine& E, const Effect* e, const Hypothesis& base, const Hypothesis& full_fit);

// diagnose_residuals.cpp
struct ChannelStats {
    double rmse_loss = 0, rmse_temp = 0;
};

ChannelStats channel_rmse(const Engine& E, const Pred& p, const Hypothesis& h);

// Is there structure a generic smooth model of the operating point explains? (delta BIC)
double structure_delta_bic(const Engine& E, const Pred& p, const Hypothesis& h);

// Where the mismatch lives: per channel, mean, RMSE, and its dependence on
// speed, torque and oil viscosity.
struct Location {
    std::string text, clause;  // clause: short form for the summary sentence
};

Location locate(const Engine& E, const Pred& p, const Hypothesis& h, const solver::Model& model);

// Why a recorded point cannot be compared with the model (empty: it can).
std::string recorded_fault(const solver::Model& model, const Obs& o);

}  // namespace gearloss::diagnosis::detail
