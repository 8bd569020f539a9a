// Load control of the KP solvers (physics-reference §3.2 "force-controlled use").
#include "conforma/load_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(LoadControlStatus status) {
  switch (status) {
    case LoadControlStatus::Ok: return "ok";
    case LoadControlStatus::NoContact: return "no_contact";
    case LoadControlStatus::NotConverged: return "not_converged";
  }
  return "unknown";
}

namespace {
void ValidatePatches(const std::vector<WheelPatch>& patches) {
  if (patches.empty()) throw InputError("wheel patches: at least one patch is needed");
  for (size_t k = 0; k < patches.size(); ++k) {
    const std::string where = "wheel patch " + std::to_string(k);
    if (patches[k].geometry == nullptr) throw InputError(where + ": geometry is null");
    require_non_negative(patches[k].gap_offset_m, (where + ".gap_offset_m").c_str());
    require_finite(patches[k].load_weight, (where + ".load_weight").c_str());
  }
}
double SmallestOffset(const std::vector<WheelPatch>& patches) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const WheelPatch& patch : patches) smallest = std::min(smallest, patch.gap_offset_m);
  return smallest;
}
}  // namespace

WheelNormalResult SolveWheelForApproach(const std::vector<WheelPatch>& patches, double approach_m,
                                        const KpOptions& options) {
  ValidatePatches(patches);
  require_non_negative(approach_m, "approach_m");
  WheelNormalResult result;
  result.approach_m = approach_m;
  result.patches.reserve(patches.size());
  bool touching = false;
  for (const WheelPatch& patch : patches) {
    const double own_approach = std::max(approach_m - patch.gap_offset_m, 0.0);
    result.patches.push_back(SolveKikPiotrowskiForApproach(*patch.geometry, own_approach, options));
    result.load_N += patch.load_weight * result.patches.back().fn_N;
    touching = touching || result.patches.back().fn_N > 0.0;
  }
  result.evaluations = 1;
  result.status = touching ? LoadControlStatus::Ok : LoadControlStatus::NoContact;
  return result;
}

WheelNormalResult SolveWheelForLoad(const std::vector<WheelPatch>& patches, double load_N,
                                    const LoadControlOptions& options) {
  ValidatePatches(patches);
  require_non_negative(load_N, "load_N");
  require_positive(options.relative_tolerance, "LoadControlOptions.relative_tolerance");
  require_positive(options.initial_approach_m, "LoadControlOptions.initial_approach_m");
  if (options.max_iterations < 1) throw InputError("LoadControlOptions.max_iterations must be >= 1");
  const double first_touch = SmallestOffset(patches);
  if (load_N == 0.0) {
    WheelNormalResult none = SolveWheelForApproach(patches, first_touch, options.kp);
    none.status = LoadControlStatus::NoContact;
    return none;
  }
  int evaluations = 0;
  auto evaluate = [&](double approach) {
    ++evaluations;
    return SolveWheelForApproach(patches, approach, options.kp);
  };
  // Bracket [low, high] with load(low) < target <= load(high); the step predicts with load ~ (delta - delta_1)^1.5.
  double low = first_touch, high = std::numeric_limits<double>::infinity();
  double approach = first_touch + options.initial_approach_m;
  WheelNormalResult current = evaluate(approach);
  double previous_approach = 0.0, previous_load = 0.0, previous_root = 0.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const double load = current.load_N;
    if (std::abs(load - load_N) <= options.relative_tolerance * load_N) {
      current.status = LoadControlStatus::Ok;
      current.evaluations = evaluations;
      return current;
    }
    if (load < load_N) low = std::max(low, approach); else high = std::min(high, approach);
    // A bracket collapsed to rounding level: accept when the load is within a looser 1e-6 (rounding in N(delta)).
    if (std::isfinite(high) && high - low <= 1e-13 * high) {
      current.status = std::abs(load - load_N) <= std::max(1e-6, options.relative_tolerance) * load_N
                           ? LoadControlStatus::Ok
                           : LoadControlStatus::NotConverged;
      current.evaluations = evaluations;
      return current;
    }
    // Secant on load^(2/3), which is linear in delta for a quadratic gap; from one point, the power law itself.
    const double target_root = std::cbrt(load_N * load_N);
    const double root = std::cbrt(load * load);
    double next;
    if (load > 0.0 && previous_load > 0.0 && root != previous_root) {
      next = approach + (target_root - root) * (approach - previous_approach) / (root - previous_root);
    } else if (load > 0.0) {
      next = first_touch + (approach - first_touch) * target_root / root;
    } else {
      next = first_touch + 4.0 * (approach - first_touch);
    }
    previous_approach = approach;
    previous_load = load;
    previous_root = root;
    if (!(next > low && next < high)) next = std::isfinite(high) ? 0.5 * (low + high) : first_touch + 4.0 * (low - first_touch);
    if (next == approach) break;
    approach = next;
    current = evaluate(approach);
  }
  current.status = LoadControlStatus::NotConverged;
  current.evaluations = evaluations;
  return current;
}

KpResult SolveKikPiotrowskiForLoad(const PatchGeometry& patch, double load_N, const LoadControlOptions& options) {
  const WheelNormalResult wheel = SolveWheelForLoad({WheelPatch{&patch, 0.0, 1.0}}, load_N, options);
  return wheel.patches.front();
}

}  // namespace conforma
