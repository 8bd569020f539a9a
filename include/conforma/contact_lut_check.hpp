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
};

ContactLutCheckResult CheckContactLut(const ContactLut& lut, const WheelsetTrackGeometry& geometry,
                                      const ContactLutCheckOptions& options);

}  // namespace conforma
