#!/usr/bin/env bash
# Mutation check: can the tests fail? Applies, one at a time, small careless-edit
# mutations (a few per cent on a published constant, a definitional slip such as a
# mean turned into a sum, an exponent off by 0.01-0.05, a normal radius taken as the
# transverse one) to the physics in lib/, rebuilds incrementally, runs the ctest
# suite of the normal (non-sanitizer) build and records which test kills each mutant.
#
#   scripts/mutation-check.sh                       every mutation; score with and without the regression net
#   scripts/mutation-check.sh --exclude-regression  correctness tests alone (no ctest entry named regression_*
#                                                   or labelled 'regression'); the score line is theirs
#   scripts/mutation-check.sh --only ID[,ID...]     some mutations (repeatable)
#   scripts/mutation-check.sh --list                the mutation table, nothing built
#   scripts/mutation-check.sh --all-killers         no --stop-on-failure: name every test that kills each
#                                                   mutant (count and first names), the regression net
#                                                   separately (slower: the whole suite per mutant)
#   scripts/mutation-check.sh --allow-baseline-failures
#                                                   tests that already fail unmutated are left out (named)
#                                                   instead of stopping the run
#
# Where: the working tree is copied (tracked and untracked-not-ignored files) into
# build-mutation/src, updated file by file on every run (unchanged files keep their
# times, so the build there stays incremental; ccache makes a repeated mutant or a
# restore a cache hit), and built in build-mutation/build. The mutations are applied
# to that copy, never to the working tree, so other people's edits and builds in the
# tree are not disturbed and cannot be overwritten by a restore.
#
# Each mutation is a literal (file, exact original text, replacement). The original
# must occur exactly once in the file, else the mutation is reported STALE (the code
# moved: update the table) and the script exits non-zero. The mutated file is saved
# first and always restored (trap on EXIT, INT and TERM), the restore checked with cmp;
# the restored copy gets a new mtime on purpose so that make recompiles it.
#
# Per mutant: build (a build error counts as killed, flagged "build error"); then the
# correctness tests, fast ones first (baseline cost < 5 s), then the slow ones, each
# pass with --stop-on-failure; a mutant that survives them is run against the
# regression net (unless --exclude-regression). Output: one line per mutation (id,
# folder, description, killed-by test or SURVIVED, seconds) and
#   mutation score: K/N killed
# (plus the score of the correctness tests alone in a full run). Exit status: 0 when
# every mutation is killed, 1 when one survives, 2 for a setup error, 3 for a STALE
# mutation. Measured on 2 shared cores (30 mutations): 2 min 40 s with an up-to-date
# build-mutation/ (about 4 s per mutant: one object recompiled, three links, the suite
# stopped at its first failure), plus about 4 min for the first build of a fresh copy;
# --all-killers 10 min 30 s.
set -euo pipefail
exec 3>&2   # the script's stderr, for messages from traps (which may run inside a redirection)
cd "$(dirname "$0")/.."
ROOT=$PWD
WORK=${MUTATION_DIR:-$ROOT/build-mutation}
SRC=$WORK/src
BLD=$WORK/build
LOGS=$WORK/logs
SAVED=$WORK/saved
JOBS=${JOBS:-$(nproc)}
TEST_TIMEOUT=${TEST_TIMEOUT:-600}   # s per ctest entry (a mutant that hangs is killed by it)

# ---------------------------------------------------------------------------------
# The mutations: id | folder | file | description | original | replacement.
IDS=() FOLDERS=() FILES=() DESCS=() ORIGS=() REPLS=()
mut() { IDS+=("$1"); FOLDERS+=("$2"); FILES+=("$3"); DESCS+=("$4"); ORIGS+=("$5"); REPLS+=("$6"); }

mut U1 units lib/gearloss/units/units.cpp "rpm as pi/60 rad/s per rpm (rev/rad slip, factor 1/2)" \
    '{"rpm", {2.0 * pi / 60.0, angular_speed, 1, false, false, true}}' '{"rpm", {pi / 60.0, angular_speed, 1, false, false, true}}'
mut L1 lubricant lib/gearloss/lubricant/oil.cpp "density reference at 20 degC instead of 15 degC" \
    'rho15 * (1.0 - expansion * (T_K - 288.15))' 'rho15 * (1.0 - expansion * (T_K - 293.15))'
mut L2 lubricant lib/gearloss/lubricant/oil.cpp "Cragoe conductivity 0.1172 -> 0.1127 (digits swapped, -3.8 %)" \
    '(0.1172 / SG15)' '(0.1127 / SG15)'
mut G1 geometry lib/gearloss/geometry/gear_geometry.cpp "rho_redC: transverse instead of normal radius (no 1/cos beta_b)" \
    'us / ((1.0 + us) * (1.0 + us) * cos(p.beta_b))' 'us / ((1.0 + us) * (1.0 + us))'
mut G2 geometry lib/gearloss/geometry/gear_geometry.cpp "beta_b with the transverse instead of the normal pressure angle" \
    'p.beta_b = std::asin(sin(beta) * cos(an))' 'p.beta_b = std::asin(sin(beta) * cos(p.alpha_t))'
mut M1 mesh lib/gearloss/mesh/friction.cpp "Schlenk constant 0.048 -> 0.050 (+4 %)" \
    'return 0.048 * std::pow' 'return 0.050 * std::pow'
mut M2 mesh lib/gearloss/mesh/friction.cpp "ISO/TS 6336-20 constant 0.060 -> 0.063 (+5 %)" \
    'return 0.060 * std::pow' 'return 0.063 * std::pow'
mut M3 mesh lib/gearloss/mesh/friction.cpp "Ertel-Grubin constant 1.95 -> 1.99 (+2 %)" \
    '1.95 * std::pow(G * U' '1.99 * std::pow(G * U'
mut M4 mesh lib/gearloss/mesh/friction.cpp "Dowson-Higginson constant 2.65 -> 2.76 (+4 %)" \
    '2.65 * std::pow(U, 0.70)' '2.76 * std::pow(U, 0.70)'
mut M5 mesh lib/gearloss/mesh/friction.cpp "Gupta thermal reduction 0.213 -> 0.231 (digits swapped)" \
    'const double b = 0.213 * (1.0 + 2.23 *' 'const double b = 0.231 * (1.0 + 2.23 *'
mut M6 mesh lib/gearloss/mesh/loss_factor.cpp "Ohlendorf bracket eps2^2 -> eps2 eps1" \
    '1.0 - g.eps_alpha + g.eps1 * g.eps1 + g.eps2 * g.eps2' '1.0 - g.eps_alpha + g.eps1 * g.eps1 + g.eps2 * g.eps1'
mut M7 mesh lib/gearloss/mesh/loss_factor.cpp "Wimmer sweep normalised by the working instead of the base radius" \
    'g.sign, g.u, g.db[0], phases}' 'g.sign, g.u, g.dw[0], phases}'
mut M8 mesh lib/gearloss/mesh/ehl_contact.cpp "Jaeger mean flash constant 1.064 -> 1.11 (Blok's maximum constant)" \
    'if (std::abs(in.u1) > 0) dT1 = 1.064 * q1' 'if (std::abs(in.u1) > 0) dT1 = 1.11 * q1'
mut M9 mesh lib/gearloss/mesh/ehl_contact.cpp "3-pressure Hertz shortcut: outer Gauss weight not doubled" \
    '2 * Gauss5::weights()[2]' 'Gauss5::weights()[2]'
mut M10 mesh lib/gearloss/mesh/friction.cpp "boundary share (1 - Lambda/L_on)^2 -> (1 - Lambda/(1.1 L_on))^2 (mixed film ends 10 % later)" \
    'const double s = 1.0 - std::max(lambda, 0.0) / onset;' 'const double s = 1.0 - std::max(lambda, 0.0) / (1.1 * onset);'
mut M11 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "the oil's mixed-film mu_ehl ignored (the mechanism's value used)" \
    'return given(kMuEhl) || !m.oil.gear_mu_ehl ? param(kMuEhl) : *m.oil.gear_mu_ehl;' 'return param(kMuEhl);'
mut S6 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "mixed friction rise read at a 10 % larger Lambda" \
    'mixed = 1.0 + mixed_rise * boundary_share_doleschel(lambda, mixed_onset);' 'mixed = 1.0 + mixed_rise * boundary_share_doleschel(1.1 * lambda, mixed_onset);'
mut S1 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "mean roughness (Ra1+Ra2)/2 -> sum Ra1+Ra2 (issue 12)" \
    'const double Ra_um = 0.5 * (g0.Ra + g1.Ra) * 1e6;' 'const double Ra_um = (g0.Ra + g1.Ra) * 1e6;'
mut S2 churning lib/gearloss/mechanisms/churning_mechanism.cpp "nu^0.21 of the churning fast path -> nu^0.20" \
    'std::exp(0.21 * std::log(e.oil.nu))' 'std::exp(0.20 * std::log(e.oil.nu))'
mut S3 bearings lib/gearloss/mechanisms/bearing_mechanism.cpp "nu^0.64 of the bearing fast path -> nu^0.6" \
    'nu064 = std::exp(0.64 * lnnu)' 'nu064 = std::exp(0.6 * lnnu)'
mut S4 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "mu ~ eta^-0.05 of the mesh fast path -> eta^-0.04" \
    'std::exp(-0.05 * std::log(s.eta * 1e3))' 'std::exp(-0.04 * std::log(s.eta * 1e3))'
mut S5 clutch lib/gearloss/mechanisms/clutch_drag_mechanism.cpp "clutch drag heats the oil instead of the clutch-pack node" \
    'bool heats_oil() const override { return false; }' 'bool heats_oil() const override { return true; }'
mut C1 churning lib/gearloss/churning/changenet_velex.cpp "Changenet-Velex 1.366 -> 1.40 (+2.5 %)" \
    'pre * 1.366 *' 'pre * 1.40 *'
mut C2 churning lib/gearloss/churning/changenet_velex.cpp "high-Re exponent of V0/D^3 -0.35 -> -0.33" \
    'std::pow(VD, -0.35)' 'std::pow(VD, -0.33)'
mut B1 bearings lib/gearloss/bearings/skf_model.cpp "SKF inlet shear constant 1.84e-9 -> 1.93e-9 (+5 %)" \
    'p.a_ish = 1.84e-9' 'p.a_ish = 1.93e-9'
mut B2 bearings lib/gearloss/bearings/skf_model.cpp "SKF roller drag factor 4 -> 0.4 (the ball factor)" \
    'first = 4.0 * b.bath_VM * K_roll' 'first = 0.4 * b.bath_VM * K_roll'
mut B3 bearings lib/gearloss/case/config_bearings.cpp "a one-side suffix seal (RS1) given the moment of both sides" \
    's.seal_KS1 *= seal_sides / 2;' 's.seal_KS1 *= 1.0;'
mut E1 seals lib/gearloss/seals/radial_lip_seal.hpp "ISO/TR 14179-2 seal constant 7.69e-6 -> 7.96e-6 (digits swapped)" \
    'return 7.69e-6 * d_mm' 'return 7.96e-6 * d_mm'
mut T1 thermal lib/gearloss/thermal/heat_rejection.cpp "free convection 0.59 -> 0.62 (+5 %)" \
    '0.59 * std::pow(Ra, 0.25)' '0.62 * std::pow(Ra, 0.25)'
mut T2 thermal lib/gearloss/thermal/heat_rejection.cpp "forced convection (flat plate) 0.664 -> 0.697 (+5 %)" \
    '0.664 * std::sqrt(Re)' '0.697 * std::sqrt(Re)'
mut T3 thermal lib/gearloss/thermal/heat_rejection.cpp "Stefan-Boltzmann constant 5.670e-8 -> 5.760e-8" \
    'constexpr double sigma_SB = 5.670374419e-8;' 'constexpr double sigma_SB = 5.760374419e-8;'
mut T4 thermal lib/gearloss/thermal/network.cpp "stored heat forgets the clutch node" \
    'if (n.has_clutch()) E += n.C_clutch * (T[2] - T_ref);' ''
mut X1 gearbox lib/gearloss/gearbox/gearbox.cpp "axial force tan(beta_b) without 1/cos(alpha_wt)" \
    'const double ax = std::tan(md.geom.beta_b) / std::cos(md.geom.alpha_wt);' 'const double ax = std::tan(md.geom.beta_b);'
mut K1 clutch lib/gearloss/clutch/wet_clutch.cpp "Patir-Cheng exponent 2.31 -> 2.13 (digits swapped)" \
    '11.1 * std::pow(H, 2.31)' '11.1 * std::pow(H, 2.13)'
mut Q1 torque_converter lib/gearloss/torque_converter/torque_converter.cpp "HI 9.6.7 C_eta constant 0.0547 -> 0.0574" \
    'std::exp(-0.0547 * std::exp' 'std::exp(-0.0574 * std::exp'
mut D1 diagnosis lib/gearloss/diagnosis/effects.cpp "forced convection may take cooling away on any heat path" \
    'if (!cooling_may_fall) lo = std::max(lo, std::min(0.0, e.neutral));' 'if (false) lo = std::max(lo, std::min(0.0, e.neutral));'
mut D2 diagnosis lib/gearloss/diagnosis/diagnose.cpp "the whole-mismatch formula never downgrades findings that stand in for it" \
    'if (d.remainder->on_case && enough_points' 'if (false && d.remainder->on_case && enough_points'
mut D4 diagnosis lib/gearloss/diagnosis/hypothesis_basis.cpp "a running-in term not in proportion to the model's loss" \
    'fn(k[i]) * (of_the_loss ? f.model_loss_W[i] : 1.0)' 'fn(k[i]) * (of_the_loss ? 1.0 : 1.0)'
mut D5 diagnosis lib/gearloss/diagnosis/diagnose.cpp "several findings stand against a simpler formula predicting as well" \
    '         simpler_and_as_good)) {' '         false)) {'
mut D6 diagnosis lib/gearloss/diagnosis/hypothesis.cpp "the exponent interval at one unit of chi-square (68 %) instead of 3.84" \
    'if (sse <= least + kChiSquare95 * sigma2)' 'if (sse <= least + sigma2)'
mut D7 diagnosis lib/gearloss/diagnosis/hypothesis_basis.cpp "powers of speed searched up to 4 only" \
    'v.id == EmpiricalVariable::speed ? 5.0' 'v.id == EmpiricalVariable::speed ? 4.0'
mut D8 diagnosis lib/gearloss/diagnosis/diagnose.cpp "a pair not named for its resamples is not said" \
    'd.unsettled = std::move(S.unsettled);' 'd.unsettled.clear();'
mut D9 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "a rival winning a quarter of the resamples is no alternative" \
    'return leader_stability < opt.stability_min && rival_wins >= 0.25 * opt.bootstrap;' 'return false;'
mut M13 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "mixed-film rise at Doleschel's onset whatever mixed_friction_onset" \
    'mixed_rise * boundary_share_doleschel(lambda, mixed_onset)' 'mixed_rise * boundary_share_doleschel(lambda)'
mut T9 thermal lib/gearloss/model/model.cpp "forced cooling linear in speed whatever cooling_speed_exponent" \
    '(q == 1.0 ? n_k : std::pow(n_k, q))' 'n_k'
mut D10 diagnosis lib/gearloss/diagnosis/diagnose_fit.cpp "a profiled shape keeps the case's value" \
    'if (f.failed.empty() && penalised < best - 1e-9) best = penalised, chosen = k;' 'if (f.failed.empty() && penalised < best - 1e-9) best = penalised;'
mut D11 diagnosis lib/gearloss/diagnosis/diagnose_joint.cpp "a joint refit holds the shape chosen alone" \
    'if (!movable(terms[j])) continue;' 'continue;'
mut D12 diagnosis lib/gearloss/diagnosis/effects.hpp "a profiled shape costs nothing in the BIC" \
    'return chosen == own ? 2.0 * std::log(2.0) : 2.0 * std::log(2.0 * others);' 'return 0.0;'
mut D14 diagnosis lib/gearloss/diagnosis/effects.hpp "keeping the case's shape costs as much as moving it" \
    'return chosen == own ? 2.0 * std::log(2.0)' 'return false ? 2.0 * std::log(2.0)'
mut D15 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "a candidate judged on top of the others with the shape it had alone" \
    'Fit fk = E.fit(*joint.back().effect, others, &rk);' 'Fit fk = E.fit(lib[k], others, &rk);'
mut M14 bearings lib/gearloss/mechanisms/bearing_mechanism.cpp "the added bearing drag at Palmgren's 2/3 whatever drag_exponent" \
    'palmgren_drag_coef(gb.bearings[i].spec, f0, w, param(kDragExponent))' 'palmgren_drag_coef(gb.bearings[i].spec, f0, w)'
mut D16 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "of candidates tied in BIC, the leader by a fraction of a unit named whatever the resamples" \
    'if (static_cast<int>(k) != chosen && wins[k] >= opt.stability_min * opt.bootstrap &&' 'if (false && wins[k] >= opt.stability_min * opt.bootstrap &&'
mut M15 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "the friction factor's fade around its film limit 0.15 -> 0.2 of the limit wide" \
    '(lambda - film_limit) / (0.15 * film_limit)' '(lambda - film_limit) / (0.2 * film_limit)'
mut M16 mesh lib/gearloss/mechanisms/mesh_friction_mechanism.cpp "friction_factor acts at every film whatever friction_factor_film_limit" \
    'const bool limited = film_limit < kFilmLimitNone && set_factor != 1.0;' 'const bool limited = false;'
mut D17 diagnosis lib/gearloss/diagnosis/diagnose_joint.cpp "a refinement that has not moved is only stepped from its case value, not scanned" \
    'if (terms[j].effect->shape->deferred && terms[j].effect->shape->at_own()) {' 'if (false) {'
mut D18 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "a finding's refinement is not tried beside the laws outside the four leaders" \
    'for (size_t r = 0, added = 0; refinable && r < order.size() && added < 6; ++r) {' 'for (size_t r = 0, added = 0; false && r < order.size() && added < 6; ++r) {'
mut D19 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "a refinement moved beside a candidate is not paid for by it" \
    'fk.extra_penalty += joint[j].effect->shape_penalty() - terms[j].effect->shape_penalty();' 'fk.extra_penalty += 0.0;'
mut D20 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "a finding dropped as no longer needed stays named in its pair partner's description" \
    '                    forget_partner(S.findings, id, e.id);' '                    (void)id;'
mut D13 diagnosis lib/gearloss/diagnosis/diagnose_verdict.cpp "two forms of one mechanism sharing the resamples leave it tentative" \
    'const bool stable = main.stability >= opt.stability_min || form_open;' 'const bool stable = main.stability >= opt.stability_min;'
mut G9 gearbox lib/gearloss/gearbox/gearbox.cpp "a pilot bearing's reaction not carried to its outer shaft" \
    'pilot.F = Vec3(-out.R[i].x(), -out.R[i].y(), -out.Z[i]);' 'pilot.F = Vec3::Zero();'
mut D3 diagnosis lib/gearloss/diagnosis/adequacy.cpp "power from the critical value alone (median ignored)" \
    'return std::sqrt(std::max(0.0, critical / median - 1));' 'return std::sqrt(std::max(0.0, critical - 1));'
mut V1 vehicle lib/gearloss/vehicle/vehicle.cpp "rotating-mass factor subtracted instead of added" \
    'mass * (1.0 + rotating_mass_factor) * a' 'mass * (1.0 - rotating_mass_factor) * a'
# Issue 36: the physics over the whole envelope.
mut C3 churning lib/gearloss/churning/changenet_velex.cpp "churning held 2 % above the transition minimum (capped regime)" \
    'c.coef_cap = blend(lo);' 'c.coef_cap = 1.02 * blend(lo);'
mut C4 churning lib/gearloss/churning/heingartner_mba.cpp "Heingartner & Mba constant 7.37 -> 7.73 (digits swapped)" \
    'return 7.37 *' 'return 7.73 *'
mut W1 gearbox lib/gearloss/gearbox/weights.cpp "gear weighed as a disc of its tip diameter (teeth taken solid)" \
    'const double d_eq2 = 0.5 * (da * da + df * df);' 'const double d_eq2 = da * da;'
mut G3 geometry lib/gearloss/geometry/gear_geometry.cpp "inv alpha_wt from the shifts without the factor 2 (ISO 21771)" \
    'involute(at) + 2.0 * tan(an) * (g1.x + g2.x) / z_sum' 'involute(at) + tan(an) * (g1.x + g2.x) / z_sum'
mut K2 clutch lib/gearloss/clutch/wet_clutch.cpp "heated clutch film: sinh^2 x = Na/4 instead of Na/8 (Nahme)" \
    'std::sqrt(nahme / 8.0)' 'std::sqrt(nahme / 4.0)'
mut M12 mesh lib/gearloss/mesh/viscoelastic.cpp "Maxwell relaxation per slice halved (G dx/u_e -> G dx/(2 u_e))" \
    'rate = G * dx / u_e *' 'rate = 0.5 * G * dx / u_e *'
mut M17 mesh lib/gearloss/mesh/ehl_contact.cpp "local EHL film temperatures read from the datasheet oil (the viscosity calibration ignored)" \
    'const lubricant::OilState sT = oil.state(T, in.viscosity_factor);' 'const lubricant::OilState sT = oil.state(T);'
mut D21 diagnosis lib/gearloss/diagnosis/effects.cpp "a mechanism's scale factor below nominal costs nothing (no prior)" \
    'if (!scales_loss || !(value < nominal) || !(nominal > 0)) return 0.0;' 'if (true) return 0.0;'
mut D22 diagnosis lib/gearloss/diagnosis/diagnose_pairs.cpp "the pair search ranks on its additive surrogate alone (only its leader refitted with the model)" \
    'constexpr size_t kPairsRefitted = 8;' 'constexpr size_t kPairsRefitted = 1;'
mut D25 diagnosis lib/gearloss/diagnosis/diagnose_pairs.cpp "the pairs screened at the surrogate's knots only (no pair refined between its knots before the ranking)" \
    'r.responses[b], r.base_pred, neutral).minimise(all);' 'r.responses[b], r.base_pred, neutral).grid(all);'
mut D26 diagnosis lib/gearloss/diagnosis/diagnose_pairs.cpp "six leading pairs refitted with the model instead of eight" \
    'constexpr size_t kPairsRefitted = 8;' 'constexpr size_t kPairsRefitted = 6;'
mut T10 thermal lib/gearloss/model/model.cpp "the heat flow linear in the rise whatever heat_rejection_rise_slope" \
    'const double rise = s == 0.0 ? 1.0 : 1.0 + s * (std::clamp(T_surface - T_amb, 0.0, 150.0) - 50.0) / 50.0;' 'const double rise = 1.0;'
mut T11 thermal lib/gearloss/model/model.cpp "the heat flow's rise slope taken about a 0 K rise instead of 50 K" \
    '1.0 + s * (std::clamp(T_surface - T_amb, 0.0, 150.0) - 50.0) / 50.0;' '1.0 + s * std::clamp(T_surface - T_amb, 0.0, 150.0) / 50.0;'
mut D28 diagnosis lib/gearloss/diagnosis/diagnose_select.cpp "beside a finding whose refinement has moved, a candidate's own refinement scanned over its whole grid" \
    'opt, false, -1, !refinable, refinable ? &leads : nullptr)' 'opt, false, -1, !refinable, leads.empty() ? nullptr : &leads)'
mut D27 diagnosis lib/gearloss/diagnosis/effects.cpp "the heat path's rise slope never moved (only the case's value on its grid)" \
    '"heat_rejection_rise_slope", {-0.15, 0.0, 0.15}' '"heat_rejection_rise_slope", {0.0}'
mut D23 diagnosis lib/gearloss/diagnosis/hypothesis.cpp "the remainder formula's leading term taken as the best of the folds (no smooth form within one standard error)" \
    'if (p == 0) best_c = smooth_within_one_se(cv, best_c, smooth_c);' 'if (false) best_c = smooth_within_one_se(cv, best_c, smooth_c);'
mut D24 diagnosis lib/gearloss/diagnosis/adequacy_structure.cpp "a mismatch claimed by Holm or Fisher each at the whole level (the claim at up to twice it)" \
    'ClaimLevels claim_levels(double level) { return {0.5 * level, 0.5 * level}; }' 'ClaimLevels claim_levels(double level) { return {level, level}; }'
mut K3 clutch lib/gearloss/clutch/wet_clutch.cpp "streak oil fraction squared (f -> f^2 beyond the wetted radius)" \
    'const double streaks = rw < c.r_outer ? f * oil_moment(rw, c.r_outer) : 0.0;' 'const double streaks = rw < c.r_outer ? f * f * oil_moment(rw, c.r_outer) : 0.0;'
mut K4 clutch lib/gearloss/clutch/wet_clutch.cpp "air between the streaks sheared over the whole gap (1 - f dropped)" \
    'const double air = (1.0 - f) * std::numbers::pi' 'const double air = std::numbers::pi'
mut R1 empirical lib/gearloss/mechanisms/empirical_mechanism.cpp "empirical step on the wrong side of its threshold" \
    'case EmpiricalShape::step: return (below ? x <= threshold : x > threshold) ? 1.0 : 0.0;' 'case EmpiricalShape::step: return (below ? x > threshold : x <= threshold) ? 1.0 : 0.0;'
mut R2 empirical lib/gearloss/mechanisms/empirical_mechanism.cpp "empirical power law exponent off by 0.2" \
    'return std::pow(std::max(0.0, x / reference), exponent);' 'return std::pow(std::max(0.0, x / reference), exponent + 0.2);'
# Issues 40 and 41: the cooler heat path and the REXS bearing scaled to a bore the catalogue lacks.
mut T5 thermal lib/gearloss/thermal/cooler.cpp "epsilon-NTU: effectiveness 1 - exp(-NTU/2) instead of 1 - exp(-NTU)" \
    'return -std::expm1(-ua / C_oil) * C_oil;' 'return -std::expm1(-0.5 * ua / C_oil) * C_oil;'
mut T6 thermal lib/gearloss/thermal/cooler.cpp "bypass valve share ignored (always fully open)" \
    'const double share = valve_share(T_oil);' 'const double share = 1.0;'
mut T7 thermal lib/gearloss/thermal/cooler.cpp "counterflow: C_r dropped from the effectiveness's denominator" \
    '(one_minus_C_r - C_r * em1)' '(one_minus_C_r - em1)'
mut T8 thermal lib/gearloss/thermal/heat_rejection.cpp "housing resistance path: 1 % more heat at every temperature" \
    'return (T - Ta) / r->resistance(omega);' 'return 1.01 * (T - Ta) / r->resistance(omega);'
mut B9 rexs lib/gearloss/rexs/bearing_mapper.cpp "scaled catalogue row: C0 with the scale instead of its square" \
    'if (row.C0) row.C0 = *best->C0 * k * k;' 'if (row.C0) row.C0 = *best->C0 * k;'
mut C5 churning lib/gearloss/churning/mauz_1987.cpp "Mauz C_2 denominator 80 -> 60" \
    'const double C2 = e / (80.0 * e0) + 0.2;' 'const double C2 = e / (60.0 * e0) + 0.2;'

# ---------------------------------------------------------------------------------
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
ONLY=() EXCLUDE_REG=0 LIST=0 ALLOW_BASELINE=0 ALL_KILLERS=0
while [ $# -gt 0 ]; do
    case "$1" in
        --list) LIST=1 ;;
        --only) shift; [ $# -gt 0 ] || { echo "--only needs an id" >&2; exit 2; }; IFS=, read -ra o <<< "$1"; ONLY+=("${o[@]}") ;;
        --only=*) IFS=, read -ra o <<< "${1#--only=}"; ONLY+=("${o[@]}") ;;
        --exclude-regression) EXCLUDE_REG=1 ;;
        --allow-baseline-failures) ALLOW_BASELINE=1 ;;
        --all-killers) ALL_KILLERS=1 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done

if [ $LIST = 1 ]; then
    for i in "${!IDS[@]}"; do
        printf '%-3s %-16s %-40s %s\n' "${IDS[$i]}" "${FOLDERS[$i]}" "${FILES[$i]}" "${DESCS[$i]}"
        printf '      - %s\n      + %s\n' "${ORIGS[$i]}" "${REPLS[$i]}"
    done
    exit 0
fi

SELECTED=()
for i in "${!IDS[@]}"; do
    if [ ${#ONLY[@]} -eq 0 ]; then SELECTED+=("$i"); continue; fi
    for o in "${ONLY[@]}"; do [ "$o" = "${IDS[$i]}" ] && SELECTED+=("$i"); done
done
for o in "${ONLY[@]}"; do
    found=0; for id in "${IDS[@]}"; do [ "$o" = "$id" ] && found=1; done
    [ $found = 1 ] || { echo "unknown mutation id '$o' (see --list)" >&2; exit 2; }
done

command -v python3 > /dev/null || { echo "mutation-check needs python3" >&2; exit 2; }
mkdir -p "$SRC" "$BLD" "$LOGS" "$SAVED"
T_START=$(date +%s)

# --- restore machinery ------------------------------------------------------------
CUR_FILE=""   # path (in SRC) of the file currently mutated, "" when none
restore() {
    [ -n "$CUR_FILE" ] || return 0
    local f=$CUR_FILE saved=$SAVED/current
    cp "$saved" "$f"   # new mtime on purpose: make must rebuild the restored file
    if ! cmp -s "$saved" "$f"; then
        echo "FATAL: restoring $f failed (differs from the saved copy $saved)" >&3
        exit 2
    fi
    CUR_FILE=""
}
# Long commands (build, ctest) run in the background in their own process group and are
# waited for: a trapped signal interrupts `wait` at once (a foreground ctest would catch
# SIGINT itself, report the interrupted tests as failures and bash would carry on), the
# trap stops the command's process group and restores the file.
CHILD=""
run_bg() {
    setsid "$@" < /dev/null &
    CHILD=$!
    local rc=0
    wait "$CHILD" || rc=$?
    CHILD=""
    return $rc
}
stop_child() {
    [ -n "$CHILD" ] || return 0
    kill -TERM -- "-$CHILD" 2> /dev/null || kill -TERM "$CHILD" 2> /dev/null || true
    wait "$CHILD" 2> /dev/null || true
    CHILD=""
}
on_exit() { local rc=$?; stop_child; restore; exit $rc; }
trap on_exit EXIT
trap 'echo "interrupted: restoring the mutated file" >&3; stop_child; restore; exit 130' INT
trap 'echo "terminated: restoring the mutated file" >&3; stop_child; restore; exit 143' TERM

# --- snapshot of the working tree -------------------------------------------------
echo "== snapshot of $ROOT -> $SRC"
python3 - "$ROOT" "$SRC" <<'PY'
import filecmp, os, shutil, subprocess, sys
root, dst = sys.argv[1], sys.argv[2]
out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                     check=True, capture_output=True).stdout.decode()
files = {f for f in out.split("\0") if f and os.path.isfile(os.path.join(root, f))}
copied = 0
for f in sorted(files):
    s, d = os.path.join(root, f), os.path.join(dst, f)
    if os.path.isfile(d) and filecmp.cmp(s, d, shallow=False):
        continue  # unchanged: keep its time (incremental build)
    os.makedirs(os.path.dirname(d), exist_ok=True)
    shutil.copy2(s, d)
    os.utime(d)  # newer than any object built from an older version
    copied += 1
removed = 0
for dirpath, dirnames, filenames in os.walk(dst):
    for n in filenames:
        rel = os.path.relpath(os.path.join(dirpath, n), dst)
        if rel not in files:
            os.remove(os.path.join(dirpath, n))
            removed += 1
print(f"   {len(files)} files, {copied} updated, {removed} removed")
PY

# --- build ------------------------------------------------------------------------
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
build() { run_bg cmake --build "$BLD" -j "$JOBS" > "$1" 2>&1; }
echo "== configure and build (Release) in $BLD"
run_bg cmake -S "$SRC" -B "$BLD" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > "$LOGS/configure.log" 2>&1 ||
    { echo "configure failed: $LOGS/configure.log" >&2; exit 2; }
if ! build "$LOGS/baseline.build.log"; then
    echo "the unmutated snapshot does not build: $LOGS/baseline.build.log" >&2
    grep -m5 -E 'error|Error' "$LOGS/baseline.build.log" >&2 || true
    exit 2
fi

# --- test lists -------------------------------------------------------------------
# ctest numbers of: correctness tests, regression-net tests (name regression_* or label
# 'regression'); after the baseline run the correctness tests are split by cost.
(cd "$BLD" && ctest --show-only=json-v1) > "$WORK/tests.json"
classify() {  # $1: what to print: all | correctness | regression ; $2: costs file (optional) ; $3: fast|slow
    python3 - "$WORK/tests.json" "$@" <<'PY'
import json, re, sys, os
tests = json.load(open(sys.argv[1]))["tests"]
what = sys.argv[2]
costs_file = sys.argv[3] if len(sys.argv) > 3 else ""
speed = sys.argv[4] if len(sys.argv) > 4 else ""
excluded = set(os.environ.get("MUT_EXCLUDED", "").split("\x1f")) - {""}
cost = {}
if costs_file and os.path.exists(costs_file):
    for line in open(costs_file):
        line = line.rstrip("\n")
        if line.startswith("---"):
            break
        parts = line.rsplit(" ", 2)
        if len(parts) == 3:
            try:
                cost[parts[0]] = float(parts[2])
            except ValueError:
                pass
out = []
for i, t in enumerate(tests, 1):
    labels = []
    for p in t.get("properties", []):
        if p.get("name") == "LABELS":
            labels = p.get("value") or []
    reg = t["name"].startswith("regression_") or "regression" in labels
    if t["name"] in excluded:
        continue
    if what == "regression" and not reg:
        continue
    if what == "correctness" and reg:
        continue
    if speed:
        slow = cost.get(t["name"], 0.0) >= 5.0
        if (speed == "slow") != slow:
            continue
    out.append(str(i))
print(",".join(out))
PY
}
names_of_failed() {  # names of the tests of the last ctest run that failed (the first 3, '; ')
    local f="$BLD/Testing/Temporary/LastTestsFailed.log"
    [ -s "$f" ] && sed 's/^[0-9]*://' "$f" | head -3 | paste -sd ';' - | sed 's/;/; /g' || true
}
count_failed() {
    local f="$BLD/Testing/Temporary/LastTestsFailed.log"
    [ -s "$f" ] && wc -l < "$f" || echo 0
}
run_tests() {  # $1: comma list of ctest numbers, $2: log file, $3: "nostop" to run them all; returns ctest's status
    [ -n "$1" ] || return 0
    rm -f "$BLD/Testing/Temporary/LastTestsFailed.log"
    local stop=(--stop-on-failure)
    [ "${3:-}" = nostop ] && stop=()
    run_bg ctest --test-dir "$BLD" -I "0,0,0,$1" -j "$JOBS" "${stop[@]}" --timeout "$TEST_TIMEOUT" > "$2" 2>&1
}

echo "== baseline: the whole suite unmutated"
export MUT_EXCLUDED=""
ALL=$(classify all)
t0=$(date +%s)
if ! run_tests "$ALL" "$LOGS/baseline.test.log" nostop; then
    failed=$(sed 's/^[0-9]*://' "$BLD/Testing/Temporary/LastTestsFailed.log")
    echo "the unmutated suite fails:" >&2
    printf '   %s\n' "$failed" >&2
    if [ $ALLOW_BASELINE = 0 ]; then
        echo "fix these first, or run with --allow-baseline-failures to leave them out" >&2
        exit 2
    fi
    MUT_EXCLUDED=$(printf '%s' "$failed" | tr '\n' '\037')
    echo "   left out of every mutant run (--allow-baseline-failures)" >&2
fi
echo "   $(grep -c 'Test *#' "$LOGS/baseline.test.log") tests in $(( $(date +%s) - t0 )) s"
COSTS="$BLD/Testing/Temporary/CTestCostData.txt"
FAST=$(classify correctness "$COSTS" fast)
SLOW=$(classify correctness "$COSTS" slow)
REG=$(classify regression)
n_count() { [ -n "$1" ] && echo "$1" | tr ',' '\n' | wc -l || echo 0; }
echo "   correctness: $(n_count "$FAST") fast + $(n_count "$SLOW") slow (>= 5 s) entries; regression net: $(n_count "$REG") entries"
[ $EXCLUDE_REG = 1 ] && echo "   --exclude-regression: the regression net is not run"
[ -z "$REG" ] && [ $EXCLUDE_REG = 0 ] && echo "   (no regression-net entry in this tree: both scores are the same)"

# --- the mutants ------------------------------------------------------------------
apply_mutation() {  # file orig repl: exact replace, exactly one occurrence
    python3 - "$1" "$2" "$3" <<'PY'
import sys
path, orig, repl = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(path, encoding="utf-8").read()
n = text.count(orig)
if n != 1:
    print(f"original text found {n} times (expected exactly once)", file=sys.stderr)
    sys.exit(3)
open(path, "w", encoding="utf-8").write(text.replace(orig, repl, 1))
PY
}

N=0 K_FULL=0 K_CORR=0 STALE=0 SURV_LIST=() REGONLY_LIST=()
printf '\n%-3s %-16s %-66s %-44s %6s\n' id folder mutation "killed by" seconds
for i in "${SELECTED[@]}"; do
    id=${IDS[$i]} folder=${FOLDERS[$i]} file=${FILES[$i]} desc=${DESCS[$i]}
    t0=$(date +%s)
    N=$((N + 1))
    target="$SRC/$file"
    if [ ! -f "$target" ]; then
        result="STALE (file not found)"; STALE=$((STALE + 1))
    else
        cp "$target" "$SAVED/current"
        CUR_FILE=$target
        if ! apply_mutation "$target" "${ORIGS[$i]}" "${REPLS[$i]}" 2> "$LOGS/$id.apply.log"; then
            CUR_FILE=""   # nothing was written
            result="STALE ($(cat "$LOGS/$id.apply.log"))"; STALE=$((STALE + 1))
        elif ! build "$LOGS/$id.build.log"; then
            result="killed (build error)"; K_FULL=$((K_FULL + 1)); K_CORR=$((K_CORR + 1))
        elif [ $ALL_KILLERS = 1 ]; then
            corr=$(echo "$FAST,$SLOW" | sed 's/^,//; s/,$//')
            run_tests "$corr" "$LOGS/$id.all.log" nostop || true
            nc=$(count_failed) first=$(names_of_failed)
            nr=0
            if [ $EXCLUDE_REG = 0 ] && [ -n "$REG" ]; then
                run_tests "$REG" "$LOGS/$id.regression.log" nostop || true
                nr=$(count_failed)
            fi
            reg_note=""
            [ $EXCLUDE_REG = 0 ] && [ -n "$REG" ] && reg_note=" [regression net: $([ "$nr" -gt 0 ] && echo kills || echo passes)]"
            if [ "$nc" -gt 0 ]; then
                result="$nc correctness tests: $first$reg_note"; K_FULL=$((K_FULL + 1)); K_CORR=$((K_CORR + 1))
            elif [ "$nr" -gt 0 ]; then
                result="regression net only$reg_note"; K_FULL=$((K_FULL + 1)); REGONLY_LIST+=("$id")
            else
                result="SURVIVED$reg_note"; SURV_LIST+=("$id")
            fi
        elif ! run_tests "$FAST" "$LOGS/$id.fast.log" || ! run_tests "$SLOW" "$LOGS/$id.slow.log"; then
            result="$(names_of_failed)"; [ -n "$result" ] || result="(ctest failed: see $LOGS/$id.*.log)"
            K_FULL=$((K_FULL + 1)); K_CORR=$((K_CORR + 1))
        elif [ $EXCLUDE_REG = 0 ] && [ -n "$REG" ] && ! run_tests "$REG" "$LOGS/$id.regression.log"; then
            result="regression net only: $(names_of_failed)"; K_FULL=$((K_FULL + 1)); REGONLY_LIST+=("$id")
        else
            result="SURVIVED"; SURV_LIST+=("$id")
        fi
        restore
    fi
    printf '%-3s %-16s %-66s %-44s %6d\n' "$id" "$folder" "${desc:0:66}" "$result" $(( $(date +%s) - t0 ))
done

# Leave the build matching the unmutated snapshot (restored files recompile: ccache hits).
build "$LOGS/final.build.log" || echo "warning: the restored snapshot did not rebuild: $LOGS/final.build.log" >&2

T_ALL=$(( $(date +%s) - T_START ))
echo
[ ${#REGONLY_LIST[@]} -gt 0 ] && echo "killed only by the regression net: ${REGONLY_LIST[*]}"
[ ${#SURV_LIST[@]} -gt 0 ] && echo "survivors: ${SURV_LIST[*]}"
[ $STALE -gt 0 ] && echo "STALE mutations: $STALE (the original text moved; update the table in $0)"
echo "run time: ${T_ALL} s ($(( T_ALL / 60 )) min $(( T_ALL % 60 )) s), $JOBS jobs"
if [ $EXCLUDE_REG = 1 ]; then
    echo "mutation score: $K_CORR/$N killed (correctness tests alone, regression net excluded)"
    score=$K_CORR
else
    echo "mutation score (correctness tests alone, regression net excluded): $K_CORR/$N killed"
    echo "mutation score: $K_FULL/$N killed"
    score=$K_FULL
fi
[ $STALE -gt 0 ] && exit 3
[ "$score" -lt "$N" ] && exit 1
exit 0
