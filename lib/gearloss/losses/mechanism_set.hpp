#pragma once
// The loss mechanisms of a model, in the order of the registry (the order of the CSV
// columns). Copies are deep: a model copy carries its own parameter values and forms.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gearloss::losses {

class LossMechanism;

class MechanismSet {
public:
    MechanismSet();  // every registered mechanism, parameters nominal
    MechanismSet(const MechanismSet&);
    MechanismSet& operator=(const MechanismSet&);
    MechanismSet(MechanismSet&&) noexcept;
    MechanismSet& operator=(MechanismSet&&) noexcept;
    ~MechanismSet();

    size_t size() const { return items_.size(); }
    const LossMechanism& operator[](size_t i) const { return *items_[i]; }
    LossMechanism& operator[](size_t i) { return *items_[i]; }
    // Index of a mechanism by name, or size() when absent.
    size_t index(std::string_view name) const;
    const LossMechanism* find(std::string_view name) const;
    LossMechanism* find(std::string_view name);
    // InputError naming the registered mechanisms when absent.
    const LossMechanism& at(std::string_view name) const;
    LossMechanism& at(std::string_view name);
    // Identity of this set (each construction or copy has its own): per-point storage made
    // by one set's mechanisms is recognised without comparing types.
    unsigned long long id() const { return id_; }

private:
    std::vector<std::unique_ptr<LossMechanism>> items_;
    unsigned long long id_;
};

}  // namespace gearloss::losses
