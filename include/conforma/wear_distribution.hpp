#pragma once
// Wear distributions along the wheel and rail profile arc lengths (paper 001 §6.2 eqs. 24-27,
// paper 003 §6 steps 1-3, docs/physics-reference.md §8.3 steps 2-5).
//
//  1. Longitudinal integration (paper 001 eq. 24): each cell of a contact patch removes
//     depth_per_rolled_metre * dx per passage; summing the cells of one strip along x gives the depth per
//     passage delta(s) at the strip's arc length (s_w on the wheel, s_r on the rail).
//  2. Spreading: a wheel point passes through the patch once per revolution, so per metre travelled the
//     wheel loses delta(s_w) / (2 pi R) (paper 001 eq. 23, paper 000 eq. 17). A rail point is passed once
//     by each wheel: the rail keeps delta(s_r) per wheel passage.
//  3. Time integration and the sum over contact points (eqs. 25-26): every time sample carries the
//     distance travelled during it; wheel depth adds up as delta/(2 pi R) * distance, rail depth as
//     delta * distance / (class length), i.e. the mean depth per wheel passage along the class's track.
//  4. Track classes with weights p_k, sum p_k = 1 (eq. 27): weighted mean of the per-metre (wheel) and
//     per-passage (rail) results.
//
// The depth grids are uniform in arc length: node i at s_i = i * spacing, i = 0..n-1, spacing = L/(n-1)
// for a profile of arc length L (same construction as the samples of Profile). A cell deposits its depth
// on the nodes in proportion to the overlap of its lateral extent [s - w/2, s + w/2] (w = area / dx) with
// the node cells [s_i - h/2, s_i + h/2] clipped to [0, L], so the removed area (trapezoid rule) is exactly
// conserved; area that falls outside the profile is reported, not lost silently.
#include <Eigen/Core>
#include <vector>

#include "conforma/material.hpp"
#include "conforma/profile.hpp"
#include "conforma/wear_law.hpp"

namespace conforma {

// Depth on a uniform arc-length grid [m].
struct WearDistribution {
  double spacing_m = 0.0;
  std::vector<double> depth_m;

  // Grid covering [0, length] with spacing <= the requested one (n = ceil(L/spacing) + 1 nodes), zero depth.
  static WearDistribution Zero(double length_m, double spacing_m);
  // Grid over the arc length of a profile.
  static WearDistribution ForProfile(const Profile& profile, double spacing_m = 0.1e-3);

  size_t size() const { return depth_m.size(); }
  double length_m() const { return depth_m.empty() ? 0.0 : spacing_m * (depth_m.size() - 1); }
  double s(size_t i) const { return spacing_m * i; }
  double max_depth_m() const;
  // Removed area per unit length along the track, integral of depth ds (trapezoid rule) [m^2].
  double area_m2() const;
  // Linear interpolation at arc length s (0 outside [0, length]).
  double at(double s_m) const;
  bool same_grid(const WearDistribution& other) const;
  // this += weight * other (grids must match; InputError otherwise).
  void add(const WearDistribution& other, double weight);
};

// Contact state of one cell of one contact patch, as the normal/tangential solvers deliver it.
struct WearCell {
  Eigen::Vector2d traction_Pa = Eigen::Vector2d::Zero();  // tangential traction p_t (x, y) [Pa]
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();         // relative slip velocity / V (x, y) [-]
  double pressure_Pa = 0.0;                               // normal pressure p
  double area_m2 = 0.0;                                   // cell area
  double length_x_m = 0.0;                                // cell length along the rolling direction x
  double wheel_s_m = 0.0;                                 // cell centre mapped to the wheel arc length
  double rail_s_m = 0.0;                                  // cell centre mapped to the rail arc length
};

// One contact patch at one time sample.
struct WearPatch {
  std::vector<WearCell> cells;
  double rolling_speed_m_s = 0.0;  // V
  double wheel_radius_m = 0.0;     // rolling radius at the patch, R (circumference spreading)
};

// Wear laws and materials of the two bodies (the same law for both by default: paper 003 uses one
// wear index for both sides, eqs. 16-17 with K_ww and K_wr).
struct WearModel {
  WearLaw wheel_law;
  WearLaw rail_law;
  Material wheel_material;
  Material rail_material;
};

// Depth per passage of one patch (step 1) on the given grids.
struct PatchWear {
  WearDistribution wheel_depth_per_passage;
  WearDistribution rail_depth_per_passage;
  double wheel_area_outside_m2 = 0.0;  // removed area of cells outside the wheel grid (should be 0)
  double rail_area_outside_m2 = 0.0;
};
// Throws InputError naming the cell for non-finite or negative cell data.
PatchWear ComputePatchWear(const WearPatch& patch, const WearModel& model, const WearDistribution& wheel_grid,
                           const WearDistribution& rail_grid);

// All contact patches of one wheel at one time sample, and the distance travelled during the sample.
struct WearSample {
  std::vector<WearPatch> patches;
  double distance_m = 0.0;
};

// Result of one track class (or of the weighted combination of classes).
struct TrackClassWear {
  WearDistribution wheel_depth_per_metre;   // wheel depth per metre travelled [m/m]
  WearDistribution rail_depth_per_passage;  // mean rail depth per wheel passage [m]
  double distance_m = 0.0;                  // distance simulated
  double area_outside_m2 = 0.0;             // wheel + rail removed area (per passage) that fell off the grids
};

// Streaming accumulation of the samples of one track class (steps 1-3). Not thread-shared: use one
// accumulator per thread and merge() them.
class WearAccumulator {
 public:
  WearAccumulator(const WearDistribution& wheel_grid, const WearDistribution& rail_grid, WearModel model);
  void add(const WearSample& sample);
  void merge(const WearAccumulator& other);
  // Divides by the distance accumulated so far: wheel per metre, rail per passage.
  TrackClassWear result() const;

 private:
  WearModel model_;
  WearDistribution wheel_sum_, rail_sum_;  // sum delta/(2piR)*d and sum delta*d
  double distance_m_ = 0.0, outside_m2_ = 0.0;
};

TrackClassWear IntegrateTrackClass(const std::vector<WearSample>& samples, const WearModel& model,
                                   const WearDistribution& wheel_grid, const WearDistribution& rail_grid);

// Weighted combination (paper 001 eq. 27). weights must be >= 0 and sum to 1 within 1e-9 (InputError).
TrackClassWear CombineTrackClasses(const std::vector<TrackClassWear>& classes, const std::vector<double>& weights);

}  // namespace conforma
