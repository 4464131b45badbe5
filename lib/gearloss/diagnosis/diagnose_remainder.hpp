#pragma once
// Model the remainder: a formula (hypothesis.hpp) for what the findings leave; where they
// leave such a formula, the formula for the whole mismatch of the case as described instead
// when it alone predicts the recordings better under cross-validation (the findings then
// likely stand in for an effect outside the library: a viscosity factor of 0.2 absorbing a
// loss that switches on in hot oil).
#include <optional>

#include "gearloss/diagnosis/diagnose_internal.hpp"
#include "gearloss/diagnosis/hypothesis.hpp"

namespace gearloss::diagnosis::detail {

// neutral/p0: the case as described and its predictions; base/pf: the accepted hypothesis
// (the findings, `findings` fitted parameters) and its predictions, at every point of E; noise_relative: the loss noise
// in use (a share of the recorded loss). nullopt when no formula beats zero significantly.
std::optional<hypothesis::Proposal> model_remainder(const Engine& E, const CampaignOils& oils, const Hypothesis& neutral,
                                                    const Pred& p0, const Hypothesis& base, const Pred& pf,
                                                    int findings, double noise_relative);

}  // namespace gearloss::diagnosis::detail
