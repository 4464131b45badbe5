#pragma once
// Where do simulation and recordings disagree, which physics was left out,
// and how much better does the model fit with it?
//
// Two observation channels per recorded point: the loss, compared with the
// model at the measured oil temperature (so a heat-path error cannot pose as
// a loss error), and the oil temperature, compared with the coupled solve (a
// real extra loss heats the oil; a sensor artefact does not). Candidates come
// from the model's mechanisms, calibration and the rig's artefacts (effects.hpp),
// with bounds relative to the campaign. Forward selection of up to three
// effects needs all three of: BIC gain (per-channel variances profiled out),
// K-fold cross-validated gain, and stability across bootstrap resamples; each
// addition is followed by a joint refit and a test of whether every earlier
// effect is still needed. What the accepted hypothesis leaves is then tested
// against the measurement noise (adequacy.hpp). Whether an effect is present and
// whether it is the whole cause are two questions: a name is confident
// (missing_physics) when the selection's evidence holds and what it leaves is noise,
// or, with the loss at the noise, only a smaller structure reported apart (sized and
// located); the report says separately whether the tests had the power to show the
// findings to be the whole cause. Otherwise the verdict is partly_explained and says
// where the remainder lives.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "gearloss/diagnosis/effects.hpp"
#include "gearloss/diagnosis/hypothesis.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "gearloss/model/model.hpp"

namespace gearloss::diagnosis {

struct DiagnoseOptions {
    int bootstrap = 24;            // resamples for the stability check
    unsigned seed = 20261121;      // resampling seed (results are reproducible)
    double bic_threshold = 10.0;   // "very strong" evidence (Kass & Raftery 1995)
    double cv_margin = 2.0;        // required cross-validated log-likelihood gain [nats]
    double stability_min = 0.6;    // share of resamples in which the effect wins
    double ambiguity_bic = 2.0;    // candidates this close in BIC are indistinguishable
    int max_findings = 3;
    int threads = 0;
    // Declared measurement noise (one standard deviation): the loss as a share of the recorded
    // loss, the oil temperature in K. 0: estimated from the recordings (adequacy.hpp).
    double loss_uncertainty = 0, temp_uncertainty = 0;
    // Without a declared noise, a small campaign's estimate (a few neighbour differences) is
    // bounded below by these: the loss of a rig is a small difference of two large measured
    // powers, known to about 1 % of itself at best; an equilibrium oil temperature is defined to
    // the stabilisation criterion's tenths of a kelvin (Pereira 2017, sec. 3.5.2: 0.5 K over
    // 30 min). The report says when the floor was the noise used.
    double loss_noise_floor = 0.01, temp_noise_floor = 0.2;
    // Level of the adequacy tests (goodness of fit and structure, per channel) as a family
    // (Holm), and of the claim that there is a mismatch at all, made when the family or the
    // tests' combination rejects, each at half of it (adequacy::claim_levels): the null model
    // is rejected only on strong evidence.
    double adequacy_level = 0.01;
    // Level of the tests' combination (Fisher 1932) that what the findings leave must pass for
    // them to be named with confidence (`missing_physics`; else `partly_explained`). Laxer
    // than adequacy_level on purpose: naming a cause demands that nothing systematic is left,
    // and several tests each just short of failing are a remainder, not noise.
    double confidence_level = 0.05;
    // The findings are shown to be the whole cause only when those tests could have seen a
    // remainder: one of this RMS (a multiple of each channel's noise) must fail them in at least
    // half such campaigns (adequacy.hpp detectable_remainder). With the noise estimated from a
    // few points' neighbour differences a remainder as large as the noise itself passes unseen
    // (3 x 3: about twice it); the findings are then still named with confidence (the effect is
    // present), and the report says that these points cannot show it to be the whole cause
    // (Diagnosis::completeness). A declared noise is known better, so tests more.
    double confident_detectable = 1.0;
    // Progress messages (a terminal shows them); called from the calling thread only.
    std::function<void(const std::string&)> progress;
    // Candidate scans stay where the model is physical at every recorded point (effects.hpp
    // valid_range: heat flow to ambient positive). false scans each parameter's full bounds;
    // a candidate that then cannot be evaluated somewhere is rejected with the reason (tests).
    bool physical_scan_range = true;
    // Points the selection works on. Each candidate's response costs a coupled solve per point
    // and knot (some 500 solves a point over a diagnosis), so a larger campaign is fitted on
    // this many of its usable points, spread evenly over it in row order (the k-th of M is
    // point floor(k N / M)): the candidates, their cross-validation and resamples, the adequacy
    // tests and the remainder formula see them; the baseline and final predictions, the
    // overall RMSE, the outliers and the residuals cover every point. A warning says so.
    int max_fit_points = 400;
    // Ceres-style check of the options (diagnose calls it): throws InputError naming the option.
    void validate() const;
};

struct Estimate {
    std::string name, unit;
    double value = 0, uncertainty = 0;
    std::string form, case_form;  // a model-form finding: the form named and the case's (value 1)
};

// A shape setting fitted with a finding's parameter by profiling over a grid (where mixed
// friction sets in): the value chosen and the grid it was chosen from.
struct ShapeEstimate {
    std::string name;
    double value = 0;
    std::vector<double> grid;
};

struct Finding {
    std::string effect, description;
    Estimate parameter;
    std::optional<ShapeEstimate> shape;
    std::vector<int> rows;          // unstabilised_test: the flagged rows
    double delta_bic = 0, stability = 0, cv_gain = 0;
    // The resamples won by this effect or another of the same loss mechanism (its level, its
    // mixed-film rise, its other published forms): whether the mechanism is settled when its
    // form is not. Equal to `stability` where no other form of it took resamples.
    double mechanism_stability = 0;
    double rmse_before = 0, rmse_after = 0, cv_rmse_before = 0, cv_rmse_after = 0;  // loss, W
    double temp_rmse_before = 0, temp_rmse_after = 0;                              // K (0 without temperatures)
    std::string oil;                // multi-oil campaigns: the oil it concerns alone (empty: every oil)
    std::vector<std::string> equivalent;  // candidates that explain the data equally well
    std::string separating_measurement;
};

struct Candidate {
    std::string effect;
    double value = 0, delta_bic = 0;
    std::string rejected;  // why the candidate could not be evaluated (empty: it was)
};

struct Outlier {
    int row;
    std::string reason;
    // The row's residual from the model (less the campaign's median) over the noise in use;
    // a row is an outlier in a channel only beyond kOutlierSigmas of that noise.
    std::optional<double> loss_deviation_over_noise, temp_deviation_over_noise;
};

struct PointResidual {
    int row;
    double speed_rpm, torque, loss, loss_before, loss_after;
    std::optional<double> temp, temp_before, temp_after;  // degC
    std::string oil;  // multi-oil campaigns: the oil of the test
};

// Multi-oil campaigns: at one operating point, the loss of oil B minus that of oil A, as
// recorded and as the model gives it before and after the findings (W).
struct OilDifference {
    double speed_rpm = 0, torque = 0;
    std::string oil_a, oil_b;
    double recorded = 0, model_before = 0, model_after = 0;
};

struct Diagnosis {
    // missing_physics: effects named, what they leave is noise; partly_explained: effects named,
    // a systematic remainder is left (`remaining`); unexplained_mismatch: no candidate helps;
    // no_significant_mismatch: the recordings agree with the model within the noise.
    std::string verdict;
    std::string summary;            // one paragraph in the expected voice
    std::string location;           // where the baseline mismatch lives
    std::string remaining;          // where an unexplained residual remains (if any)
    // Effects that fit well but are not named because the resamples cannot tell them from
    // others (a pair against other pairs, a single effect against other singles), with what
    // they compete with; empty when there is none.
    std::string unsettled;
    std::vector<Finding> findings;
    std::vector<Candidate> candidates;  // every effect, best first
    std::vector<Outlier> outliers;  // also the rows not used (recorded values the model cannot evaluate)
    std::vector<PointResidual> residuals;
    std::vector<std::string> warnings;
    double rmse_before = 0, rmse_after = 0, cv_rmse_after = 0, temp_rmse_before = 0, temp_rmse_after = 0;
    bool has_temperature = false;
    // The adequacy of the final hypothesis: the noise used (declared or estimated, and how)
    // and the p-values of the goodness-of-fit and structure tests per channel.
    struct Channel {
        double noise = 0;          // relative (loss) or K (oil temperature)
        std::string noise_source;  // declared | replicates | neighbour differences | none
        double fit_p = 1, structure_p = 1;
        // The smallest systematic remainder (RMS over the noise) the fit test sees half the time.
        double fit_detectable = std::numeric_limits<double>::infinity();
        std::string structure_along;  // speed | torque | oil temperature | run order
    } adequacy_loss, adequacy_temp;
    // The fit tests' joint power: the remainder (RMS over the noise) they see half the time.
    double detectable = std::numeric_limits<double>::infinity();
    // Which noise the verdict was tested against, and why that one (declared, estimated, or the
    // small-campaign floor: DiagnoseOptions::loss_noise_floor).
    struct NoiseUsed {
        double loss_relative = 0, temp_K = 0;
        std::string source, why, temp_source, temp_why;
    } noise_used;
    // Whether an effect is present and whether it is the whole cause are two questions. The
    // main finding (the first) is `confident` when the verdict is missing_physics, else
    // `tentative`; empty effect: none named.
    struct MainFinding {
        std::string effect, confidence;
    } main_finding;
    // After a confident main finding, a smaller structure left (sized and located), reported
    // apart from it: the loss at the noise, the oil temperature beyond it (a heat path that
    // differs a little from the model's).
    struct RemainingStructure {
        std::string channel;        // "loss" | "oil_temperature"
        double rms_over_noise = 0;  // RMS beyond the noise, in units of the noise
        std::string along;          // "power" | "speed" | "torque" | "oil temperature" | "run order" | ""
        std::string text;
    };
    std::optional<RemainingStructure> remaining_structure;
    // Whether the findings were shown to be the whole cause (the tests could have seen a
    // remainder of the noise's size), in words; empty without findings.
    std::string completeness;
    // The run order: from a `run`, `date` or `time` column (a raw log: its time stamps); not
    // recorded, no drift or running-in hypothesis is formed.
    struct RunOrder {
        bool recorded = false;
        std::string column;
    } run_order;
    // For a remainder no candidate explains (partly_explained, unexplained_mismatch): a compact
    // formula by sparse regression over the operating point, a hypothesis, never a finding.
    std::optional<hypothesis::Proposal> remainder;
    std::vector<std::string> oils;  // multi-oil campaigns: the oils tested (as in the recordings)
    std::vector<OilDifference> oil_differences;
    Hypothesis calibrated;          // the accepted hypothesis
    int points = 0;                 // usable recorded points
    int fit_points = 0;             // of them, those the selection and the tests used (max_fit_points)
    int bootstrap = 24;             // resamples of the stability check
};

Diagnosis diagnose(const solver::Model& model, const Recordings& rec, const DiagnoseOptions& opt = {});

// The recorded output speeds against the case's gear ratio (model.layout.ratio, omega_out /
// omega_in): a row (or log test) whose |speed_out / speed_in| is more than 2 % from it is a
// finding naming file:line:column (recorded in another gear, or the speed sensors swapped).
// diagnose() adds them to its warnings.
std::vector<std::string> ratio_findings(const solver::Model& model, const Recordings& rec);

// A parameter value with its unit for reports: "1.234 W", "0.95".
std::string fmt_value(double v, const std::string& unit);
// "mesh.mixed_friction_onset = 2.8 (fitted with it: the best of 1, 1.4, 2, 2.8, 4, 5.6)".
std::string shape_text(const ShapeEstimate& s);
std::string diagnosis_text(const Diagnosis& d);
std::string diagnosis_json(const Diagnosis& d);
std::string residuals_csv(const Diagnosis& d);

// Writes the case file `config_in` with a `calibration:` block holding the
// accepted physics to `config_out` (artefacts are reported, not written).
void write_calibrated_config(const std::string& config_in, const std::string& config_out, const Diagnosis& d);

}  // namespace gearloss::diagnosis
