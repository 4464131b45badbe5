#include "gearloss/core/errors.hpp"
#include "gearloss/losses/loss_mechanism.hpp"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "gearloss/core/issue.hpp"

namespace gearloss::losses {

namespace {
size_t parameter_index(const LossMechanism& mech, std::string_view name) {
    const auto ps = mech.parameters();
    for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i].name == name) return i;
    throw InputError(fmt::format("mechanism '{}' has no parameter '{}'", mech.name(), name));
}
}  // namespace

void MechanismDetail::reset(size_t components, size_t q) {
    quantities = q;
    values.assign(components * q, 0.0);
}

void LossMechanism::reset_parameters() {
    values_.clear();
    for (const auto& p : parameters()) values_.push_back(p.nominal);
    given_.assign(values_.size(), false);
}

double LossMechanism::parameter(std::string_view name) const { return values_[parameter_index(*this, name)]; }

void LossMechanism::set_parameter(std::string_view name, double value) {
    const size_t i = parameter_index(*this, name);
    values_[i] = value;
    given_[i] = true;
}

bool LossMechanism::parameter_given(std::string_view name) const { return given_[parameter_index(*this, name)]; }

double LossMechanism::value_in(const solver::Model& m, std::string_view name) const {
    const size_t i = parameter_index(*this, name);
    if (given_[i]) return values_[i];
    return oil_value(m, name).value_or(values_[i]);
}

LossMechanism::Source LossMechanism::value_source(const solver::Model& m, std::string_view name) const {
    if (given_[parameter_index(*this, name)]) return Source::case_setting;
    return oil_value(m, name) ? Source::oil : Source::nominal;
}

const char* LossMechanism::source_name(Source s) {
    switch (s) {
        case Source::case_setting: return "case";
        case Source::oil: return "oil";
        case Source::nominal: break;
    }
    return "default";
}

bool LossMechanism::reads(const solver::Model& m, const Parameter& p) const {
    if (p.used_by.empty()) return true;
    for (const auto& a : forms(m))
        if (form(m, a.axis) == p.used_by) return true;
    return false;
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
