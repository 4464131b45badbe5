#pragma once
// diagnose: the selection of effects (diagnose_select.cpp).
#include <string>
#include <vector>

#include "gearloss/diagnosis/diagnose_internal.hpp"

namespace gearloss::diagnosis::detail {

struct Selection {
    Hypothesis h;                        // the case with every accepted effect, jointly refitted
    std::vector<Finding> findings;       // in the order they were added
    std::vector<Candidate> candidates;   // the first round's screening, best first
    std::vector<std::string> warnings;
    std::string unsettled;               // effects that fit well but were not named, and why
    double cv_rmse_after = 0;
    int fitted = 0;                      // parameters in h beyond the case
};

// The case with the accepted terms (and the flagged points of an unstabilised-test term);
// `skip`: a term left out.
Hypothesis with_terms(const Hypothesis& neutral, const std::vector<Term>& terms, const std::vector<char>& flags,
                      int skip = -1);
// A rival the recordings cannot rule out: when the leader wins fewer resamples than the
// stability rule asks, one that wins a quarter of them, however far behind on all points
// (two forms of one mechanism splitting the resamples 54/46 are one finding, not none).
bool rival_in_resamples(double leader_stability, int rival_wins, const DiagnoseOptions& opt);
// "a in 33 %, b in 21 %": what won the resamples the leader did not (wins > 0 only).
std::string resample_shares(const std::vector<std::pair<std::string, int>>& rivals, const DiagnoseOptions& opt);
// What a finding named as a pair with `partner` adds to its description (diagnose_pairs.cpp),
// and what replaces that once a later finding made the partner unnecessary.
std::string pair_clause(const std::string& partner);
// Whether e is already among the terms or excluded by one of them (another form of its axis,
// the same effect for every oil and for one); `skip`: a term being replaced.
bool taken(const std::vector<Term>& terms, const Effect& e, int skip = -1);
// The terms' parameters refitted jointly (kFailedNll when the combination cannot be
// evaluated): Gauss-Newton for two or more continuous parameters, else coordinate descent;
// the flagged points are chosen again only when `refit_flags`. Shapes move along their grids;
// a deferred one (a refinement) is held when `hold_deferred`, and where it has not moved yet it
// is first scanned over every other grid value. With `scan` (a finding's refinement scanned
// beside a candidate: the indices refinement_leads gave) only that refinement moves, over those
// indices; any other unmoved one, a candidate's own, is held (not offered before its effect is
// named), and one that has moved already steps on from where it is.
double refit_jointly(const Engine& E, const Hypothesis& neutral, std::vector<Term>& terms, std::vector<char>& flags,
                     const DiagnoseOptions& opt, bool refit_flags, int skip = -1, bool hold_deferred = false,
                     const std::vector<size_t>* scan = nullptr);
// Where an unmoved refinement of the terms fits best with them alone: the `count` grid indices
// of its every-other-value scan with the best joint likelihood (empty without one). A partner
// fitted beside the terms moves the level, rarely the place of the peak, so its scan starts
// there (diagnose_joint.cpp).
std::vector<size_t> refinement_leads(const Engine& E, const Hypothesis& neutral, const std::vector<Term>& terms,
                                     const std::vector<char>& flags, const DiagnoseOptions& opt, size_t count);
// Gauss-Newton with Levenberg-Marquardt damping over the terms' continuous parameters at once
// (forms and flagged points held), within their ranges; the likelihood reached, kFailedNll
// when the start cannot be evaluated (diagnose_joint.cpp).
double joint_gauss_newton(const Engine& E, const Hypothesis& neutral, std::vector<Term>& terms,
                          const std::vector<char>& flags, int skip = -1);
// A finding's before/after figures: without it (predictions pb) and with it (h).
void record_fit(Finding& f, const Engine& E, const Pred& pb, const Hypothesis& without, const Hypothesis& h,
                const CvResult& cv_without, const CvResult& cv_with);

// The first round's candidates, as fitted alone on top of the case (diagnose_pairs.cpp).
struct FirstRound {
    const std::vector<Fit>& fits;
    const std::vector<Response>& responses;
    const std::vector<double>& delta_bic;
    const std::vector<size_t>& order;  // best first
    const Pred& base_pred;
    double base_nll;
};

// Two effects taken together when no single one leads to them: effects that partly cancel
// (a negative sensor offset under a real drag) or that another single candidate imitates
// better than either does alone. Every pair is screened on the responses, the leading pair
// refitted with the model; it is taken when it beats the best pair forward selection can
// reach by the BIC threshold and each member is needed on top of the other (BIC, cross-
// validation, stability). On success the two findings are in S and `terms` holds them.
// `lead_partners`: the leading candidate's best partners on the screening, for the next
// round's joint fits (a partner that the lead, fitted alone, partly cancels ranks low there).
bool select_pair(const Engine& E, const std::vector<Effect>& lib, const Hypothesis& neutral, const FirstRound& r,
                 const DiagnoseOptions& opt, Selection& S, std::vector<Term>& terms, std::vector<size_t>& lead_partners);

Selection select_effects(const Engine& E, const std::vector<Effect>& candidates, const Hypothesis& neutral,
                         const DiagnoseOptions& opt);

}  // namespace gearloss::diagnosis::detail
