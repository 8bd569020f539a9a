#pragma once
// One sample of the roller rig's real-time contact and wear (issue 18, paper 000 §3, Fig. 3;
// docs/physics-reference.md §18.3): measured lateral shift y, yaw, roller speeds (and optionally the wheelset speed)
// and wheel loads of one time step (20 ms on the rig) -> both contacts' forces and creepages (roller_rig_kinematics.hpp),
// the wear of wheel and roller, and the profile update.
//
// Wear (paper 000 §3.4): per contact cell the wear law's depth per metre rolled times the cell length dx is the depth
// per passage (ComputePatchWear, wear_distribution.hpp; Archard eqs. 7-10 with the wear map of Table 3, or the
// project's T-gamma / USFD law); per step the wheel ring receives delta_w omega_3 dt / (2 pi) and the roller ring
// delta_r omega_i dt / (2 pi) (paper 000 eq. 17: U_S = U_x / (2 pi r) * omega r dt).
// Profile update (paper 000 §3.5): every step the profiles in contact are the reference profiles minus the raw depth
// accumulated since the last filter, removed along the local normal (eqs. 19-21, RemoveAlongNormal,
// profile_update.hpp); every filter_every_steps steps the accumulated depth is regularised by a sliding mean and
// removed from the reference profiles for good (the sliding mean acts on the wear, not on the profile shape, so that
// the unworn parts of the profiles, e.g. the roller's crown radii, are not smoothed).
#include <array>
#include <limits>
#include <memory>
#include <string>

#include "conforma/roller_rig_kinematics.hpp"
#include "conforma/wear_distribution.hpp"

namespace conforma {

// Archard: paper 000 Table 3 maps (ArchardMap::Paper000Wheel / Paper000Roller, hardness of Table 4);
// WearIndex: the project's T-gamma / USFD law for both bodies (wear_law.hpp).
enum class RollerRigWearLaw { Archard, WearIndex };
const char* to_string(RollerRigWearLaw law);              // "archard", "wear_index"
RollerRigWearLaw RollerRigWearLawFromName(const std::string& name);  // the names above; InputError otherwise

// validate() throws InputError for a value outside the ranges given.
struct RollerRigSampleOptions {
  RollerRigSetup setup;                   // the rig (Table 1, profiles, springs)
  RollerRigKinematicsOptions kinematics;  // contact and balance options (RollerRigSampleOptions::Defaults: rig ones)
  RollerRigWearLaw wear_law = RollerRigWearLaw::Archard;  // see RollerRigWearLaw
  double wear_grid_spacing_m = 0.02e-3;   // arc-length spacing of the depth grids, m, > 0 (0.1 mm x phi)
  // Paper 000 eq. 16 takes a strip's depth per passage as the MEAN of its C FASTSIM elements (C = 20, §3.4), i.e.
  // 1/C of the depth integrated over the strip (eq. 8 already holds the element's dx); the wear coefficients of its
  // Table 3 were calibrated against the measured profiles with that rule. The code integrates (paper 001 eq. 24), so
  // the depth of every cell is divided by this C, independent of the contact model's own grid. >= 1; 1: the
  // integrated depth with the coefficients as printed (the Archard volume of eq. 6); 20: paper 000's calibration
  // (the scenario's default, docs/physics-reference.md §18.3). Archard (Table 3) only: the USFD wear-index law is
  // calibrated on the integrated depth and is not divided.
  double strip_mean_elements = 1.0;
  bool update_profiles = true;            // false: wear is computed and reported, the profiles stay as they are
  // Sliding-mean filter and final removal every N steps (paper 000 §3.5: 10 steps of 20 ms), >= 1. With coarser
  // steps keep the filter period N dt near 0.2 s (RollerRigFilterSteps).
  int filter_every_steps = 10;
  // The profiles in contact (and the geometry built from them) take the raw wear every N steps, >= 1; 1 (default):
  // every step, as paper 000 §3.5. With N < filter_every_steps (real time) the geometry is not rebuilt but updated
  // where the wear moved the profiles, bit for bit a rebuild (WheelsetTrackGeometry's update constructor; the rollers
  // mounted by translation, GeometryOptions::refit_uninclined_rail false), also at the filters until a refit; N =
  // filter_every_steps updates (and rebuilds) at the filters only, with the refitted mounting, as the test plan does.
  int profile_update_every_steps = 1;
  // At a filter step the smoothed depth is removed by moving the reference profile's samples along their normals
  // (no refit) while the depth so moved since the last refit stays below this fraction of the sample spacing; beyond
  // it RemoveAlongNormal refits and checks the profile (profile_update.hpp). >= 0; 0: refit at every filter.
  double refit_depth_fraction = 0.1;
  // Width of the sliding mean along the arc length, m, >= 0 (0: no filter). Default 1 mm: ~4 % of the rig wheel's
  // 26 mm profile (paper 001's sliding mean spans 1-5 % of the profile points), about the contact width 2b. Narrower
  // windows (0.5 mm) leave ripples of the strip-wise depth that the Hertz model reads as many sharp contact points
  // (p_max of several GPa, the severe Archard coefficient): the groove runs away within the second test of Table 5.
  double filter_window_m = 1.0e-3;
  // Stability rule of the explicit wear update (docs/physics-reference.md §18.3): the depth one step adds to wheel +
  // roller on a side should stay below this fraction of that contact's elastic approach (the approach of its most
  // loaded patch). Wear opens the gap where it acts; an update comparable to the approach moves the whole load within
  // one step (explicit Euler on a relaxation whose time constant is approach / wear rate), overshoots and runs away.
  // The sample reports the ratio and whether the rule holds (the real-time path keeps its step); the plan runner
  // repeats a step that breaks it in smaller sub-steps (RollerRigPlanOptions::adaptive_substeps). > 0; default 0.1.
  double max_depth_per_approach = 0.1;
  void validate() const;
  // The rig defaults: kinematics.contact = RollerRigContactOptions(setup).
  static RollerRigSampleOptions Defaults(const RollerRigSetup& setup = {});
};

// Steps per filter for a step dt so that the filter period stays the paper's 10 x 20 ms: max(1, round(0.2 s / dt)).
int RollerRigFilterSteps(double step_s);

// One measured (or prescribed) sample.
struct RollerRigSample {
  double time_s = 0.0;                                 // time stamp, s (reported only)
  double duration_s = 0.02;                            // time step dt the sample stands for, s, > 0 (rig: 20 ms)
  double lateral_m = 0.0;                              // wheelset lateral shift y, m
  double yaw_rad = 0.0;                                // wheelset yaw, rad
  double lateral_velocity_m_s = 0.0;                   // dy/dt, m/s
  std::array<double, 2> roller_speed_rad_s{0.0, 0.0};  // omega_1, omega_2, rad/s, > 0
  std::array<double, 2> wheel_load_N{0.0, 0.0};        // vertical load per wheel [left, right], N, > 0
  double wheelset_speed_rad_s = std::numeric_limits<double>::quiet_NaN();  // measured omega_3; NaN: balance solved
};

// The evolving rig: profiles and the wear accumulated since the last filter. Copyable (the geometry is shared and
// immutable); one state per rig, not shared between threads while it is being processed.
struct RollerRigState {
  std::array<Profile, 2> wheel;         // the wheel profiles in contact now [left, right]
  std::array<Profile, 2> roller;        // the roller profiles in contact now [roller 1, roller 2]
  std::array<Profile, 2> wheel_reference;   // wheel profiles at the last filter
  std::array<Profile, 2> roller_reference;  // roller profiles at the last filter
  std::array<WearDistribution, 2> wheel_pending;   // raw depth since the last filter, on the reference wheel grids, m
  std::array<WearDistribution, 2> roller_pending;  // on the reference roller grids, m
  std::shared_ptr<const WheelsetTrackGeometry> geometry;  // of wheel / roller
  std::array<double, 2> wheel_unrefit_m{0.0, 0.0};   // depth moved without refit since the last refit, m
  std::array<double, 2> roller_unrefit_m{0.0, 0.0};  // m
  long step = 0;                        // samples processed with wear
  double time_s = 0.0;                  // sum of the processed samples' durations, s
  std::array<double, 2> roller_distance_m{0.0, 0.0};  // rolled distance of each roller surface, m
};
// Initial state: the rig's profiles (MakeRollerRigWheelProfile / RollerProfile) on both sides, or the given ones.
RollerRigState MakeRollerRigState(const RollerRigSampleOptions& options);
RollerRigState MakeRollerRigState(const RollerRigSampleOptions& options, const std::array<Profile, 2>& wheel,
                                  const std::array<Profile, 2>& roller);

// Ok: forces, wear and (if enabled) profiles updated. ContactFailed: the kinematics did not converge or a wheel has no
// contact (no wear applied; the kinematics status and message say why). ProfileUpdateFailed: the removal failed
// (e.g. a self-intersecting profile); the state keeps its previous profiles.
enum class RollerRigSampleStatus { Ok, ContactFailed, ProfileUpdateFailed };
const char* to_string(RollerRigSampleStatus status);  // "ok", "contact_failed", "profile_update_failed"

struct RollerRigSampleResult {
  RollerRigSampleStatus status = RollerRigSampleStatus::Ok;  // see RollerRigSampleStatus
  std::string message;                     // reason when not Ok; "" otherwise
  RollerRigKinematicsResult kinematics;    // forces, creepages, wheelset speed, springs (with the cells)
  std::array<double, 2> wheel_wear_max_depth_m{0.0, 0.0};   // largest depth added this step per wheel, m
  std::array<double, 2> roller_wear_max_depth_m{0.0, 0.0};  // per roller, m
  std::array<double, 2> wheel_wear_area_m2{0.0, 0.0};       // integral of the added depth over the arc length, m^2
  std::array<double, 2> roller_wear_area_m2{0.0, 0.0};      // m^2
  std::array<double, 2> wheel_wear_volume_m3{0.0, 0.0};     // area x 2 pi r_i (ring volume), m^3
  std::array<double, 2> roller_wear_volume_m3{0.0, 0.0};    // area x 2 pi R_i, m^3
  std::array<double, 2> max_slip_velocity_m_s{0.0, 0.0};    // largest |s| V_i over the cells, m/s
  // Elastic approach of each side's most loaded patch, m (the scale of the stability rule)
  std::array<double, 2> elastic_approach_m{0.0, 0.0};
  // max over the sides of (wheel + roller largest depth added this step) / elastic approach; +inf when wear was
  // added to a side without a positive approach
  double depth_per_approach = 0.0;
  bool stability_rule_violated = false;    // depth_per_approach > options.max_depth_per_approach
  bool profiles_updated = false;           // the profiles in contact changed this step
  bool filtered = false;                   // the sliding-mean filter ran this step
  long step = 0;                           // the state's step count after this sample
};

// InputError for bad options or sample values; a failed contact or profile update is a status.
RollerRigSampleResult ProcessRigSample(const RollerRigSampleOptions& options, RollerRigState* state,
                                       const RollerRigSample& sample);

// The sliding mean of paper 000 §3.5 on a depth grid: each node the mean of the nodes within +-window/2 (the window
// shrinks symmetrically at the ends). Exposed for the tests.
WearDistribution SlidingMean(const WearDistribution& depth, double window_m);

}  // namespace conforma
