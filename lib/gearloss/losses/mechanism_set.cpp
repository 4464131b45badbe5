#include "gearloss/core/errors.hpp"
#include "gearloss/losses/mechanism_set.hpp"

#include <atomic>
#include <stdexcept>

#include "gearloss/losses/registry.hpp"

namespace gearloss::losses {

namespace {
unsigned long long next_id() {
    static std::atomic<unsigned long long> counter{0};
    return ++counter;
}
}  // namespace

MechanismSet::MechanismSet() : id_(next_id()) {
    for (const auto& r : registry()) items_.push_back(r.create());
}
MechanismSet::MechanismSet(const MechanismSet& o) : id_(next_id()) {
    items_.reserve(o.items_.size());
    for (const auto& m : o.items_) items_.push_back(m->clone());
}
MechanismSet& MechanismSet::operator=(const MechanismSet& o) {
    if (this != &o) {
        MechanismSet copy(o);
        items_ = std::move(copy.items_);
        id_ = copy.id_;
    }
    return *this;
}
MechanismSet::MechanismSet(MechanismSet&&) noexcept = default;
MechanismSet& MechanismSet::operator=(MechanismSet&&) noexcept = default;
MechanismSet::~MechanismSet() = default;

size_t MechanismSet::index(std::string_view name) const {
    for (size_t i = 0; i < items_.size(); ++i)
        if (items_[i]->name() == name) return i;
    return items_.size();
}
const LossMechanism* MechanismSet::find(std::string_view name) const {
    const size_t i = index(name);
    return i < items_.size() ? items_[i].get() : nullptr;
}
LossMechanism* MechanismSet::find(std::string_view name) {
    const size_t i = index(name);
    return i < items_.size() ? items_[i].get() : nullptr;
}
const LossMechanism& MechanismSet::at(std::string_view name) const {
    if (const auto* m = find(name)) return *m;
    throw InputError("no loss mechanism '" + std::string(name) + "' (registered: " + registered_names() + ")");
}
LossMechanism& MechanismSet::at(std::string_view name) {
    if (auto* m = find(name)) return *m;
    throw InputError("no loss mechanism '" + std::string(name) + "' (registered: " + registered_names() + ")");
}

}  // namespace gearloss::losses
