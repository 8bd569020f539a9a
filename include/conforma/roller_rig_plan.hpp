#pragma once
// Roller-rig scenario and wear test plan (issue 18, paper 000 §4 and Table 5; docs/physics-reference.md §18.4):
// the rig (Table 1 and the options of roller_rig.hpp), the contact and wear options, and a list of wear tests (creepage,
// reference speed, load per wheel, distance) run one after the other, each from the previous test's final profiles.
//
// A test: roller 1 turns at the reference speed omega_ref, roller 2 at omega_ref (1 - xi) / (1 + xi), so that eq. 2
// with equal radii gives the creepages +xi / -xi (paper 000 §4: the second roller is slowed to a fixed ratio, the
// motors in electronic gearing); the wheelset speed is the balance's (roller_rig_kinematics.hpp). The wheelset is
// centred (y = 0, yaw 0; the paper's measured y(t) is not published). The test runs for distance / (omega_ref R_r) in
// steps of step_s (Table 5's km travelled are the reference roller's surface distance: 21.8 km in 37 min at
// 500 rpm x 0.185 m, 10.2 km in 35 min at 250 rpm).
//
// Scenario file (YAML), every key optional except plan; any other key is an InputError naming the file and the key
// (yaml_keys.hpp):
//   rig:     roller_radius_m, wheel_radius_m, wheelset_mass_kg, inertia_kg_m2 [Ix, Iy, Iz], length_factor,
//            longitudinal_stiffness_N_per_m, spring_half_spacing_m, wheel_profile, wheel_conicity_rad,
//            wheel_width_field_m, roller_profile   (RollerRigSetup; profile files relative to the scenario file)
//   contact: model, friction_coefficient, fastsim_elements
//   wear:    law (archard | wear_index), step_s, filter_window_m, filter_interval_s, grid_spacing_m
//   gravity_m_s2
//   wheelset_speed: balance (default; the moment balance) | eq2 (opposite creepages +-xi, as Table 5 prescribes)
//   plan:    list of {test, creep, reference_speed_rpm, wheel_load_kg, distance_km, time_min (printed, reported)}
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "conforma/roller_rig_sample.hpp"

namespace conforma {

// One row of the test plan (paper 000 Table 5).
struct RollerRigWearTestCase {
  int test = 0;                      // test number
  double creep = 0.0;                // creepage magnitude xi of each contact (eq. 2, opposite signs), in [0, 1)
  double reference_speed_rpm = 0.0;  // roller 1 speed, rpm, > 0
  double wheel_load_kg = 0.0;        // vertical load per wheel, kg, > 0
  double distance_km = 0.0;          // reference roller surface distance, km, > 0
  double time_min = 0.0;             // test time printed in the plan, min (reported beside the simulated time)
};

struct RollerRigScenario {
  std::string source;                   // the file read
  RollerRigSampleOptions options;       // rig, contact, wear, filter (filter_every_steps from filter_interval_s)
  double step_s = 1.0;                  // time step of the plan runs, s, > 0
  double filter_interval_s = 0.2;       // sliding-mean period (paper 000: 10 x 20 ms), s, > 0
  double gravity_m_s2 = 9.81;           // kg -> N, > 0
  std::vector<RollerRigWearTestCase> plan;  // the tests, in order
};
// InputError "<file>: <key>: ..." for a malformed file or a value out of range.
RollerRigScenario LoadRollerRigScenario(const std::string& path);

// Options of a plan run.
struct RollerRigPlanOptions {
  double step_s = 0.0;            // overrides the scenario's step when > 0, s
  double distance_fraction = 1.0; // run this fraction of each test's distance (a shorter check), in (0, 1]
  int max_tests = 0;              // run only the first N tests when > 0
  // true: a step whose wear breaks the stability rule (RollerRigSampleOptions::max_depth_per_approach) is repeated in
  // halved sub-steps, down to min_substep_s, s (> 0); false (default): every step as it is (the rule is counted only).
  // Not the default: with the hertz model and Table 3 the sub-steps do not make the plan's result step-independent
  // nor stop the groove runaway (docs/physics-reference.md §18.6).
  bool adaptive_substeps = false;
  double min_substep_s = 1e-4;
  // Called after every sample: (test index, sample index, samples of the test); may be empty.
  std::function<void(int, long, long)> progress;
};

// Worn depth between two profiles of one body: the vertical (wheel: radial) difference z_before - z_after over their
// common y range, sampled every 2 um.
struct ProfileWearSummary {
  double max_depth_m = 0.0;  // largest difference, m
  double area_m2 = 0.0;      // integral of the positive difference over y, m^2
};
ProfileWearSummary CompareProfiles(const Profile& before, const Profile& after);

// Ok: every sample processed; SamplesFailed: some samples failed (their wear is missing; counted in failed_samples).
enum class RollerRigTestStatus { Ok, SamplesFailed };
const char* to_string(RollerRigTestStatus status);  // "ok", "samples_failed"

struct RollerRigTestResult {
  RollerRigWearTestCase test;                      // the plan row
  RollerRigTestStatus status = RollerRigTestStatus::Ok;  // see RollerRigTestStatus
  std::string first_failure;                       // message of the first failed sample; "" when none
  long samples = 0;                                // samples processed
  long failed_samples = 0;                         // samples whose status was not ok
  long substeps = 0;                               // accepted sub-steps (= samples without adaptive sub-steps)
  long rejected_substeps = 0;                      // sub-steps repeated shorter (stability rule)
  long stability_violations = 0;                   // accepted sub-steps that still break the rule (at min_substep_s)
  double min_substep_s = 0.0;                      // shortest accepted sub-step, s
  double max_depth_per_approach = 0.0;             // largest depth per step / elastic approach accepted
  double simulated_time_s = 0.0;                   // sum of the sample durations, s
  double distance_m = 0.0;                         // reference roller surface distance simulated, m
  double run_time_s = 0.0;                         // wall-clock time of the test, s
  double mean_wheelset_speed_rad_s = 0.0;          // mean omega_3, rad/s
  std::array<double, 2> mean_creepage{0.0, 0.0};   // mean xi of each contact
  std::array<double, 2> mean_fx_N{0.0, 0.0};       // mean longitudinal creep force on each wheel, N
  std::array<ProfileWearSummary, 2> wheel_wear;    // this test's wheel wear [left, right] (profile difference)
  std::array<ProfileWearSummary, 2> roller_wear;   // [roller 1, roller 2]
  std::array<ProfileWearSummary, 2> wheel_wear_total;   // since the start of the plan
  std::array<ProfileWearSummary, 2> roller_wear_total;  // since the start of the plan
  std::array<Profile, 2> wheel;                    // profiles at the end of the test
  std::array<Profile, 2> roller;                   // at the end of the test
};

// Runs the plan from the rig's initial profiles. InputError for bad options.
std::vector<RollerRigTestResult> RunRollerRigPlan(const RollerRigScenario& scenario, const RollerRigPlanOptions& options);

}  // namespace conforma
