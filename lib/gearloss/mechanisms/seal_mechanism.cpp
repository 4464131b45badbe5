// Radial lip seals as a loss mechanism: ISO/TR 14179-2 per seal at its shaft's speed
// (gearloss/seals/radial_lip_seal.hpp), with a calibration factor. Independent of the oil state.
#include <cmath>
#include <fmt/format.h>

#include "gearloss/losses/registry.hpp"
#include "gearloss/model/model.hpp"
#include "gearloss/seals/radial_lip_seal.hpp"

namespace gearloss::seals {
namespace {

struct SealPoint : losses::MechanismPointOf<SealPoint> {
    std::vector<double> power;  // per seal [W]
    double total = 0;
};

class Seals final : public losses::LossMechanism {
public:
    enum : size_t { kFactor };
    std::unique_ptr<LossMechanism> clone() const override { return std::make_unique<Seals>(*this); }
    std::string_view name() const override { return "seals"; }
    std::string_view label() const override { return "seals"; }
    std::string_view column() const override { return "P_seal_W"; }
    std::vector<std::string> components(const solver::Model& m) const override {
        return losses::names_of(m.gearbox.seals, [](const auto& s) { return s.name; });
    }
    std::vector<losses::DetailQuantity> quantities() const override { return {{"P_seal_{}_W", 1.0}}; }
    std::vector<losses::Parameter> parameters() const override {
        std::vector<losses::Parameter> v{{"factor", "scales every seal loss", nullptr, "1.2", 1.0, 0.0, 100.0, true, "seal_friction",
                 "radial lip seal friction differs from the standard estimate (P ~ d^2 n)"}};
        v[0].scales_loss = true;
        return v;
    }
    std::unique_ptr<losses::MechanismPoint> make_point() const override { return std::make_unique<SealPoint>(); }

    void prepare(const solver::Model& m, const losses::PointInput& in, losses::MechanismPoint& out) const override {
        auto& p = static_cast<SealPoint&>(out);
        const auto& gb = m.gearbox;
        p.power.assign(gb.seals.size(), 0.0);
        p.total = 0.0;
        if (!enabled()) return;
        for (size_t i = 0; i < gb.seals.size(); ++i) {
            p.power[i] = param(kFactor) * radial_seal_power(gb.seals[i].diameter, m.layout.seal_speed_ratio[i] * in.omega_in);
            p.total += p.power[i];
        }
    }
    std::string point_fault(const solver::Model& m, const losses::MechanismPoint& pt) const override {
        const auto& p = static_cast<const SealPoint&>(pt);
        for (size_t i = 0; i < p.power.size(); ++i)
            if (!(std::isfinite(p.power[i]) && p.power[i] >= 0.0)) return "seal " + m.gearbox.seals[i].name;
        return {};
    }
    double power(const solver::Model&, const losses::MechanismPoint& pt, losses::Evaluation&,
                 losses::MechanismDetail* d) const override {
        const auto& p = static_cast<const SealPoint&>(pt);
        if (d) {
            d->reset(p.power.size(), 1);
            d->values = p.power;
        }
        return p.total;
    }
    std::string loss_fault(const solver::Model& m, const losses::MechanismPoint&,
                           const losses::MechanismDetail& d) const override {
        for (size_t i = 0; i < m.gearbox.seals.size(); ++i)
            if (!(std::isfinite(d.at(i)) && d.at(i) >= 0)) return "seal " + m.gearbox.seals[i].name;
        return {};
    }
    std::string report(const solver::Model& m, const losses::PointInput&, const losses::MechanismPoint&,
                       const losses::MechanismDetail& d) const override {
        const auto& gb = m.gearbox;
        if (gb.seals.empty()) return {};
        std::string s = "seals                 d [mm]   P [W]\n";
        for (size_t i = 0; i < gb.seals.size(); ++i)
            s += fmt::format("  {:<18} {:7.1f} {:8.2f}\n", gb.seals[i].name, gb.seals[i].diameter * 1e3, d.at(i));
        return s;
    }
};

}  // namespace
}  // namespace gearloss::seals

namespace gearloss::losses {
std::unique_ptr<LossMechanism> create_seals() { return make_mechanism<seals::Seals>(); }
}  // namespace gearloss::losses
