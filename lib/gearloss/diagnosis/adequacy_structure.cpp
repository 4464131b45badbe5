// The absolute adequacy test, part 2: the permutation test for structure left along the
// campaign's coordinates, and the combination of the tests' p-values (see adequacy.hpp).
#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <random>

#include "gearloss/diagnosis/adequacy.hpp"
#include "gearloss/diagnosis/adequacy_detail.hpp"

namespace gearloss::diagnosis::adequacy {
using namespace detail;

namespace {

// One coordinate of the structure test: the points in its order (sorted once) and, for each
// window size, where each position's window starts in that order.
struct Axis {
    const char* name;
    Index order;
    std::vector<Index> start;  // start[w][j]: first position of the window of size ks[w] around j
};

// The window of position j: the k points nearest to it in the coordinate, the point itself
// included. In a sorted order they are consecutive, grown one point at a time towards the
// nearer value. Tied values are at distance zero, so the points of one speed level fill
// each other's windows before any point of the next level comes in: a step of one level is
// then seen by whole windows and not smeared over the level's edges. Between candidates at
// equal distance (inside a level, or equal spacing such as the run order) the side with
// fewer positions so far is taken, which centres the window.
Index window_starts(const std::vector<double>& x, const Index& order, std::size_t k) {
    const std::size_t n = order.size();
    Index start(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double xj = x[order[j]];
        std::size_t lo = j, hi = j + 1;  // [lo, hi)
        while (hi - lo < k) {
            if (lo == 0) { ++hi; continue; }
            if (hi == n) { --lo; continue; }
            const double left = xj - x[order[lo - 1]], right = x[order[hi]] - xj;
            if (left < right || (left == right && j - lo <= hi - 1 - j)) --lo;
            else ++hi;
        }
        start[j] = lo;
    }
    return start;
}

struct Best {
    double gain = 0;
    int axis = -1;
    std::size_t w = 0;  // index into the window sizes
};

// The best relative LOO gain over the axes and window sizes for residuals r (centred).
// err_mean is that of the mean of the others, the same for every ordering of r. Only sums
// over the precomputed windows: O(n) per axis and window size.
Best best_gain(const std::vector<double>& r, const std::vector<Axis>& axes, const std::vector<std::size_t>& ks,
               double err_mean, std::vector<double>& prefix) {
    const std::size_t n = r.size();
    Best best;
    for (std::size_t a = 0; a < axes.size(); ++a) {
        const Index& order = axes[a].order;
        prefix.assign(n + 1, 0.0);
        for (std::size_t j = 0; j < n; ++j) prefix[j + 1] = prefix[j] + r[order[j]];
        for (std::size_t w = 0; w < ks.size(); ++w) {
            const std::size_t k = ks[w];
            const Index& start = axes[a].start[w];
            double err = 0;
            for (std::size_t j = 0; j < n; ++j) {
                const double y = r[order[j]];
                // Leave-one-out: the point's own value is not in its prediction.
                const double loo = (prefix[start[j] + k] - prefix[start[j]] - y) / static_cast<double>(k - 1);
                err += (y - loo) * (y - loo);
            }
            const double gain = 1 - err / err_mean;
            // Strictly better only: on a tie the earlier coordinate (speed first) is named.
            if (gain > best.gain) best = {gain, static_cast<int>(a), w};
        }
    }
    return best;
}

// The coordinates to test: given, one value per point, more than one distinct value.
std::vector<Axis> structure_axes(const Channel& c, const std::vector<std::size_t>& ks) {
    const std::size_t n = c.residual.size();
    const std::pair<const char*, const std::vector<double>*> all[] = {
        {"speed", &c.speed}, {"torque", &c.torque}, {"oil temperature", &c.oil_temp}, {"run order", &c.order}};
    std::vector<Axis> axes;
    for (const auto& [name, x] : all) {
        if (x->empty()) continue;
        const auto [lo, hi] = std::minmax_element(x->begin(), x->end());
        if (*lo == *hi) continue;
        Axis axis{name, all_points(n), {}};
        sort_by(axis.order, *x);
        for (std::size_t k : ks) axis.start.push_back(window_starts(*x, axis.order, k));
        axes.push_back(std::move(axis));
    }
    return axes;
}

}  // namespace

StructureTest structure(const Channel& c, int permutations, std::uint64_t seed) {
    check_channel(c);
    StructureTest t;
    const std::size_t n = c.residual.size();
    if (n == 0) return t;
    const double mean = std::accumulate(c.residual.begin(), c.residual.end(), 0.0) / static_cast<double>(n);
    t.smooth.assign(n, mean);
    // Below 6 points a window of 2..5 is nearly the whole campaign: nothing to compare.
    if (n < 6) return t;

    // Both the smoother and the mean of the others follow an added constant: centring first
    // only keeps the sums of large channels (temperatures in K) accurate.
    std::vector<double> r(n);
    for (std::size_t i = 0; i < n; ++i) r[i] = c.residual[i] - mean;
    double err_mean = 0;
    const double total = std::accumulate(r.begin(), r.end(), 0.0);
    for (double y : r) {
        const double loo = (total - y) / static_cast<double>(n - 1);
        err_mean += (y - loo) * (y - loo);
    }
    if (!(err_mean > 0)) return t;

    // Narrow windows for a step, wide ones for a drift; a quarter of the points for large
    // campaigns. Clipped so that a window holds one other point at least and not all.
    std::vector<std::size_t> ks;
    for (std::size_t k : {std::size_t{3}, std::size_t{5}, std::size_t{9}, n / 4}) ks.push_back(std::clamp(k, std::size_t{2}, n - 1));
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    const auto axes = structure_axes(c, ks);
    if (axes.empty()) return t;

    std::vector<double> prefix;
    const Best observed = best_gain(r, axes, ks, err_mean, prefix);
    if (observed.axis < 0) return t;
    const Axis& winner = axes[static_cast<std::size_t>(observed.axis)];
    t.gain = observed.gain;
    t.coordinate = winner.name;

    // In-sample fit of the winner, for reports: the window mean including the point itself.
    const std::size_t k = ks[observed.w];
    prefix.assign(n + 1, 0.0);
    for (std::size_t j = 0; j < n; ++j) prefix[j + 1] = prefix[j] + r[winner.order[j]];
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t lo = winner.start[observed.w][j];
        t.smooth[winner.order[j]] = mean + (prefix[lo + k] - prefix[lo]) / static_cast<double>(k);
    }

    // The permutation distribution of the whole statistic (best of the coordinates and the
    // windows), so that choosing the best is paid for: the p-value holds for any exchangeable
    // noise. Counting the observed one among them keeps it above zero and the test exact.
    const int perms = std::max(permutations, 0);
    std::mt19937_64 rng(seed);
    std::vector<double> shuffled = r;
    int at_least = 0;
    for (int p = 0; p < perms; ++p) {
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        if (best_gain(shuffled, axes, ks, err_mean, prefix).gain >= observed.gain) ++at_least;
    }
    t.p_value = (1.0 + at_least) / (1.0 + perms);
    return t;
}

double combined_p(const std::vector<double>& p_values) {
    if (p_values.empty()) return 1;
    double statistic = 0;
    for (double p : p_values) statistic -= 2 * std::log(std::clamp(p, 1e-300, 1.0));
    const boost::math::chi_squared chi2(2.0 * static_cast<double>(p_values.size()));
    return boost::math::cdf(boost::math::complement(chi2, statistic));
}

double holm_threshold(std::vector<double> p_values, double level) {
    std::sort(p_values.begin(), p_values.end());
    const size_t m = p_values.size();
    double threshold = 0;
    for (size_t k = 0; k < m && p_values[k] < level / static_cast<double>(m - k); ++k)
        threshold = std::nextafter(p_values[k], 1.0);
    return threshold;
}

ClaimLevels claim_levels(double level) { return {0.5 * level, 0.5 * level}; }

}  // namespace gearloss::diagnosis::adequacy
