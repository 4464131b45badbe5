#pragma once
// Is what a hypothesis leaves consistent with measurement noise? The absolute adequacy test
// of the diagnosis, independent of any candidate: the noise of a residual channel (declared,
// from replicates, or from differences of neighbouring points), a goodness-of-fit test of the
// residuals against it, and a non-parametric test for structure left over speed, torque, oil
// temperature and run order (cross-validated smoothers with a permutation p-value).
//
// Everything here works on plain vectors: one channel (the relative loss residual, or the oil
// temperature residual in K) of one campaign at a time.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gearloss::diagnosis::adequacy {

// One residual channel of a campaign: the residuals and the coordinates of their points.
struct Channel {
    std::vector<double> residual;  // recorded - model, in the channel's unit (relative loss, or K)
    std::vector<double> speed;     // input speed of each point (any unit; levels are found in it)
    std::vector<double> torque;    // input torque of each point
    std::vector<double> oil_temp;  // oil temperature of each point (K or degC)
    std::vector<double> order;     // run order of each point (row number)
};

// How large the noise of a channel is, and how well that is known.
struct Contrasts;  // the pseudo-residuals' coefficients on the residuals (adequacy.cpp)
struct NoiseEstimate {
    double sigma = 0;        // one standard deviation, in the channel's unit
    double dof = 0;          // degrees of freedom of the estimate (infinity when declared)
    std::string source;      // "declared", "replicates", "neighbour differences", "none"
    int pairs = 0;           // replicate groups or pseudo-residuals used
    // For an estimate from neighbour differences: how it was formed, so that the fit test can
    // draw its null distribution (see goodness_of_fit).
    std::shared_ptr<const Contrasts> contrasts;
    bool known() const { return sigma > 0 && dof > 0; }
};

// The noise of a channel from the recordings themselves, without any model form:
// 1. replicates: points at the same operating point (speed and torque within `rel_tol`),
//    pooled within-group variance (dof = sum of (group size - 1));
// 2. otherwise pseudo-residuals of neighbouring points (Gasser et al. 1986):
//    along torque within each speed level and along speed within each torque level, each
//    interior point against the straight line through its two neighbours, normalised to unit
//    variance; the scale is a robust one (Huber's (1981) proposal 2, so that a band or step at
//    one level moves it by a bounded amount) with the contrasts' effective dof (Satterthwaite
//    (1946): they share points) reduced by the estimator's efficiency;
// 3. fewer than 3 usable pseudo-residuals: source "none", sigma 0.
// The residual that goes in is the channel's residual (the model removes most of the
// variation, so what remains is smooth plus noise).
NoiseEstimate estimate_noise(const Channel& c, double rel_tol = 0.01);

// Goodness of fit: are the residuals larger than the noise allows? RSS / sigma^2 against
// chi-squared with (n - fitted) dof for a declared noise (dof infinite), else the ratio of
// mean squares against Fisher's F(n - fitted, noise.dof) (Boost.Math distributions). An
// estimate from neighbour differences of the same residuals shares their data: F, which
// assumes independence, is then far from the truth on a small campaign (at a nominal 5 % it
// rejects 1 % of pure-noise 3 x 4 grids and so misses most remainders). Up to 400 points its
// p-value is drawn instead: 999 Gaussian residual vectors through the same contrasts and the
// same robust scale, the share whose ratio is at least the one observed (deterministic).
// `detectable`: the power of the test, as the RMS of a systematic remainder (in units of the
// noise) that lifts the statistic's median to the test's critical value at `level`, so that it
// is seen in half the campaigns; a smaller one mostly passes. It is large when the noise is
// estimated from few contrasts (a 3 x 3 grid: a remainder as large as the noise goes unseen).
struct FitTest {
    double statistic = 0;    // mean square of the residuals / sigma^2
    double p_value = 1;      // of a value at least this large if the residuals are noise only
    int n = 0, dof = 0;
    double detectable = std::numeric_limits<double>::infinity();
    // The statistic's null distribution: chi-squared / dof, Fisher's F(dof, noise dof), or the
    // drawn ratios (sorted); none when nothing was tested.
    enum class Null { none, chi_squared, fisher, drawn } null = Null::none;
    double noise_dof = 0;
    std::shared_ptr<const std::vector<double>> drawn;
};
FitTest goodness_of_fit(const std::vector<double>& residual, const NoiseEstimate& noise, int fitted_parameters,
                        double level = 0.05);

// The power of several fit tests together (the loss and the oil temperature of one campaign):
// the RMS of a remainder, the same multiple of each channel's noise in every channel, that
// lifts the median of the sum of their statistics to the sum's critical value at `level`
// (null: the tests independent). One test: its own `detectable`. Infinite when none tested.
double detectable_remainder(const std::vector<const FitTest*>& tests, double level = 0.05);

// Structure left in the residuals: for each coordinate (speed, torque, oil temperature, run
// order) a 1-D smoother in that coordinate (a running mean over the k nearest points in its
// order, k chosen by leave-one-out cross-validation from a small set), its leave-one-out
// prediction error compared with that of the mean of the others. The statistic is the best
// relative gain over the coordinates; its p-value comes from `permutations` random
// permutations of the residuals over the points (deterministic for a seed), so it holds
// for any noise distribution and accounts for taking the best of four.
struct StructureTest {
    double gain = 0;          // best relative reduction of the LOO error (0: none, 1: all)
    double p_value = 1;
    std::string coordinate;   // where it lives: "speed", "torque", "oil temperature", "run order" (empty: none)
    // The smoother's fitted values for the best coordinate (one per point), for reports.
    std::vector<double> smooth;
};
StructureTest structure(const Channel& c, int permutations = 199, std::uint64_t seed = 20261123);

// Fisher's (1932) combination of p-values: -2 sum ln p against chi-squared with 2k dof.
// Exact for independent tests; the tests of one campaign are positively dependent, which
// makes it reject somewhat more often than its level.
double combined_p(const std::vector<double>& p_values);

// The levels of Holm's step-down and of Fisher's combination over one family when a mismatch
// is claimed as soon as either rejects: half the claim's level each (Bonferroni over the two
// procedures), so that the claim holds its level. Each at the whole level, pure noise in four
// independent tests is called a mismatch in 1.6 % of campaigns, not 1 %.
struct ClaimLevels {
    double holm = 0, combination = 0;
};
ClaimLevels claim_levels(double level);

// Holm's (1979) step-down over a family of m tests at family-wise level `level`: the k-th
// smallest p-value is rejected when it and every smaller one are below level / (m - k + 1).
// Returns the bound below which a p-value of the family is rejected (0: none is).
double holm_threshold(std::vector<double> p_values, double level);

}  // namespace gearloss::diagnosis::adequacy
