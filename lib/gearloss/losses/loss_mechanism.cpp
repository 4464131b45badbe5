#include "gearloss/core/errors.hpp"
#include "gearloss/losses/loss_mechanism.hpp"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "gearloss/core/issue.hpp"

namespace gearloss::losses {

void MechanismDetail::reset(size_t components, size_t q) {
    quantities = q;
    values.assign(components * q, 0.0);
}

void LossMechanism::reset_parameters() {
    values_.clear();
    for (const auto& p : parameters()) values_.push_back(p.nominal);
}

double LossMechanism::parameter(std::string_view name) const {
    const auto ps = parameters();
    for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i].name == name) return values_[i];
    throw InputError(fmt::format("mechanism '{}' has no parameter '{}'", this->name(), name));
}

void LossMechanism::set_parameter(std::string_view name, double value) {
    const auto ps = parameters();
    for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i].name == name) {
            values_[i] = value;
            return;
        }
    throw InputError(fmt::format("mechanism '{}' has no parameter '{}'", this->name(), name));
}

bool LossMechanism::parameters_nominal() const {
    const auto ps = parameters();
    for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i].calibration && values_[i] != ps[i].nominal) return false;
    return true;
}

std::string LossMechanism::form(const solver::Model& m, std::string_view axis) const {
    for (const auto& a : forms(m))
        if (a.axis == axis) return a.forms.front();
    throw InputError(fmt::format("mechanism '{}' has no form axis '{}'", name(), axis));
}

void LossMechanism::set_form(solver::Model&, std::string_view axis, std::string_view) {
    throw InputError(fmt::format("mechanism '{}' has no form axis '{}'", name(), axis));
}

void LossMechanism::validate(const solver::Model&, std::vector<solver::Issue>& out) const {
    const auto ps = parameters();
    for (size_t i = 0; i < ps.size(); ++i) {
        const double v = values_[i];
        if (std::isfinite(v) && v >= ps[i].lower && v <= ps[i].upper) continue;
        out.push_back({ps[i].calibration ? "calibration" : "mechanisms", "",
                       fmt::format("{}.{}", name(), ps[i].name),
                       fmt::format("{} ({}) is {}; it must be within [{}, {}]", ps[i].name, ps[i].description,
                                   fmt::format("{:.6g}", v), ps[i].lower, ps[i].upper)});
    }
}

std::string LossMechanism::loss_fault(const solver::Model& m, const MechanismPoint&, const MechanismDetail& d) const {
    const auto names = components(m);
    for (size_t c = 0; c < names.size(); ++c) {
        const double P = d.at(c, 0);
        if (!(std::isfinite(P) && P >= 0.0)) return fmt::format("{} {}", label(), names[c]);
    }
    return {};
}

std::string LossMechanism::report(const solver::Model& m, const PointInput&, const MechanismPoint&,
                                  const MechanismDetail& d) const {
    const auto names = components(m);
    if (names.empty()) return {};
    std::string s = fmt::format("{:<22}P [W]\n", label());
    for (size_t c = 0; c < names.size(); ++c) s += fmt::format("  {:<18} {:9.2f}\n", names[c], d.at(c, 0));
    return s;
}

}  // namespace gearloss::losses
