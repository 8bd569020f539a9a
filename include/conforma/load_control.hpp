#pragma once
// Load control for the KP solvers: one wheel with one or more contact patches that share ONE rigid approach
// of the wheel. Each patch's gaps are relative to its own lowest point; gap_offset_m says how far that lowest
// point is from the wheel's first touching point, so patch k sees the approach delta - gap_offset_k
// (docs/physics-reference.md §3.2 "force-controlled use").
#include <vector>

#include "conforma/kik_piotrowski.hpp"
#include "conforma/patch.hpp"

namespace conforma {

struct WheelPatch {
  const PatchGeometry* geometry = nullptr;  // not owned; must outlive the call
  double gap_offset_m = 0.0;                // >= 0: extra approach before this patch touches
  // Weight of this patch's fn_N in the wheel load (e.g. the cosine of its contact angle to carry a vertical
  // load); 1 = the sum of the normal forces.
  double load_weight = 1.0;
};

enum class LoadControlStatus {
  Ok,
  NoContact,      // zero target load (or no patch can touch)
  NotConverged,   // iteration limit reached: the last iterate is returned
};
const char* to_string(LoadControlStatus status);

struct LoadControlOptions {
  KpOptions kp;
  double relative_tolerance = 1e-10;   // on the load
  int max_iterations = 60;
  double initial_approach_m = 1.0e-5;  // first guess (without hertz_initial_guess, or when that has no solution)
  // First guess from Hertz: the first-touching patch alone carries the load (divided by its load_weight), with the
  // curvatures A, B at its minimum-gap strip (B from the gaps of its neighbours). Saves about one KP solve per
  // load-controlled patch; the converged result is the same within relative_tolerance.
  bool hertz_initial_guess = true;
};

struct WheelNormalResult {
  LoadControlStatus status = LoadControlStatus::NoContact;
  double approach_m = 0.0;     // common rigid approach of the wheel
  double load_N = 0.0;         // sum of load_weight * fn_N
  int evaluations = 0;         // solver calls
  std::vector<KpResult> patches;  // one per WheelPatch, same order
};

// Plain mode: approach given -> forces of every patch.
WheelNormalResult SolveWheelForApproach(const std::vector<WheelPatch>& patches, double approach_m,
                                        const KpOptions& options);
// Load given: the approach at which the patches together carry load_N (sum of load_weight * fn_N). N(delta) is
// monotone; the iteration is a power-law secant (N ~ delta^1.5) safeguarded by a bracket.
WheelNormalResult SolveWheelForLoad(const std::vector<WheelPatch>& patches, double load_N,
                                    const LoadControlOptions& options);
// One patch, load given (convenience).
KpResult SolveKikPiotrowskiForLoad(const PatchGeometry& patch, double load_N, const LoadControlOptions& options);

}  // namespace conforma
