#pragma once
// Accuracy check of a contact look-up table against the direct pipeline (`conforma lut check`): random poses
// inside the table, each solved by SolveWheelContact at the rigid-equilibrium pose (as the quasi-static curving
// does) and by EvaluateContactLut, with random curving-like velocities.
//
// Away from contact jumps (the pose's grid cell has one topology at its 8 corners) the errors per patch are
// (patches paired in order when both have the same topology): normal force |dFn| / Q, creep forces |dFx|, |dFy|
// / (mu Q), contact position |d y_rail| (m). At jumps (corners of two topologies) the direct solve's topology is
// compared with the LUT's; when they differ, the jump is "within one grid step" if the direct topology is that of
// one of the cell's corners (the change happens inside the cell).
#include <cstdint>
#include <ostream>
#include <vector>

#include "conforma/contact_lut.hpp"

namespace conforma {

struct ContactLutCheckOptions {
  int samples = 1000;                 // random poses, >= 1
  std::uint64_t seed = 1;             // std::mt19937_64 seed (the same samples for any thread count)
  double speed_m_s = 10.0;            // forward speed V, > 0
  // Velocity ranges (uniform): lateral velocity / V in +-lateral_creep, yaw rate / V in +-curvature (1/m), axle
  // speed V / r0 (1 + u) with u in +-axle_creep
  double lateral_creep = 2e-3, curvature_per_m = 1.0 / 200.0, axle_creep = 2e-3;
  WheelContactOptions contact;  // the direct solve's options (the load is set per sample); must match the table
  LutEvaluationOptions evaluation;  // the table's creep forces (fastsim: as the direct solve; polach: the closed form)
  int threads = 0;              // OpenMP threads, 0: the default
  ProgressFunction on_progress;  // progress (progress.hpp), one unit per sample ("sample <k>"); empty: none
  void validate() const;
};

struct Percentiles {
  int count = 0;
  double p50 = 0.0, p90 = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
  // the sample of the largest error: side (0 left, 1 right), y (m), psi (rad), Q (N)
  int worst_side = 0;
  double worst_y_m = 0.0, worst_yaw_rad = 0.0, worst_load_N = 0.0;
};

// One random pose of the check: where it was and what it showed (`conforma lut check --samples-csv`).
struct ContactLutCheckSample {
  int side = 0;                   // 0 left, 1 right
  double y_m = 0.0, yaw_rad = 0.0, load_N = 0.0;
  // single (one topology at the cell's corners, both Ok), jump_same, jump_corner, jump_outside (cells with a topology
  // change), single_mismatch (one topology at the corners, another in the direct solve), status_mismatch,
  // both_failed, no_equilibrium (the pose has no rigid equilibrium: not solved)
  const char* category = "no_equilibrium";
  bool lut_error = false;         // EvaluateContactLut threw
  int patches_direct = 0, patches_lut = 0;
  // single only (NaN otherwise): the largest per-patch error over the paired patches, as in the percentiles
  double fn_rel = 0.0, fx_rel = 0.0, fy_rel = 0.0, rail_y_m = 0.0, lateral_rel = 0.0;
  // the direct solve's wheel: sum of the patches' Fn, Fx, Fy (N), and the candidates' load (total-consistent)
  double direct_fn_N = 0.0, direct_fx_N = 0.0, direct_fy_N = 0.0, direct_candidate_load_N = 0.0;
};

struct ContactLutCheckResult {
  int samples = 0;                // random poses drawn
  int single_topology = 0;        // samples in single-topology cells (both solves Ok)
  int single_topology_mismatch = 0;  // ... where the direct topology still differs (a sub-cell patch the grid missed)
  int jump_samples = 0;           // samples in cells with a topology change (both Ok)
  int jump_same_topology = 0;     // ... LUT and direct agree
  int jump_within_one_step = 0;   // ... differ, but the direct topology is one of the cell's corners
  int jump_outside = 0;           // ... the direct topology is at no corner
  int status_mismatch = 0;        // one of the two not Ok (the other Ok)
  int both_failed = 0;            // neither Ok
  int lut_errors = 0;             // EvaluateContactLut threw (counted in status_mismatch or both_failed too)
  // Away from jumps, per patch (see the header comment)
  Percentiles normal_force_rel, fx_rel, fy_rel, rail_y_m;
  // Wheel totals away from jumps: |d vertical force|, |d lateral force| / Q
  Percentiles lateral_force_rel;
  double direct_cpu_s = 0.0, lut_cpu_s = 0.0;  // summed per-sample solve times, s
  std::vector<ContactLutCheckSample> sample_records;  // every pose, in the order drawn
};

ContactLutCheckResult CheckContactLut(const ContactLut& lut, const WheelsetTrackGeometry& geometry,
                                      const ContactLutCheckOptions& options);

// result.sample_records as CSV, one row per pose: side, y_mm, yaw_mrad, load_kN, category, lut_error,
// patches_direct, patches_lut, fn_rel_pct, fx_rel_pct, fy_rel_pct, rail_y_mm, lateral_rel_pct (empty where not a
// single-topology sample), direct_fn_kN, direct_fx_kN, direct_fy_kN, direct_candidate_load_kN.
void WriteContactLutCheckSamplesCsv(std::ostream& out, const ContactLutCheckResult& result);

}  // namespace conforma
