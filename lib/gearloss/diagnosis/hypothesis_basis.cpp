// The basis columns of the remainder formula: powers of speed, load and viscosity with the
// exponent on a grid of 0.1 (a one-dimensional search done by the cross-validated selection),
// steps and thresholds at the midpoints of the recorded values of each variable, windows at
// the recorded speed levels, low powers of speed and load gated by a threshold of another
// variable, the oil where several were recorded, and the run order where it was recorded.
//
// The library is deliberately readable: the engineer has to recognise each term, so a
// flexible but opaque fit (splines, kernels) would defeat the point.
#include "gearloss/diagnosis/hypothesis_basis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

namespace gearloss::diagnosis::hypothesis::detail {

std::string fmt(double v, int sig) {
    if (v == 0 || !std::isfinite(v)) return v == 0 ? "0" : std::to_string(v);
    const double a = std::fabs(v);
    char buf[64];
    if (a >= 1e6 || a < 1e-4) {
        std::snprintf(buf, sizeof buf, "%.*e", sig - 1, v);
        return buf;
    }
    const int mag = static_cast<int>(std::floor(std::log10(a)));
    const double unit = std::pow(10.0, mag - sig + 1);
    const double r = std::round(v / unit) * unit;
    const int decimals = std::max(0, sig - 1 - mag);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, r);
    return buf;
}

std::string num(double v, int sig) {
    std::string s = fmt(v, sig);
    if (s.find('.') != std::string::npos && s.find('e') == std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
    }
    return s;
}

namespace {

using losses::EmpiricalFactor;
using losses::EmpiricalShape;
using losses::EmpiricalTerm;
using losses::EmpiricalVariable;

constexpr double kPi = 3.14159265358979323846;

// A variable of the operating point: its names, unit, SI conversion and reference scale.
struct Variable {
    EmpiricalVariable id;
    const char* key;     // "speed_rpm"
    const char* symbol;  // "n"
    const char* unit;    // "rpm"
    double to_si_scale, to_si_offset;
    double reference;    // in `unit`: the scale of powers and thresholds
    const std::vector<double>* values;
    double si(double v) const { return v * to_si_scale + to_si_offset; }
    double si_scale(double v) const { return v * to_si_scale; }
};

// Levels of a variable: sorted values split where the gap exceeds 1 % of the recorded range
// (speed: of the larger value, as a rig's set-points wander by a fraction of a percent).
struct Levels {
    std::vector<double> lo, hi, mean;
};

Levels levels(const std::vector<double>& v, bool relative_to_value) {
    std::vector<double> s = v;
    std::sort(s.begin(), s.end());
    Levels L;
    const double range = s.back() - s.front();
    double sum = 0;
    int count = 0;
    for (std::size_t r = 0; r < s.size(); ++r) {
        if (r > 0) {
            const double gap = s[r] - s[r - 1];
            const double tol = relative_to_value ? 0.01 * std::max(std::fabs(s[r]), std::fabs(s[r - 1])) : 0.01 * range;
            if (gap > tol) {
                L.mean.push_back(sum / count);
                sum = 0;
                count = 0;
            }
        }
        if (count == 0) {
            L.lo.push_back(s[r]);
            L.hi.push_back(s[r]);
        }
        L.hi.back() = s[r];
        sum += s[r];
        ++count;
    }
    L.mean.push_back(sum / count);
    return L;
}

// Cut points: the midpoints between levels, at most max_cuts of them (spread evenly when more).
std::vector<double> cuts(const Levels& L, std::size_t max_cuts) {
    std::vector<double> c;
    for (std::size_t j = 0; j + 1 < L.lo.size(); ++j) c.push_back(0.5 * (L.hi[j] + L.lo[j + 1]));
    if (c.size() <= max_cuts) return c;
    std::vector<double> out;
    for (std::size_t k = 0; k < max_cuts; ++k) out.push_back(c[(2 * k + 1) * c.size() / (2 * max_cuts)]);
    return out;
}

std::string mechanism_of(const Term& t) {
    if (t.variable == "order") return "running-in or drift during the campaign (not a law of the operating point)";
    if (t.variable == "oil") return "a property of one oil the case does not describe (its friction or viscosity law)";
    if (t.shape == "constant") return "a constant parasitic loss (pump, auxiliary drag)";
    const bool gated = t.gate.has_value();
    if (t.shape == "power") {
        std::string m;
        if (t.variable == "speed_rpm")
            m = t.exponent < 1.3   ? "seal friction or a torque-sensor offset (~ n)"
                : t.exponent < 2.4 ? "churning (~ n^1.5-2)"
                                   : "windage (n^2.9)";
        else if (t.variable == "torque_Nm")
            m = "mesh friction (load-dependent)";
        else
            m = "bearing or churning drag (viscous)";
        if (t.window) m += ", only at one speed (a resonance or a local contact problem?)";
        if (gated && t.gate->variable == "oil_temp_C")
            m += t.gate->above ? ", only in hot oil (a thermostat, a bypass or a thinning film?)" : ", only in cold oil";
        else if (gated)
            m += t.gate->above ? ", only above a threshold (something engaging?)" : ", only below a threshold";
        return m;
    }
    if (t.variable == "speed_rpm")
        return t.shape == "window" ? "a resonance or a local contact problem at one speed"
                                   : "a loss that switches on above a speed (a pump or a clutch engaging?)";
    if (t.variable == "torque_Nm")
        return t.shape == "threshold" ? "mesh friction rising beyond a load (mixed lubrication, a thinner film?)"
                                      : "a loss that switches on above a load (a contact or a clutch engaging?)";
    if (t.variable == "oil_temp_C")
        return t.above ? "a loss that appears only in hot oil (a thermostat or bypass?)"
                       : "a loss that appears only in cold oil (thick-oil drag, a cold-start bypass?)";
    return t.above ? "a loss in thick (cold) oil: churning or bearing drag beyond the model's"
                   : "a loss in thin (hot) oil: a film breaking down (mixed friction?)";
}

class Library {
public:
    explicit Library(std::size_t n) : n_(n) {
        std::uint64_t s = 88172645463325252ull;  // xorshift: a fixed probe vector for duplicate signatures
        probe_.resize(static_cast<Eigen::Index>(n));
        for (Eigen::Index i = 0; i < probe_.size(); ++i) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            probe_(i) = static_cast<double>(s % 1000003) / 1000003.0 + 0.5;
        }
    }

    // Skips constant columns (the intercept aside) and duplicates up to a factor (including a
    // sign): they add nothing to the fit and would make the selection ambiguous.
    void add(Term t, Eigen::VectorXd x) {
        const double amax = x.cwiseAbs().maxCoeff();
        if (!(amax > 0) || !x.allFinite()) return;
        if (t.shape != "constant" && x.maxCoeff() - x.minCoeff() <= 1e-12 * amax) return;
        const Eigen::VectorXd u = x / amax;
        const double sig = u.dot(probe_);
        for (std::size_t k = 0; k < sig_.size(); ++k) {
            if (std::fabs(std::fabs(sig) - std::fabs(sig_[k])) > 1e-9 * static_cast<double>(n_)) continue;
            const Eigen::VectorXd& c = cols[k].x;
            const double cmax = c.cwiseAbs().maxCoeff();
            if ((u - c / cmax).cwiseAbs().maxCoeff() < 1e-9 || (u + c / cmax).cwiseAbs().maxCoeff() < 1e-9) return;
        }
        sig_.push_back(sig);
        std::string m = mechanism_of(t);
        cols.push_back({std::move(t), std::move(m), std::move(x)});
    }

    std::vector<Column> cols;

private:
    std::size_t n_;
    Eigen::VectorXd probe_;
    std::vector<double> sig_;
};

// One factor's display and its calibration factor.
struct Piece {
    std::string text;
    EmpiricalFactor factor;
};

Piece power(const Variable& v, double a) {
    Piece p;
    p.factor = {v.id, EmpiricalShape::power, v.si_scale(v.reference), a, 0, 0, 0};
    p.text = "(" + std::string(v.symbol) + "/" + num(v.reference, 4) + " " + v.unit + ")";
    if (std::fabs(a - 1) > 1e-9) p.text += "^" + num(a, 3);
    return p;
}

Piece step(const Variable& v, double c, bool above) {
    Piece p;
    p.factor = {v.id, EmpiricalShape::step, 1, 1, v.si(c), 0, 0};
    p.factor.below = !above;
    p.text = "[" + std::string(v.symbol) + (above ? " > " : " <= ") + num(c, 4) + " " + v.unit + "]";
    return p;
}

Piece hinge(const Variable& v, double c, bool above) {
    Piece p;
    p.factor = {v.id, EmpiricalShape::threshold, v.si_scale(v.reference), 1, v.si(c), 0, 0};
    p.factor.below = !above;
    const std::string at = num(c, 4) + " " + v.unit;
    p.text = "max(0, " + (above ? std::string(v.symbol) + " - " + at : at + " - " + v.symbol) + ")/" +
             num(v.reference, 3) + " " + (v.id == EmpiricalVariable::oil_temperature ? "K" : v.unit);
    return p;
}

// The oil temperature that splits the points as the viscosity threshold c does: the midpoint
// between the hottest point above c and the coldest at or below it, when all above are colder.
double split_temperature(const Features& f, double c) {
    double hottest_thick = -1e300, coldest_thin = 1e300;
    for (std::size_t i = 0; i < f.viscosity_cSt.size(); ++i) {
        if (f.viscosity_cSt[i] > c) hottest_thick = std::max(hottest_thick, f.oil_temp_C[i]);
        else coldest_thin = std::min(coldest_thin, f.oil_temp_C[i]);
    }
    return hottest_thick < coldest_thin ? 0.5 * (hottest_thick + coldest_thin) : kNone;
}

}  // namespace

std::vector<Column> build_library(const Features& f, std::size_t n) {
    Library lib(n);
    // Every column's values come from the calibration term itself (SI), so that the formula
    // written into a case is the formula fitted.
    const auto N = static_cast<Eigen::Index>(n);
    auto si_at = [&](std::size_t i, EmpiricalVariable id) {
        switch (id) {
            case EmpiricalVariable::speed: return f.speed_rpm[i] * 2 * kPi / 60;
            case EmpiricalVariable::torque: return f.torque_Nm[i];
            case EmpiricalVariable::oil_temperature: return f.oil_temp_C[i] + 273.15;
            case EmpiricalVariable::viscosity: return f.viscosity_cSt[i] * 1e-6;
        }
        return 0.0;
    };
    auto values = [&](const EmpiricalTerm& t) {
        Eigen::VectorXd v(N);
        for (std::size_t i = 0; i < n; ++i) {
            double b = 1;
            for (const auto& fac : t.factors) b *= fac.value(si_at(i, fac.variable));
            v(static_cast<Eigen::Index>(i)) = b;
        }
        return v;
    };
    auto add = [&](std::vector<Piece> pieces, Term t) {
        EmpiricalTerm e;
        e.coefficient = 1;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            t.basis += (k ? " " : "") + pieces[k].text;
            e.factors.push_back(pieces[k].factor);
        }
        e.oil = t.oil;
        Eigen::VectorXd x = values(e);
        t.empirical = std::move(e);
        lib.add(std::move(t), std::move(x));
    };

    {
        Term c;
        c.basis = "1";
        c.shape = "constant";
        EmpiricalTerm e;
        e.coefficient = 1;
        c.empirical = e;
        lib.add(c, Eigen::VectorXd::Ones(N));
    }

    double tmax = 0;
    for (double t : f.torque_Nm) tmax = std::max(tmax, std::fabs(t));
    std::vector<Variable> vars;
    if (!f.speed_rpm.empty()) vars.push_back({EmpiricalVariable::speed, "speed_rpm", "n", "rpm", 2 * kPi / 60, 0, 1000, &f.speed_rpm});
    if (!f.torque_Nm.empty() && tmax > 0)
        vars.push_back({EmpiricalVariable::torque, "torque_Nm", "T_in", "N*m", 1, 0, std::stod(num(tmax, 4)), &f.torque_Nm});
    if (!f.oil_temp_C.empty())
        vars.push_back({EmpiricalVariable::oil_temperature, "oil_temp_C", "theta_oil", "degC", 1, 273.15, 10, &f.oil_temp_C});
    if (!f.viscosity_cSt.empty())
        vars.push_back({EmpiricalVariable::viscosity, "viscosity_cSt", "nu", "cSt", 1e-6, 0, 100, &f.viscosity_cSt});
    const Variable* speed = nullptr;
    const Variable* torque = nullptr;
    for (const auto& v : vars) {
        if (v.id == EmpiricalVariable::speed) speed = &v;
        if (v.id == EmpiricalVariable::torque) torque = &v;
    }

    // Powers with the exponent searched on a grid of 0.1: speed 0.3-5 (seals ~1, churning
    // 1.5-2, windage ~2.9, oil squeezing and pumping faster), load 0.5-3, viscosity -1.5-1.5 (Petroff drag ~ nu, Palmgren ~ nu^(2/3)).
    auto power_term = [&](const Variable& v, double a) {
        Term t;
        t.shape = "power";
        t.variable = v.key;
        t.exponent = a;
        add({power(v, a)}, t);
    };
    for (const auto& v : vars) {
        if (v.id == EmpiricalVariable::oil_temperature) continue;  // no physical reference for a power of it
        const double lo = v.id == EmpiricalVariable::speed ? 0.3 : v.id == EmpiricalVariable::torque ? 0.5 : -1.5;
        const double hi = v.id == EmpiricalVariable::speed ? 5.0 : v.id == EmpiricalVariable::torque ? 3.0 : 1.5;
        for (int k = 0; lo + 0.1 * k <= hi + 1e-9; ++k) {
            const double a = std::round((lo + 0.1 * k) * 10) / 10;
            if (a != 0) power_term(v, a);
        }
    }
    // Speed times load (mesh friction, a torque-sensor gain: P ~ n T).
    if (speed && torque) {
        Term t;
        t.shape = "power";
        t.variable = "torque_Nm";
        t.exponent = 1;
        add({power(*speed, 1), power(*torque, 1)}, t);
    }

    // Steps and thresholds at the midpoints between the recorded levels of each variable,
    // either way (above; at and below), and low powers of speed and load gated by them.
    for (const auto& v : vars) {
        const Levels L = levels(*v.values, v.id == EmpiricalVariable::speed || v.id == EmpiricalVariable::torque);
        for (double c : cuts(L, 24)) {
            for (bool above : {true, false}) {
                Term s;
                s.shape = "step";
                s.variable = v.key;
                s.threshold = c;
                s.above = above;
                if (v.id == EmpiricalVariable::viscosity && !f.oil_temp_C.empty()) s.oil_temp_equivalent = split_temperature(f, c);
                add({step(v, c, above)}, s);
                Term h = s;
                h.shape = "threshold";
                add({hinge(v, c, above)}, h);
                for (const Variable* g : {speed, torque}) {
                    if (!g || g == &v) continue;
                    for (double a : {1.0, 2.0, 3.0}) {
                        if (g == torque && a == 3.0) continue;
                        Term t;
                        t.shape = "power";
                        t.variable = g->key;
                        t.exponent = a;
                        t.gate = Gate{v.key, c, above};
                        add({power(*g, a), step(v, c, above)}, t);
                    }
                }
            }
        }
    }

    // Windows at the recorded speed levels (a resonance), alone and growing with load squared.
    if (speed) {
        const Levels L = levels(f.speed_rpm, true);
        if (L.mean.size() >= 3 && L.mean.size() <= 12) {
            for (std::size_t j = 0; j < L.mean.size(); ++j) {
                const double lower = j == 0 ? L.lo[0] - 0.5 * (L.lo[1] - L.hi[0]) : 0.5 * (L.hi[j - 1] + L.lo[j]);
                const double upper = j + 1 == L.mean.size() ? L.hi[j] + 0.5 * (L.lo[j] - L.hi[j - 1])
                                                            : 0.5 * (L.hi[j] + L.lo[j + 1]);
                Piece w;
                w.factor = {EmpiricalVariable::speed, EmpiricalShape::window, 1, 1, 0, speed->si(lower), speed->si(upper)};
                w.text = "[n = " + num(L.mean[j], 4) + " rpm]";
                Term t;
                t.shape = "window";
                t.variable = "speed_rpm";
                t.lower = lower;
                t.upper = upper;
                add({w}, t);
                if (torque) {  // the same window, growing with load squared: a power of load in a window
                    Term tq;
                    tq.shape = "power";
                    tq.variable = "torque_Nm";
                    tq.exponent = 2;
                    tq.window = Window{"speed_rpm", lower, upper};
                    add({power(*torque, 2), w}, tq);
                }
            }
        }
    }

    // The oil, where several were recorded: a constant and a speed-proportional loss per oil.
    if (!f.oil.empty()) {
        std::vector<std::string> names = f.oil;
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
        if (names.size() >= 2)
            for (const auto& o : names) {
                Term t;
                t.shape = "constant";
                t.variable = "oil";
                t.oil = o;
                Eigen::VectorXd x(N);
                for (std::size_t i = 0; i < n; ++i) x(static_cast<Eigen::Index>(i)) = f.oil[i] == o ? 1.0 : 0.0;
                t.basis = "[oil = " + o + "]";
                EmpiricalTerm e;
                e.coefficient = 1;
                e.oil = o;
                t.empirical = e;
                lib.add(t, x);
                if (speed) {
                    Term s = t;
                    s.shape = "power";
                    s.exponent = 1;
                    const Piece p = power(*speed, 1);
                    s.basis = p.text + " [oil = " + o + "]";
                    e.factors = {p.factor};
                    s.empirical = e;
                    Eigen::VectorXd xs = x;
                    for (std::size_t i = 0; i < n; ++i) xs(static_cast<Eigen::Index>(i)) *= f.speed_rpm[i] / 1000;
                    lib.add(s, xs);
                }
            }
    }

    if (!f.order.empty()) {
        // k: the rank of each point in the run order (0 = first recorded), so that gaps or
        // offsets in the row numbers do not matter.
        std::vector<std::size_t> idx(n);
        std::iota(idx.begin(), idx.end(), 0);
        std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return f.order[a] < f.order[b]; });
        std::vector<double> k(n);
        for (std::size_t r = 0; r < n; ++r) k[idx[r]] = static_cast<double>(r);
        const double Nd = static_cast<double>(n);
        auto run = [&](std::string basis, const char* shape, auto fn, bool of_the_loss) {
            Term t;
            t.basis = std::move(basis);
            t.shape = shape;
            t.variable = "order";
            t.relative = of_the_loss;
            Eigen::VectorXd x(N);
            for (std::size_t i = 0; i < n; ++i)
                x(static_cast<Eigen::Index>(i)) = fn(k[i]) * (of_the_loss ? f.model_loss_W[i] : 1.0);
            lib.add(t, x);
        };
        for (double frac : {0.08, 0.1, 0.12, 0.15, 0.18, 0.21, 0.24, 0.27, 0.3, 0.35, 0.4, 0.5, 0.6}) {
            const double tau = frac * Nd;
            run("exp(-k/" + num(tau, 3) + ")", "exp", [tau](double kk) { return std::exp(-kk / tau); }, false);
            // Running-in smooths the contacts, so the friction losses fall by a share that
            // fades with the running time: at each point that share of the loss.
            if (!f.model_loss_W.empty())
                run("exp(-k/" + num(tau, 3) + ") P_model", "exp", [tau](double kk) { return std::exp(-kk / tau); }, true);
        }
        run("(k/" + num(Nd, 4) + ")", "power", [Nd](double kk) { return kk / Nd; }, false);
        if (!f.model_loss_W.empty()) run("(k/" + num(Nd, 4) + ") P_model", "power", [Nd](double kk) { return kk / Nd; }, true);
    }
    return std::move(lib.cols);
}

}  // namespace gearloss::diagnosis::hypothesis::detail
