// A constant parasitic loss while the input turns (an oil pump, a sensor's drag): the
// calibration's term for what the case does not describe. Independent of the oil state.
#include <cmath>

#include "gearloss/losses/registry.hpp"
#include "gearloss/units/units.hpp"

namespace gearloss::losses {
namespace {

struct AuxiliaryPoint : MechanismPointOf<AuxiliaryPoint> {
    bool turning = false;
};

class Auxiliary final : public LossMechanism {
public:
    enum : size_t { kPower };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<Auxiliary>(*this); }
    std::string_view name() const override { return "auxiliary"; }
    std::string_view label() const override { return "auxiliary"; }
    std::string_view column() const override { return "P_aux_W"; }
    std::vector<Parameter> parameters() const override {
        return {{"power", "constant parasitic loss while the input turns", &units::dim::power, "20 W", 0.0, 0.0, 1e9, true, "constant_parasitic",
                 "a constant parasitic loss (oil pump, drag of an auxiliary part), heating the oil"}};
    }
    std::unique_ptr<MechanismPoint> make_point() const override { return std::make_unique<AuxiliaryPoint>(); }
    void prepare(const solver::Model&, const PointInput& in, MechanismPoint& out) const override {
        static_cast<AuxiliaryPoint&>(out).turning = enabled() && in.omega_in != 0.0;
    }
    double power(const solver::Model&, const MechanismPoint& pt, Evaluation&, MechanismDetail* d) const override {
        if (d) d->reset(0, 1);
        return static_cast<const AuxiliaryPoint&>(pt).turning ? param(kPower) : 0.0;
    }
};

}  // namespace

std::unique_ptr<LossMechanism> create_auxiliary() { return make_mechanism<Auxiliary>(); }

}  // namespace gearloss::losses
