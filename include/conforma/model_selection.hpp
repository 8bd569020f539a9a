#pragma once
// Contact model `auto` (issue 6, "skip what a scene doesn't need"): per contact patch, the cheapest model that is
// adequate for it, decided from the undeformed geometry alone (no normal solve).
//
// ESTIMATED CONTACT. The elastic contact is estimated by Kik-Piotrowski's virtual interpenetration with the
// constant eps = 0.55 (docs/physics-reference.md §3.1): the strips whose undeformed gap is below eps * delta, delta
// the
// patch's rigid approach (in the pipeline the approach of the Hertz push-down for the wheel load, at which the
// candidates are taken). For an elliptic patch this region has the width of the Hertz ellipse to a few %.
//
// CRITERIA (thresholds: ModelSelectionOptions, defaults below).
//   conformity   alpha_c = max - min of the rail normal angle over the estimated contact (paper 003 eq. 13).
//                alpha_c > conformity_threshold_deg -> `conformal`. Default 17.7 deg: the angle above which the
//                conformal and the planar KP results differ by more than 5 % on new S1002/60E1 at 1:20
//                (`conforma threshold`, validation/threshold_*.cpp; paper 003 gives 18 deg).
//   ellipticity  the patch is Hertzian when, over the estimated contact,
//                (a) the gap is a parabola in s: a least-squares fit gap ~ c0 + c1 s + c2 s^2 leaves a largest
//                    residual <= gap_fit_tolerance * eps * delta (default 5 % of the virtual penetration);
//                (b) the lateral curvature is the one at the rigid contact point: |c2 / B - 1| <= curvature_tolerance
//                    (B = hertz_B_per_m of the Hertz point; default 10 %), i.e. the lateral radii do not change
//                    across the contact width;
//                (c) the longitudinal curvature A(s) stays within curvature_tolerance of A at the Hertz point;
//                (d) at least min_strips strips lie in the estimated contact (otherwise nothing can be judged);
//                (e) the Hertz ellipse's axis ratio g = min(a,b)/max(a,b) >= min_hertz_axis_ratio (default 0.1): the
//                    range of Kalker's creep-coefficient table behind Hertz's FASTSIM (kalker.hpp; below it the
//                    coefficients are asymptotic). `conforma bench` case flange_root_p0 (S1002/60E1 1:40 flange,
//                    g = 0.053, spin 0.2 1/m) has Hertz p_max within 0.1 % but creep forces 43 % off the conformal
//                    reference; the mbench / worn cases with g >= 0.12 are within 1 %.
//                elliptic and not conformal -> `hertz`; not elliptic ((a)-(c) fail) -> `conformal` (issue 15: its
//                strip-collocated amplitudes, docs/physics-reference.md §5.3; KPEC's amplitude rule is exact only on
//                elliptic patches and missed p_max by 11-19 % on the non-elliptic bench patches mbench_01 and the
//                worn gauge_corner treads); (d) or (e) failing, or no Hertz point -> `kpec` (planar KP with the
//                variable virtual penetration, exact for elliptic patches, docs/physics-reference.md §3.3).
//   Calibration (S1002/60E1 1:40, 10 kN, y = -9..9 mm; S1002/50E4 1:20, 40 kN): patches passing (a)-(c) have Hertz
//   p_max within 1.1 % and creep forces within 1 % of the conformal model (fit residual up to 0.04); the rejected
//   tread patches have fit residuals 0.06..0.7 and Hertz p_max errors up to +17 % (60E1 centred: the contact
//   straddles the rail's R300/R80 junction) and +12..+44 % (50E4 at 1:20, every tread position).
// The decision is a pure function of (patch, approach, Hertz point, options): deterministic and thread-safe.
//
// WHAT IT BUYS (measured 2026-11-22): `conforma bench` s31e30: median 24 us per patch against 55 us for conformal,
// with the conformal model's largest errors (p_max 12.2 % on groove_10.02, creep forces 1.0 %, wear index 9.4 %).
// On the default metro scenario (S1002 on 50E4 at 1:20) every tread patch is non-elliptic (Hertz p_max +12..+44 %),
// so 86 % of the wear patches are kpec, 14 % hertz, 0.4 % conformal, and a KPEC solve costs about what a conformal
// one does: `conforma wear --model auto --steps 7` is 1.0-1.2x faster than `--model conformal` there; no model
// choice can beat the hertz model itself (1.4-2x, the wheel-rail geometry being the rest of the cost). Its Sd/Sh/qR
// after 7 steps were within 0.02 mm of conformal on one build and 0.09/0.03/0.17 mm on the next: below the loop's
// noise floor (conformal against itself with load_tolerance 1e-7 instead of 1e-6: Sh differs by 0.21 mm).
#include "conforma/conformity.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/geometry.hpp"
#include "conforma/patch.hpp"

namespace conforma {

// The thresholds of the choice (CRITERIA above); validate() throws InputError outside the ranges given.
struct ModelSelectionOptions {
  // deg, finite; default 17.7 (conformity.hpp): alpha_c above it -> conformal
  double conformity_threshold_deg = kMeasuredConformityThresholdDeg;
  double virtual_penetration_factor = 0.55;  // eps of the estimated contact, in (0, 1]
  double gap_fit_tolerance = 0.05;           // largest parabola residual / (eps * delta), >= 0 (criterion a)
  double curvature_tolerance = 0.10;         // relative, >= 0, lateral (fit vs Hertz B) and longitudinal (A(s) vs A)
  int min_strips = 5;                        // strips in the estimated contact needed to judge (criterion d), >= 3
  double min_hertz_axis_ratio = 0.1;         // g = min(a,b)/max(a,b) of the Hertz ellipse (criterion e), >= 0
  void validate() const;  // InputError naming the option
};

// Why a model was chosen ("elliptic", "non_elliptic", ... by to_string).
enum class ModelSelectionReason {
  Elliptic,          // -> hertz
  NonElliptic,       // -> conformal (issue 15; kpec before): gap not a parabola, or curvatures change across it
  ElongatedEllipse,  // -> kpec: Hertz axis ratio below min_hertz_axis_ratio (outside Kalker's creep tables)
  NoHertzPoint,      // -> kpec: no rigid contact point with positive curvatures for Hertz
  TooFewStrips,      // -> kpec: the estimated contact covers fewer than min_strips strips
  Conformal,         // -> conformal: alpha_c above the threshold
};
const char* to_string(ModelSelectionReason reason);

// The choice and the measures behind it. The criteria are evaluated in the order conformity, strips, Hertz point,
// ellipticity, axis ratio; a measure of a criterion not reached is 0.
struct ModelSelection {
  ContactModel model = ContactModel::Kpec;  // Hertz, Kpec or Conformal
  ModelSelectionReason reason = ModelSelectionReason::TooFewStrips;  // why
  double alpha_c_deg = 0.0;            // estimated conformity index, deg (always computed)
  int strips_in_contact = 0;           // strips of the estimated contact (always computed)
  double width_m = 0.0;                // estimated contact width along s (strip centres, plus one ds), m
  double gap_fit_residual = 0.0;       // largest parabola residual / (eps * delta), dimensionless
  double lateral_curvature_error = 0.0;       // |c2 / B - 1|, dimensionless
  double longitudinal_curvature_error = 0.0;  // max |A(s) / A - 1|, dimensionless
  double hertz_axis_ratio = 0.0;              // min(a,b)/max(a,b) of the Hertz ellipse of A, B, in (0, 1]
};

// approach_m: rigid approach of the patch along its reference normal (> 0 for a contact; <= 0 gives kpec with
// TooFewStrips). hertz_point: the rigid contact point the Hertz model would use (nullptr: no Hertz). Throws
// InputError for NaN input or bad options.
ModelSelection SelectContactModel(const PatchGeometry& patch, double approach_m, const RigidContactPoint* hertz_point,
                                  const ModelSelectionOptions& options = {});

}  // namespace conforma
