// The absolute adequacy test, part 1: the noise of a residual channel, goodness of fit against
// it and the fit test's power (see adequacy.hpp; structure and combination: adequacy_structure.cpp).
#include "gearloss/diagnosis/adequacy.hpp"
#include "gearloss/diagnosis/adequacy_detail.hpp"

#include <algorithm>
#include <array>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/statistics/univariate_statistics.hpp>
#include <cmath>
#include <Eigen/SparseCore>
#include <cstddef>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

namespace gearloss::diagnosis::adequacy {

namespace detail {

// A coordinate is either absent (empty) or one value per point; anything else is a caller
// error. Non-finite values would make the sorts and medians below undefined, so they are too.
void check_vector(const std::vector<double>& v, std::size_t n, const char* what, bool may_be_empty) {
    if (v.empty() && may_be_empty) return;
    if (v.size() != n)
        throw std::invalid_argument(std::string("adequacy: ") + what + " has " + std::to_string(v.size()) +
                                    " values for " + std::to_string(n) + " residuals");
    for (double x : v)
        if (!std::isfinite(x)) throw std::invalid_argument(std::string("adequacy: non-finite value in ") + what);
}

void check_channel(const Channel& c) {
    const std::size_t n = c.residual.size();
    check_vector(c.residual, n, "residual", false);
    check_vector(c.speed, n, "speed", true);
    check_vector(c.torque, n, "torque", true);
    check_vector(c.oil_temp, n, "oil temperature", true);
    check_vector(c.order, n, "run order", true);
}

// `idx` sorted by x, ties by index (a stable order, so results do not depend on the sort).
void sort_by(Index& idx, const std::vector<double>& x) {
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
}

Index all_points(std::size_t n) {
    Index idx(n);
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    return idx;
}

}  // namespace detail

using namespace detail;

namespace {

// 1 / Phi^-1(3/4): makes the median of |e| a consistent estimate of sigma for Gaussian e.
constexpr double mad_consistency = 1.4826;
// Huber's (1981, sec. 5.4) "proposal 2" scale: the root of mean(min(e^2, (c s)^2)) = kappa s^2,
// kappa = E[min(Z^2, c^2)] for a standard normal Z (consistency). With c = 2 a value beyond
// 2 s counts as 2 s, so a few points off the rest (a step, a band, an outlier) move the scale
// by a bounded amount (about a fifth of the values may be such before it breaks down), while
// for Gaussian values it is worth a standard deviation from about 88 % as many (the median
// absolute value: 37 %, Rousseeuw & Croux (1993), and biased upward by 12 % on 7 values).
// That efficiency is part of its dof.
constexpr double huber_c = 2.0;
constexpr double huber_efficiency = 0.88;

double huber_kappa() {
    const double c = huber_c, phi = std::exp(-0.5 * c * c) / std::sqrt(2 * std::numbers::pi);
    const double tail = 0.5 * std::erfc(c / std::sqrt(2.0));  // P(Z > c)
    return std::erf(c / std::sqrt(2.0)) - 2 * c * phi + 2 * c * c * tail;
}

// Robust scale of values that have zero mean under the null: about zero, not about their
// median, since a common shift is structure and not noise. Huber's proposal 2 by fixed-point
// iteration from the median absolute value (a contraction for c = 2; converged to 1e-10).
double robust_scale(const std::vector<double>& e) {
    if (e.empty()) return 0;
    std::vector<double> a(e.size());
    std::transform(e.begin(), e.end(), a.begin(), [](double x) { return std::abs(x); });
    // The median absolute value (the mean of the middle two for an even count), on a copy: the
    // sums below stay in the values' order.
    std::vector<double> m = a;
    double s = mad_consistency * boost::math::statistics::median(m);
    if (!(s > 0)) {  // more than half the values zero: start from the root mean square
        for (double x : a) s += x * x / static_cast<double>(a.size());
        s = std::sqrt(s);
    }
    if (!(s > 0)) return 0;
    static const double kappa = huber_kappa();
    for (int it = 0; it < 200; ++it) {
        double w = 0;
        for (double x : a) w += std::min(x * x, huber_c * huber_c * s * s);
        const double next = std::sqrt(w / (static_cast<double>(a.size()) * kappa));
        const bool done = std::abs(next - s) <= 1e-10 * s;
        s = next;
        if (done) break;
    }
    return s;
}

// Levels of a coordinate among the points `idx`: sorted by x, a new level where the gap to the
// previous value exceeds rel_tol of their magnitude. The magnitude has a floor (a thousandth
// of the coordinate's largest) so that set points at zero jittering around it stay one level.
// An absent coordinate is one level.
std::vector<Index> split_levels(const std::vector<double>& x, Index idx, double rel_tol) {
    if (x.empty() || idx.empty()) return {std::move(idx)};
    sort_by(idx, x);
    double largest = 0;
    for (double v : x) largest = std::max(largest, std::abs(v));
    std::vector<Index> out(1);
    out.back().push_back(idx[0]);
    for (std::size_t j = 1; j < idx.size(); ++j) {
        const double a = x[idx[j - 1]], b = x[idx[j]];
        const double scale = std::max({std::abs(a), std::abs(b), 1e-3 * largest});
        if (b - a > rel_tol * scale) out.emplace_back();
        out.back().push_back(idx[j]);
    }
    return out;
}

// Level number of each point in a coordinate (all 0 when it is absent).
std::vector<int> level_ids(const std::vector<double>& x, std::size_t n, double rel_tol) {
    std::vector<int> id(n, 0);
    const auto levels = split_levels(x, all_points(n), rel_tol);
    for (std::size_t l = 0; l < levels.size(); ++l)
        for (std::size_t i : levels[l]) id[i] = static_cast<int>(l);
    return id;
}

// 1. Replicates: pooled within-group variance over operating points recorded more than once.
// Needs both speed and torque, since an absent one cannot tell two operating points apart.
bool replicate_noise(const Channel& c, double rel_tol, NoiseEstimate& out) {
    const std::size_t n = c.residual.size();
    if (c.speed.empty() || c.torque.empty()) return false;
    double ss = 0;
    int dof = 0, groups = 0;
    for (const Index& level : split_levels(c.speed, all_points(n), rel_tol))
        for (const Index& g : split_levels(c.torque, level, rel_tol)) {
            if (g.size() < 2) continue;
            double mean = 0;
            for (std::size_t i : g) mean += c.residual[i];
            mean /= static_cast<double>(g.size());
            for (std::size_t i : g) ss += (c.residual[i] - mean) * (c.residual[i] - mean);
            dof += static_cast<int>(g.size()) - 1;
            ++groups;
        }
    // Two groups, or three dof in one: fewer is too little to be worth more than the
    // neighbour differences of the whole grid.
    if (groups < 2 && dof < 3) return false;
    out.sigma = std::sqrt(ss / dof);
    out.dof = dof;
    out.source = "replicates";
    out.pairs = groups;
    return true;
}

// A pseudo-residual's coefficients on the residuals: value = sum of coefficient x residual.
using ContrastRow = std::vector<std::pair<std::size_t, double>>;

// One pseudo-residual: its value, the contrast it belongs to (see grid_pseudo_residuals) and
// its row, from which the estimate's degrees of freedom (effective_dof) and the fit test's
// null distribution (null_ratios) follow.
struct Pseudo {
    double value;
    std::array<int, 4> key;  // axis, level ids of the left, centre and right points
    ContrastRow row;
};

// 2. Pseudo-residuals of Gasser et al. (1986) along one axis: within each line (a level of the
// other coordinate) the points sorted by x, each interior point against the straight line
// through its two neighbours, normalised so that it has the noise's variance when the truth
// is locally linear.
void line_pseudo_residuals(const Channel& c, const std::vector<double>& x, const std::vector<double>& across,
                           const std::vector<int>& x_level, int axis, double rel_tol, std::vector<Pseudo>& out) {
    for (Index line : split_levels(across, all_points(c.residual.size()), rel_tol)) {
        sort_by(line, x);
        for (std::size_t j = 1; j + 1 < line.size(); ++j) {
            const std::size_t a = line[j - 1], i = line[j], b = line[j + 1];
            const double span = x[b] - x[a];
            // Zero spread (three points at one x): the line through the neighbours is their mean.
            double wa = 0.5, wb = 0.5;
            if (span > 0) {
                wa = (x[b] - x[i]) / span;
                wb = (x[i] - x[a]) / span;
            }
            const double norm = std::sqrt(wa * wa + wb * wb + 1);
            const double e = (wa * c.residual[a] + wb * c.residual[b] - c.residual[i]) / norm;
            out.push_back({e, {axis, x_level[a], x_level[i], x_level[b]}, {{a, wa / norm}, {b, wb / norm}, {i, -1 / norm}}});
        }
    }
}

std::vector<Pseudo> grid_pseudo_residuals(const Channel& c, double rel_tol) {
    const std::size_t n = c.residual.size();
    const auto speed_level = level_ids(c.speed, n, rel_tol);
    const auto torque_level = level_ids(c.torque, n, rel_tol);
    std::vector<Pseudo> p;
    if (!c.torque.empty()) line_pseudo_residuals(c, c.torque, c.speed, torque_level, 0, rel_tol, p);
    if (!c.speed.empty()) line_pseudo_residuals(c, c.speed, c.torque, speed_level, 1, rel_tol, p);
    return p;
}

// The same contrast (same axis, same three levels) in several lines: on a grid, a step of
// one speed level (an offset of the whole level) enters every torque line's contrast around
// that level by the same amount, and that is structure in speed, not noise. Its mean over the
// lines is removed, each value rescaled by sqrt(m / (m - 1)) so that it keeps the noise's
// variance (the lines share no point). Without this, a 3-sigma step at a middle level of 5
// puts 18 of the 38 pseudo-residuals of a 5 x 6 grid off zero, and a median cannot stand
// half of them (+50 % on sigma). Likewise for a step of one torque level. An offset of only
// part of a level's torques is not common to all lines and stays a (bounded) contamination.
// (Each removal costs one dof, which effective_dof sees in the rows.)
void remove_common_contrasts(std::vector<Pseudo>& p) {
    std::map<std::array<int, 4>, std::vector<std::size_t>> groups;
    for (std::size_t j = 0; j < p.size(); ++j) groups[p[j].key].push_back(j);
    for (const auto& [key, members] : groups) {
        if (members.size() < 2) continue;
        const double m = static_cast<double>(members.size()), k = std::sqrt(m / (m - 1));
        double mean = 0;
        ContrastRow mean_row;
        for (std::size_t j : members) {
            mean += p[j].value / m;
            for (auto [i, w] : p[j].row) mean_row.emplace_back(i, w / m);
        }
        for (std::size_t j : members) {
            p[j].value = (p[j].value - mean) * k;
            for (auto& [i, w] : p[j].row) w *= k;
            for (auto [i, w] : mean_row) p[j].row.emplace_back(i, -k * w);
        }
    }
}

// Average ranks of x scaled to [0, 1] (all 0 when absent or constant): the plane in which
// nearest neighbours are found, so that neither coordinate's unit weighs more.
std::vector<double> normalised_ranks(const std::vector<double>& x, std::size_t n) {
    std::vector<double> rank(n, 0);
    if (x.empty() || n < 2) return rank;
    Index idx = all_points(n);
    sort_by(idx, x);
    for (std::size_t j = 0; j < n;) {
        std::size_t k = j;
        while (k + 1 < n && x[idx[k + 1]] == x[idx[j]]) ++k;
        for (std::size_t m = j; m <= k; ++m) rank[idx[m]] = 0.5 * static_cast<double>(j + k);
        j = k + 1;
    }
    for (double& r : rank) r /= static_cast<double>(n - 1);
    return rank;
}

// 2b. Scattered points (no level holds three): the difference of each point and its nearest
// other point in the (speed, torque) rank plane, each unordered pair once.
std::vector<Pseudo> nearest_neighbour_pseudo_residuals(const Channel& c) {
    const std::size_t n = c.residual.size();
    std::vector<Pseudo> e;
    if (c.speed.empty() && c.torque.empty()) return e;
    const auto u = normalised_ranks(c.speed, n), v = normalised_ranks(c.torque, n);
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t best = n;
        double best_d = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < n; ++j) {
            if (j == i) continue;
            const double d = (u[i] - u[j]) * (u[i] - u[j]) + (v[i] - v[j]) * (v[i] - v[j]);
            if (d < best_d) best_d = d, best = j;
        }
        if (best < n) pairs.insert({std::min(i, best), std::max(i, best)});
    }
    const double h = 1 / std::sqrt(2.0);
    for (const auto& [i, j] : pairs)
        e.push_back({(c.residual[i] - c.residual[j]) * h, {}, {{i, h}, {j, -h}}});
    return e;
}

// The degrees of freedom of a mean square of the pseudo-residuals e = A r when the residuals
// r are independent noise: Satterthwaite's (1946) tr(C)^2 / tr(C^2) with C = A A^T. The
// pseudo-residuals share points (a point is the centre of one contrast and the neighbour of
// up to four), so they are worth fewer than their number: on a 3 x 4 grid 10 of them, less
// the 3 common contrasts removed, carry about 4 dof, not 7.
double effective_dof(const std::vector<ContrastRow>& rows, std::size_t n) {
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t j = 0; j < rows.size(); ++j)
        for (auto [i, w] : rows[j]) t.emplace_back(static_cast<int>(j), static_cast<int>(i), w);
    Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(n));
    A.setFromTriplets(t.begin(), t.end());  // repeated (row, point) entries are summed
    const Eigen::SparseMatrix<double> C = A * A.transpose();
    const double tr = C.diagonal().sum(), tr2 = C.squaredNorm();  // C symmetric: tr(C^2) = |C|_F^2
    return tr2 > 0 ? tr * tr / tr2 : 0.0;
}

}  // namespace

struct Contrasts {
    std::size_t points = 0;
    std::vector<ContrastRow> rows;
};

namespace {

NoiseEstimate from_pseudo_residuals(std::vector<Pseudo> p, std::size_t n) {
    std::vector<double> e;
    auto contrasts = std::make_shared<Contrasts>();
    contrasts->points = n;
    for (Pseudo& q : p) {
        e.push_back(q.value);
        contrasts->rows.push_back(std::move(q.row));
    }
    NoiseEstimate out;
    out.sigma = robust_scale(e);
    out.dof = std::max(1.0, huber_efficiency * effective_dof(contrasts->rows, n));
    out.source = "neighbour differences";
    out.pairs = static_cast<int>(e.size());
    out.contrasts = std::move(contrasts);
    return out;
}

// The mean-square ratios (mean square of the residuals over the squared robust scale of their
// contrasts) of 999 Gaussian residual vectors through these contrasts, sorted: the null
// distribution of the fit test's statistic. It depends on the points' coordinates only, so a
// campaign's hypotheses share it: the last few are kept (keyed by the contrasts themselves).
std::shared_ptr<const std::vector<double>> null_ratios(const std::shared_ptr<const Contrasts>& key) {
    static std::mutex guard;
    static std::vector<std::pair<std::shared_ptr<const Contrasts>, std::shared_ptr<const std::vector<double>>>> kept;
    const Contrasts& c = *key;
    auto same = [&](const Contrasts& k) { return &k == &c || (k.points == c.points && k.rows == c.rows); };
    {
        std::lock_guard<std::mutex> lock(guard);
        for (const auto& [k, v] : kept)
            if (same(*k)) return v;
    }
    constexpr int draws = 999;
    std::mt19937_64 rng(20261124);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> z(c.points), e(c.rows.size());
    auto ratios = std::make_shared<std::vector<double>>();
    for (int d = 0; d < draws; ++d) {
        double ss = 0;
        for (double& x : z) x = normal(rng), ss += x * x;
        for (std::size_t j = 0; j < c.rows.size(); ++j) {
            e[j] = 0;
            for (auto [i, w] : c.rows[j]) e[j] += w * z[i];
        }
        const double s = robust_scale(e);
        ratios->push_back(s > 0 ? ss / static_cast<double>(c.points) / (s * s) : std::numeric_limits<double>::infinity());
    }
    std::sort(ratios->begin(), ratios->end());
    std::lock_guard<std::mutex> lock(guard);
    if (kept.size() >= 8) kept.erase(kept.begin());
    kept.emplace_back(key, ratios);
    return ratios;
}

// The p-value of an observed ratio: the share of the null draws at least as large (with the
// observation counted among them, so never 0).
double drawn_fit_p(const std::shared_ptr<const Contrasts>& c, double statistic) {
    const auto r = null_ratios(c);
    const auto at_least = r->end() - std::lower_bound(r->begin(), r->end(), statistic);
    return (1.0 + static_cast<double>(at_least)) / (static_cast<double>(r->size()) + 1.0);
}

}  // namespace

NoiseEstimate estimate_noise(const Channel& c, double rel_tol) {
    check_channel(c);
    NoiseEstimate out;
    out.source = "none";
    if (replicate_noise(c, rel_tol, out)) return out;

    const std::size_t n = c.residual.size();
    auto grid = grid_pseudo_residuals(c, rel_tol);
    if (grid.size() >= 3) {
        remove_common_contrasts(grid);
        return from_pseudo_residuals(std::move(grid), n);
    }
    const auto e = nearest_neighbour_pseudo_residuals(c);
    if (e.size() >= 3) return from_pseudo_residuals(e, n);
    return out;
}

namespace {

// A test's null distribution at `draws` evenly spaced probabilities (sorted): the drawn ratios
// themselves, or the quantiles of chi-squared / dof or F.
std::vector<double> null_sample(const FitTest& t, std::size_t draws) {
    if (t.null == FitTest::Null::drawn) return *t.drawn;
    std::vector<double> q(draws);
    const double dof = t.dof;
    for (std::size_t j = 0; j < draws; ++j) {
        const double p = (static_cast<double>(j) + 0.5) / static_cast<double>(draws);
        q[j] = t.null == FitTest::Null::chi_squared ? boost::math::quantile(boost::math::chi_squared(dof), p) / dof
                                                    : boost::math::quantile(boost::math::fisher_f(dof, t.noise_dof), p);
    }
    return q;
}

}  // namespace

double detectable_remainder(const std::vector<const FitTest*>& tests, double level) {
    // Under a remainder of variance v sigma^2 in each channel every statistic is about (1 + v)
    // times its null value (the noise estimate, from contrasts, does not see a smooth
    // remainder), so the sum is too: v = critical / median - 1 of the null sum.
    constexpr std::size_t draws = 999, pairings = 8;
    std::vector<double> sum;
    std::mt19937_64 rng(20261124);
    for (const FitTest* t : tests) {
        if (!t || t->null == FitTest::Null::none) continue;
        const std::vector<double> x = null_sample(*t, draws);
        if (sum.empty()) {
            sum = x;
            continue;
        }
        // Independent channels: the sum so far paired with this sample in shuffled orders
        // (the drawn samples of two channels on the same points are the same sequence).
        std::vector<double> next;
        for (std::size_t k = 0; k < pairings; ++k) {
            std::vector<double> y = x;
            std::shuffle(y.begin(), y.end(), rng);
            for (std::size_t j = 0; j < sum.size(); ++j) next.push_back(sum[j] + y[j % y.size()]);
        }
        sum = std::move(next);
        if (sum.size() > pairings * draws) {  // three or more channels: keep the sample's size bounded
            std::shuffle(sum.begin(), sum.end(), rng);
            sum.resize(pairings * draws);
        }
    }
    if (sum.empty()) return std::numeric_limits<double>::infinity();
    std::sort(sum.begin(), sum.end());
    // The sample's quantile at q, its j-th value taken at probability (j + 1/2) / size.
    const auto at = [&](double q) {
        const double last = static_cast<double>(sum.size() - 1);
        const double pos = std::clamp(q * static_cast<double>(sum.size()) - 0.5, 0.0, last);
        const std::size_t j = static_cast<std::size_t>(std::min(pos, std::max(last - 1, 0.0)));
        return j + 1 < sum.size() ? sum[j] + (pos - static_cast<double>(j)) * (sum[j + 1] - sum[j]) : sum[j];
    };
    const double critical = at(1 - level), median = at(0.5);
    if (!(median > 0) || !std::isfinite(critical)) return std::numeric_limits<double>::infinity();
    return std::sqrt(std::max(0.0, critical / median - 1));
}

FitTest goodness_of_fit(const std::vector<double>& residual, const NoiseEstimate& noise, int fitted_parameters,
                        double level) {
    check_vector(residual, residual.size(), "residual", false);
    if (fitted_parameters < 0) throw std::invalid_argument("adequacy: negative number of fitted parameters");
    FitTest t;
    t.n = static_cast<int>(residual.size());
    const int dof = t.n - fitted_parameters;
    // Nothing left to test: the model can pass through every point.
    if (dof <= 0) return t;
    t.dof = dof;
    if (!noise.known() || !std::isfinite(noise.sigma)) return t;
    double rss = 0;
    for (double r : residual) rss += r * r;
    const double chi2 = rss / (noise.sigma * noise.sigma);
    t.statistic = chi2 / dof;
    // A declared noise is known exactly: RSS / sigma^2 is chi-squared. An estimated one has
    // its own chi-squared of noise.dof in the denominator: the ratio is Fisher's F, or, for
    // neighbour differences of these residuals, its distribution drawn through their contrasts.
    if (std::isinf(noise.dof)) {
        t.null = FitTest::Null::chi_squared;
        t.p_value = boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), chi2));
    } else if (noise.contrasts && noise.contrasts->points == residual.size() && residual.size() <= 400) {
        t.null = FitTest::Null::drawn;
        t.drawn = null_ratios(noise.contrasts);
        t.p_value = drawn_fit_p(noise.contrasts, t.statistic);
    } else {
        t.null = FitTest::Null::fisher;
        t.p_value = boost::math::cdf(boost::math::complement(boost::math::fisher_f(dof, noise.dof), t.statistic));
    }
    t.noise_dof = noise.dof;
    t.detectable = detectable_remainder({&t}, level);
    return t;
}

}  // namespace gearloss::diagnosis::adequacy
