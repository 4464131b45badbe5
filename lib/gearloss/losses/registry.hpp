#pragma once
// The name-keyed factory of loss mechanisms. A new mechanism is its physics (in the folder
// named after it), a class implementing losses::LossMechanism (mechanisms/<name>_mechanism.cpp)
// and one line in registry.cpp (CONTRIBUTING.md, "Adding a loss mechanism").
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gearloss/losses/loss_mechanism.hpp"

namespace gearloss::losses {

struct Registration {
    std::string name;
    std::function<std::unique_ptr<LossMechanism>()> create;
};

// Every registered mechanism, in the order of the output columns.
const std::vector<Registration>& registry();
// A new mechanism by name, parameters nominal (InputError when unknown).
std::unique_ptr<LossMechanism> create(const std::string& name);
// The registered names, comma separated (for messages).
std::string registered_names();

// Factory of one mechanism type (parameters reset to nominal).
template <class T>
std::unique_ptr<LossMechanism> make_mechanism() {
    auto m = std::make_unique<T>();
    m->reset_parameters();
    return m;
}

}  // namespace gearloss::losses
