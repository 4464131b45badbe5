#pragma once
// Test access to the loss of one mechanism by name (the library loops over mechanisms and
// never names them; tests check particular ones).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "gearloss/losses/registry.hpp"
#include "gearloss/mechanisms/mesh_friction_mechanism.hpp"
#include "gearloss/solver/operating_point.hpp"

namespace gearloss::test {

// Index of a mechanism in a model made with the default registry.
inline size_t mech(std::string_view name) {
    const auto& r = losses::registry();
    for (size_t i = 0; i < r.size(); ++i)
        if (r[i].name == name) return i;
    throw std::logic_error("no mechanism " + std::string(name));
}
inline double part(const solver::LossBreakdown& L, std::string_view name) { return L.power.at(mech(name)); }
// Per-component value (detail evaluations): quantity 0 is the component's loss [W].
inline double each(const solver::LossBreakdown& L, std::string_view name, size_t i, size_t q = 0) {
    return L.detail.at(mech(name)).at(i, q);
}
inline size_t components(const solver::LossBreakdown& L, std::string_view name) {
    const auto& d = L.detail.at(mech(name));
    return d.values.size() / d.quantities;
}

}  // namespace gearloss::test
