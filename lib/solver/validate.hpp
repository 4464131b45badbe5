#pragma once
// The validation of a model lives with the model (model/validate.hpp, physics layer). This
// header only keeps the old path working for io/config.cpp and diagnosis/diagnose.cpp until
// their includes name model/validate.hpp; nothing else includes it.
#include "model/validate.hpp"
