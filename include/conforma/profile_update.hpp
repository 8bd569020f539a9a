#pragma once
// Profile update of one wear step (paper 003 §6 eqs. 18-19, paper 001 §6.2 eqs. 28-30,
// docs/physics-reference.md §8.3 steps 6-9).
//
// Order (our choice, documented in UpdateProfile): SMOOTH, then SCALE, then REMOVE.
//   1. Mass-conserving smoothing S of the accumulated depth (penalised least squares, CHOLMOD).
//      S is positively homogeneous, S(c d) = c S(d) for c > 0, so smoothing first and scaling second is
//      the same as the paper's scale-then-smooth, except that the scale factor is fixed on the SMOOTHED
//      maximum: the final max depth equals the cap exactly (up to rounding) and the distance of the step
//      is distance_step = distance_represented * cap / max(S(d)) (paper 001 eq. 28 with the adaptive
//      threshold of paper 003 §6).
//   2. Removal along the local outward normal: P_new(s) = P(s) - d(s) n(s) (eqs. 18-19), then
//      re-parametrisation by arc length (Profile::FromPoints, input order = arc-length order).
//   3. Validity checks of the new profile (no self-intersection, no new folds in y, curvature bound). A wheel
//      whose flange face is worn past vertical (a new fold in y) gets the overhanging lip cut back
//      (CutOverhangs, ProfileUpdateOptions::cut_overhangs), the corner at the top of the cut rounded by an opening
//      with a 1.25 mm disc (material removed only), refitted, and cut again on the refit's samples, which are kept as
//      the new profile's nodes (Profile::FromArcLengthSamples): single-valued in y by construction. The area removed
//      by the cut and its rounding is reported; the profile is checked again.
#include <limits>
#include <string>

#include "conforma/profile.hpp"
#include "conforma/wear_distribution.hpp"

namespace conforma {

// ---------------------------------------------------------------- mass-conserving smoothing
// Whittaker smoother (penalised least squares with second differences) on the uniform s grid:
//   (W + lambda D2^T D2) f = W d,   W = trapezoid weights (1/2 at the ends, 1 inside)
// Because D2 * 1 = 0, 1^T W f = 1^T W d: the removed area (trapezoid) is preserved exactly, and linear
// depth fields pass unchanged. Inside the grid the gain at wavelength Lw is
// 1 / (1 + 16 lambda sin^4(pi h / Lw)); lambda is chosen so the gain is 1/2 at cutoff_wavelength_m.
// Negative values (ringing next to spikes) are clipped to 0 and the remaining field is rescaled by the
// area ratio, so the result is >= 0 and keeps the area exactly.
// The paper-001 sliding mean over 1-5 % of the profile points (about 1.5-7.5 mm on a wheel) has its
// half-gain wavelength at about 1.66 window widths; the default 5 mm is within that range.
struct DepthSmoothingOptions {
  double cutoff_wavelength_m = 5.0e-3;  // half-gain wavelength, m, >= 0; 0 disables smoothing
};
struct DepthSmoothingResult {
  WearDistribution depth;     // the smoothed depth on the input grid, m, >= 0 (the input when smoothing is off)
  double area_in_m2 = 0.0;    // trapezoid area of the input, m^2 (depth x arc length)
  double area_out_m2 = 0.0;   // trapezoid area of the output, m^2 (= area_in_m2 up to rounding)
  size_t clipped_nodes = 0;   // nodes where the smoother went negative and were set to 0
};
// Throws InputError for negative or non-finite input depth.
DepthSmoothingResult SmoothDepthMassConserving(const WearDistribution& depth, const DepthSmoothingOptions& options);

// ---------------------------------------------------------------- removal along the normal
// Points P(s_i) - d_i n(s_i) at the depth grid nodes, re-parametrised by arc length with the given
// sample spacing (0: the profile's own spacing). The depth grid must span the profile's arc length
// (WearDistribution::ForProfile). Throws InputError if the grid does not match or the new curve
// self-intersects (message from Profile::FromPoints, prefixed with `context`).
Profile RemoveAlongNormal(const Profile& profile, const WearDistribution& depth, double output_spacing_m = 0.0,
                          const std::string& context = "profile update");

// Points of a curve that should be single-valued in y, ordered so that y does not decrease: every point whose y
// exceeds that of a later point is moved back to the smallest later y (reverse running minimum), i.e. material
// is only removed (material lies towards -y of a face that y increases along). Returns the area between the
// input and the output polylines (the material cut away) [m^2].
double CutOverhangs(std::vector<Eigen::Vector2d>* points);

// ---------------------------------------------------------------- validity
struct ProfileValidityOptions {
  // Kink criterion: |curvature| must stay below this [1/m] (1/(1 mm)) wherever the previous profile was
  // below it; where the previous profile itself was sharper (e.g. a tight flange radius), the new
  // curvature may not exceed 1.2 x the previous maximum within +-2 mm.
  double max_curvature_1_m = 1.0e3;  // 1/m, > 0
  // Fold criterion: the profile must stay single-valued in y; a reversal of y along the curve counts as a fold once
  // y has moved back by more than this from its running extreme (hysteresis): wiggles of a vertical flange face
  // below it are rounding, not an overhang. 1 um: below profile-measurement resolution. (A profile after an
  // overhang cut has no reversal at all: UpdateProfile cuts the refitted samples again.)
  double fold_tolerance_m = 1.0e-6;  // m, > 0
};
// The checks stop at the first failure (non-finite points, self-intersection, new folds, kink); the fields of the
// later checks then keep their defaults.
struct ProfileValidity {
  bool valid = true;                  // all checks passed
  std::string reason;                 // empty when valid
  double max_abs_curvature_1_m = 0.0; // of the new profile, 1/m
  int y_folds_before = 0, y_folds_after = 0;  // reversals of y along the curve beyond fold_tolerance_m (previous / new)
};
ProfileValidity CheckProfileValidity(const Profile& updated, const Profile& previous,
                                     const ProfileValidityOptions& options = {});

// ---------------------------------------------------------------- one update step
// InputError (UpdateProfile) for a cap or distance limit <= 0.
struct ProfileUpdateOptions {
  double max_depth_per_step_m = 0.4e-3;  // m, > 0: cap on the largest depth of a step (paper 003 §6: 0.4 mm)
  // Upper limit of the distance one step may represent (e.g. to land on the target mileage), m, > 0 (default
  // unlimited); when it binds, the max depth of the step is below the cap.
  double max_distance_step_m = std::numeric_limits<double>::infinity();
  DepthSmoothingOptions smoothing;  // step 1
  ProfileValidityOptions validity;  // step 3
  double output_spacing_m = 0.0;  // arc-length spacing of the new profile, m, >= 0; 0 = that of the old one
  // A profile that was single-valued in y (no folds) and folds after the removal (a flange face worn past
  // vertical: the lip above overhangs the worn band below) gets the lip cut back to the vertical through the
  // band (CutOverhangs): contact would wear it off at once. The corner at the top of the cut is rounded (radius
  // 1.25 mm, material removed only) and the result is single-valued in y by construction (see step 3 above). The
  // area removed by the cut and its rounding is reported; false: invalid instead.
  bool cut_overhangs = true;
  // With a cut: the lip is flange-face wear the contact would have done there instead of on the band below it, so
  // the step removes the area the wear law gave (docs/physics-reference.md §8.7): the removed depth over the cut is
  // scaled by k (ProfileUpdateResult::cut_area_scale), tapering back to 1 as a half cosine over two smoothing
  // lengths (>= 5 mm) on either side, with k set so that removal + cut = the removal's area unscaled; the step's
  // distance is unchanged. false: the lip is cut on top of the step's wear (it is worn off at once).
  bool cut_conserves_area = true;
  int step_index = 0;             // only for messages ("wear step 3: ...")
};

// Updated: the profile was updated and is valid. NoWear: the smoothed depth is nowhere > 0 (profile unchanged).
// InvalidProfile: the removal failed (self-intersection) or the new profile failed a validity check.
enum class ProfileUpdateStatus { Updated, NoWear, InvalidProfile };
const char* to_string(ProfileUpdateStatus status);  // "updated", "no wear", "invalid profile"

struct ProfileUpdateResult {
  ProfileUpdateStatus status = ProfileUpdateStatus::NoWear;  // see ProfileUpdateStatus
  std::string message;           // names the step and the failed check when status != Updated; "" otherwise
  Profile profile;               // the new profile (the old one when status != Updated)
  // smoothed, scaled depth actually removed [m] (NoWear: the smoothed depth, unscaled)
  WearDistribution removed_depth;
  double scale_factor = 0.0;     // removed_depth = scale_factor * S(accumulated); 0 with NoWear
  double distance_step_m = 0.0;  // distance the step represents = distance_represented * scale_factor, m
  double max_depth_m = 0.0;      // max of removed_depth, m (= cap unless max_distance_step_m binds)
  double removed_area_m2 = 0.0;  // integral of removed_depth ds, m^2
  // m^2, extra area removed by cutting overhangs and rounding the cut (ProfileUpdateOptions::cut_overhangs): the area
  // between the profile after the removal and the final one; 0 when no cut was made
  double overhang_cut_area_m2 = 0.0;
  // the factor on the removed depth around the cut with ProfileUpdateOptions::cut_conserves_area (1: no cut)
  double cut_area_scale = 1.0;
  // with cut_conserves_area and a cut: whether a k balanced the areas (to 1e-3); false: the lip was cut on top of
  // the wear (as without the option) because no taper of up to 16 smoothing lengths (>= 40 mm) held the band
  bool cut_area_conserved = true;
  DepthSmoothingResult smoothing;  // diagnostics of step 1 (before scaling)
  ProfileValidity validity;        // of the new profile (default when NoWear or the removal failed)
};

// accumulated_depth: the depth the simulated distance `distance_represented_m` removes (e.g. a wheel's
// depth per metre with distance 1 m), on the grid WearDistribution::ForProfile(profile, h).
ProfileUpdateResult UpdateProfile(const Profile& profile, const WearDistribution& accumulated_depth,
                                  double distance_represented_m, const ProfileUpdateOptions& options = {});

}  // namespace conforma
