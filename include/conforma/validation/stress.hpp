#pragma once
// Numerical stability stress suite (issue 6; `conforma stress`, tests/test_stress.cpp): random contact situations
// that must never give NaN/inf or crash, forces continuous in the lateral shift, results independent of the number
// of OpenMP threads.
//
// Case i (deterministic: its random numbers come from a generator seeded with (seed, i) only) is, by i mod 8:
//   0-5  one wheel (SolveWheelContact, load control) on the new pair S1002 / 60E1 at 1:40, the worn pair
//        worn_high_mileage.prw / site_b_hr.prr, or S1002 with 30 um Gaussian noise smoothed by
//        Profile::FromPoints (smoothing_rms 30 um) on 60E1; model hertz / kp / kpec / conformal in turn; lateral
//        shift +-12 mm, yaw +-25 mrad, roll +-3 mrad, load log-uniform 100 N ... 200 kN; creepages either from
//        the kinematics (V = 20 m/s, axle rate V/r0 (1 + xi_drive)) or given, log-uniform magnitude 1e-6 ... 0.1
//        (full slip) with random sign, spin +-10 /m;
//   6    a near-conformal groove (wheel circle 10 mm in a groove 10 mm (1 + u), u log-uniform 1e-4 ... 0.5) as a
//        PatchGeometry, kp / kpec / conformal, load 100 N ... 200 kN, random creepages;
//   7    a degenerate patch: one strip, zero strip width, two strips, a flat (zero-gap) patch, a patch with a
//        zero curvature strip; must give a status or an InputError, never NaN or another exception.
// Wheelset mode (issue 3's check): both wheels, y +-12 mm, yaw +-25 mrad, load 1 ... 150 kN, conformal model,
// kinematic creepages, alternating the new and the worn pair.
//
// Force continuity: every continuity_every-th wheel case is solved again at y + continuity_step_m. Unless the
// contact point jumps (the number of patches changes, or a patch's reference point moves by more than
// jump_distance_m on the rail), the change of the lateral force and of each patch's normal and creep forces must
// stay below continuity_bound_fraction * load (1 % of the load per um: a lateral contact stiffness of at most one
// load per 0.1 mm), OR, where the contact is stiffer than that (two-point load sharing at a small approach: a patch
// force changes by ~1.5 F dy sin(delta) / approach; a contact point running fast over a near-conformal flange root),
// the change must shrink with the step: |dF(step / 4)| < |dF(step)| / 2, which a discontinuity cannot satisfy.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/progress.hpp"

namespace conforma {

// The profile pairs, built once (building the geometry tables is the expensive part).
struct StressSetup {
  // S1002 / 60E1 at 1:40; worn_high_mileage.prw / site_b_hr.prr; noisy S1002 / 60E1 (see above). Null until Make
  std::unique_ptr<WheelsetTrackGeometry> new_pair, worn_pair, noisy_pair;
  // Reads the worn pair from shared_data_dir; throws InputError when missing.
  static StressSetup Make(const std::string& shared_data_dir, std::uint64_t noise_seed = 7);
};

// validate() throws InputError outside the ranges given.
struct StressOptions {
  long cases = 2000;               // number of cases run, >= 0
  long first_case = 0;             // run cases first_case ... first_case + cases - 1; >= 0
  std::uint64_t seed = 20261122;   // seed of every case's generator (with the case index)
  bool wheelset_mode = false;      // issue 3's check (see above)
  int continuity_every = 8;        // 0: no continuity pairs; >= 0
  double continuity_step_m = 1e-6;           // lateral step of a continuity pair, m, > 0
  double continuity_bound_fraction = 0.01;   // bound on |dF| as a fraction of the load (dimensionless), > 0
  double jump_distance_m = 0.1e-3;           // reference-point move along the rail counted as a jump, m, > 0
  int threads = 0;                 // OpenMP threads; 0 = the default
  ProgressFunction on_progress;    // progress (progress.hpp), one unit per case ("case <index>"); empty: none
  void validate() const;
};

// Counts over the cases run (a case counts once however many of its wheels or patches are affected).
struct StressSummary {
  long cases = 0, wheel_cases = 0, patch_cases = 0, degenerate_cases = 0;  // cases run, and by kind (see above)
  long patches = 0;              // solved patches (wheel cases) / in-contact patches (patch cases)
  long non_finite = 0;           // any NaN/inf in a result
  long crashes = 0;              // an exception other than InputError
  long input_errors = 0;         // InputError: expected only for degenerate patches
  long unexpected_input_errors = 0;  // InputError on a valid random situation
  // cases with a wheel (or the patch) without contact / a wheel whose load control did not converge
  long no_contact = 0, not_converged = 0;
  // continuity pairs solved; of these, skipped as contact-point jumps; above the bound and not shrinking (failures)
  long continuity_pairs = 0, continuity_jumps = 0, continuity_violations = 0;
  long continuity_steep = 0;     // above the bound at 1 um but shrinking with the step: stiff, continuous
  double max_continuity_fraction = 0.0;  // largest |dF| / load among the non-jump pairs
  std::uint64_t digest = 0;      // hash of every result number, in case order
  double seconds = 0.0;          // wall-clock time of the run, s (not reproducible)
  std::vector<std::string> failures;  // descriptions of the first failures (NaN, crash, continuity)
  bool passed() const { return non_finite == 0 && crashes == 0 && unexpected_input_errors == 0 && continuity_violations == 0; }
};

StressSummary RunStress(const StressSetup& setup, const StressOptions& options);

}  // namespace conforma
