#pragma once
// Rail update (paper 003 §6 and Fig. 11; docs/physics-reference.md §8.3 step 10).
//
// The rail changes much more slowly than the wheel, so its evolution is decoupled: during one rail step
// the rail r_k stays fixed while the wheel runs through its whole sequence of steps w^1..w^n. Each wheel
// profile w^j, coupled with r_k, gives a rail wear distribution d_j(s_r) and so a VIRTUAL rail profile
// r_k^j = r_k - S(d_j) c n (removal along the rail normal, common scale factor c). The next rail r_{k+1}
// is the (weighted) mean of the virtual rails, taken pointwise along the normals of r_k.
#include <limits>
#include <string>
#include <vector>

#include "conforma/profile.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/wear_distribution.hpp"

namespace conforma {

// Mean of profiles along the normals of a base profile: for each node s_i of the base (spacing of the
// base, or output_spacing_m), the normal line q(s_i) - t n(s_i) is intersected with each profile (near its
// closest point; beyond a profile's end its end tangent is extended), the signed distances t_j are
// averaged with the weights (empty = equal; must sum to 1 within 1e-9 otherwise), and the new node is
// q - mean(t) n. Returns the mean profile and mean_depth (t averaged, on the base node grid).
struct NormalAverageResult {
  Profile profile;                  // the mean profile
  WearDistribution mean_depth;      // mean removal along the base normal [m]
  double max_intersection_residual_m = 0.0;  // |(v(sigma) - q) . t| after the solve, worst node, m
};
NormalAverageResult AverageAlongNormals(const Profile& base, const std::vector<Profile>& profiles,
                                        const std::vector<double>& weights = {}, double output_spacing_m = 0.0);

// Material removed from `base` to reach `worn`, measured along the normals of base (the normal-line intersection of
// AverageAlongNormals): depth t(s_i) > 0 where worn lies inside base, at each node of base (its spacing); removed
// area = integral of t ds (trapezoid rule, WearDistribution::area_m2). This area is first order in t: the exact
// area between the two curves differs by the integral of curvature * t^2 / 2 ds. Being linear in t, it makes the
// area of a normal average the weighted mean of the averaged profiles' areas (up to the refit of the mean profile).
struct RemovedAlongNormals {
  WearDistribution depth;                    // t on the node grid of base [m]
  double area_m2 = 0.0;                      // integral of t ds [m^2]
  double max_depth_m = 0.0;                  // largest t [m] (0 when nothing is removed)
  double max_intersection_residual_m = 0.0;  // as NormalAverageResult
};
RemovedAlongNormals MeasureRemovedAlongNormals(const Profile& base, const Profile& worn);

struct RailStepOptions {
  bool keep_rail_fixed = false;          // the rail is never updated (paper 003 §7 keeps a measured rail)
  double max_depth_per_step_m = 0.1e-3;  // m, > 0: cap on the mean rail depth of one rail step (our default;
                                         // docs/physics-reference.md §8.3: the rail uses its own smaller step)
  // Upper limit of the wheel passages one rail step may represent, > 0 (default unlimited)
  double max_passages_per_step = std::numeric_limits<double>::infinity();
  DepthSmoothingOptions smoothing;       // of each rail wear distribution
  ProfileValidityOptions validity;       // of the averaged rail
  double output_spacing_m = 0.0;         // arc-length spacing of the new rail, m; 0 = that of r_k
  int step_index = 0;                    // only for messages ("rail step 2: ...")
};

// status as ProfileUpdateStatus (NoWear also when keep_rail_fixed); the fields below are filled with Updated and,
// where reached, with InvalidProfile.
struct RailStepResult {
  ProfileUpdateStatus status = ProfileUpdateStatus::NoWear;  // see ProfileUpdateStatus above
  std::string message;                 // names the step and the reason when status != Updated; "" otherwise
  Profile rail;                        // r_{k+1} (r_k when fixed, without wear, or invalid)
  std::vector<Profile> virtual_rails;  // r_k^j, one per wheel profile
  std::vector<double> weights;         // of the virtual rails in the mean (normalised; equal when none were given)
  // mean depth along the normals of r_k [m] (NoWear without keep_rail_fixed: the unscaled smoothed mean)
  WearDistribution mean_removed_depth;
  double scale_factor = 0.0;           // common factor on the smoothed rail wear (dimensionless)
  double passages_step = 0.0;          // wheel passages the rail step represents
  ProfileValidity validity;            // of the averaged rail
};

// rail_wear_per_wheel_profile[j]: rail depth (e.g. TrackClassWear::rail_depth_per_passage) while the wheel
// has profile w^j, on the grid WearDistribution::ForProfile(rail, h); weights: share of the step spent with
// each wheel profile (empty = equal); passages_represented: the wheel passages that depth stands for (1 for
// depth per passage). The common factor makes max(mean smoothed depth) equal the cap.
RailStepResult UpdateRail(const Profile& rail, const std::vector<WearDistribution>& rail_wear_per_wheel_profile,
                          const std::vector<double>& weights, double passages_represented,
                          const RailStepOptions& options = {});

}  // namespace conforma
