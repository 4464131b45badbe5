#include "gearloss/core/errors.hpp"
#include "gearloss/losses/registry.hpp"

#include <stdexcept>

namespace gearloss::losses {

// The registered mechanisms: one line each, NAME and the factory its source file in
// mechanisms/ defines (`std::unique_ptr<LossMechanism> FACTORY()` in namespace
// gearloss::losses; the same static library, gearloss_physics). The order is the order of the
// output columns.
#define GEARLOSS_LOSS_MECHANISMS(X)              \
    X("mesh", create_mesh_friction)              \
    X("churning", create_churning)               \
    X("bearings", create_bearings)               \
    X("seals", create_seals)                     \
    X("clutch_drag", create_clutch_drag)         \
    X("auxiliary", create_auxiliary)             \
    X("windage", create_gear_windage)            \
    X("empirical", create_empirical)

#define GEARLOSS_DECLARE(NAME, FACTORY) std::unique_ptr<LossMechanism> FACTORY();
GEARLOSS_LOSS_MECHANISMS(GEARLOSS_DECLARE)
#undef GEARLOSS_DECLARE

const std::vector<Registration>& registry() {
#define GEARLOSS_ENTRY(NAME, FACTORY) Registration{NAME, FACTORY},
    static const std::vector<Registration> r = {GEARLOSS_LOSS_MECHANISMS(GEARLOSS_ENTRY)};
#undef GEARLOSS_ENTRY
    return r;
}

std::string registered_names() {
    std::string s;
    for (const auto& r : registry()) s += (s.empty() ? "" : ", ") + r.name;
    return s;
}

std::unique_ptr<LossMechanism> create(const std::string& name) {
    for (const auto& r : registry())
        if (r.name == name) return r.create();
    throw InputError("no loss mechanism '" + name + "' (registered: " + registered_names() + ")");
}

}  // namespace gearloss::losses
