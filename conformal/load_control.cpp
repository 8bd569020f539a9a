// Load control of the KP solvers (docs/physics-reference.md §3.2 "force-controlled use").
#include "conforma/load_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/influence.hpp"
#include "kp_solver_internal.hpp"

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
// The x where load = C x^1.5 (1 + beta x) reaches `target`, C and beta through (x_a, load_a) and (x_b, load_b)
// (x > 0, loads > 0): load / x^1.5 is linear in x. Newton from the power-law step of the nearer point; NaN when the
// model has no root there (the caller's bracket then takes over).
double PowerLawSecantStep(double x_a, double load_a, double x_b, double load_b, double target) {
  if (!(x_a > 0.0 && x_b > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double y_a = load_a / (x_a * std::sqrt(x_a)), y_b = load_b / (x_b * std::sqrt(x_b));
  const double slope = (y_b - y_a) / (x_b - x_a);
  double x = x_b * std::cbrt(target * target / (load_b * load_b));
  for (int iteration = 0; iteration < 30; ++iteration) {
    const double root_x = std::sqrt(x);
    const double y = y_b + slope * (x - x_b);
    const double residual = y * x * root_x - target;
    const double derivative = slope * x * root_x + 1.5 * y * root_x;
    if (!(derivative > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    const double step = residual / derivative;
    x -= step;
    if (!(x > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (std::abs(step) <= 1e-15 * x) break;
  }
  return x;
}
// Hertz approach of one patch carrying `load` alone (LoadControlOptions::hertz_initial_guess); NaN without a
// Hertz solution (minimum at the end of the strips, B <= 0, ...).
double HertzApproachGuess(const WheelPatch& patch, double load, const Material& material) {
  const PatchGeometry& geometry = *patch.geometry;
  const std::vector<double>& g = geometry.gap_m;
  const std::vector<double>& s = geometry.s_m;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (g.size() < 3 || s.size() != g.size() || geometry.longitudinal_curvature_per_m.size() != g.size()) return nan;
  const size_t i = static_cast<size_t>(std::min_element(g.begin(), g.end()) - g.begin());
  if (i == 0 || i + 1 == g.size()) return nan;
  // B = g''/2 of the parabola through the three nodes (docs/physics-reference.md §1.1)
  const double left_slope = (g[i] - g[i - 1]) / (s[i] - s[i - 1]);
  const double right_slope = (g[i + 1] - g[i]) / (s[i + 1] - s[i]);
  const double B = (right_slope - left_slope) / (s[i + 1] - s[i - 1]);
  const double A = geometry.longitudinal_curvature_per_m[i];
  if (!(A > 0.0 && B > 0.0 && patch.load_weight > 0.0 && std::isfinite(A) && std::isfinite(B))) return nan;
  const HertzResult hertz = SolveHertzForLoad(A, B, load / patch.load_weight, material);
  return hertz.status == HertzStatus::Ok && hertz.approach_m > 0.0 ? hertz.approach_m : nan;
}

double SmallestOffset(const std::vector<WheelPatch>& patches) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const WheelPatch& patch : patches) smallest = std::min(smallest, patch.gap_offset_m);
  return smallest;
}

// Every patch at one wheel approach, on interpolants built once (kp_solver_internal.hpp); options validated.
WheelNormalResult SolveInterpolantsForApproach(const std::vector<WheelPatch>& patches,
                                               const std::vector<kp_detail::PatchInterpolant>& interpolants,
                                               double approach_m, const KpOptions& options) {
  WheelNormalResult result;
  result.approach_m = approach_m;
  result.patches.reserve(patches.size());
  bool touching = false;
  for (size_t k = 0; k < patches.size(); ++k) {
    const double own_approach = std::max(approach_m - patches[k].gap_offset_m, 0.0);
    result.patches.push_back(kp_detail::SolveKikPiotrowskiOnInterpolant(interpolants[k], own_approach, options));
    result.load_N += patches[k].load_weight * result.patches.back().fn_N;
    touching = touching || result.patches.back().fn_N > 0.0;
  }
  result.evaluations = 1;
  result.status = touching ? LoadControlStatus::Ok : LoadControlStatus::NoContact;
  return result;
}

// Options first, then the patches in order (the order of SolveKikPiotrowskiForApproach's checks).
std::vector<kp_detail::PatchInterpolant> PrepareInterpolants(const std::vector<WheelPatch>& patches,
                                                             const KpOptions& options) {
  kp_detail::ValidateKpOptions(options);
  (void)CombinedElasticConstants(options.material);
  std::vector<kp_detail::PatchInterpolant> interpolants;
  interpolants.reserve(patches.size());
  for (const WheelPatch& patch : patches) interpolants.emplace_back(*patch.geometry);
  return interpolants;
}

}  // namespace

WheelNormalResult SolveWheelForApproach(const std::vector<WheelPatch>& patches, double approach_m,
                                        const KpOptions& options) {
  ValidatePatches(patches);
  require_non_negative(approach_m, "approach_m");
  return SolveInterpolantsForApproach(patches, PrepareInterpolants(patches, options), approach_m, options);
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
  const std::vector<kp_detail::PatchInterpolant> interpolants = PrepareInterpolants(patches, options.kp);
  int evaluations = 0;
  auto evaluate = [&](double approach) {
    ++evaluations;
    return SolveInterpolantsForApproach(patches, interpolants, approach, options.kp);
  };
  // Bracket [low, high] with load(low) < target <= load(high); the step predicts with load ~ (delta - delta_1)^1.5.
  double low = first_touch, high = std::numeric_limits<double>::infinity();
  double approach = first_touch + options.initial_approach_m;
  if (options.hertz_initial_guess) {
    size_t first = 0;
    for (size_t k = 1; k < patches.size(); ++k)
      if (patches[k].gap_offset_m < patches[first].gap_offset_m) first = k;
    const double guess = HertzApproachGuess(patches[first], load_N, options.kp.material);
    if (guess > 0.0) approach = first_touch + guess;  // NaN: keep initial_approach_m
  }
  WheelNormalResult current = evaluate(approach);
  double previous_approach = 0.0, previous_load = 0.0;
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
    // Two points: secant on the power-law coefficient load / x^1.5 (x = delta - delta_1), i.e. the model
    // load = C x^1.5 (1 + beta x), exact for a quadratic gap (beta = 0) and first-order in the gap's departure from
    // it; one point: the power law itself.
    double next;
    if (load > 0.0 && previous_load > 0.0 && approach != previous_approach) {
      next = first_touch + PowerLawSecantStep(previous_approach - first_touch, previous_load, approach - first_touch,
                                              load, load_N);
    } else if (load > 0.0) {
      next = first_touch + (approach - first_touch) * std::cbrt(load_N * load_N / (load * load));
    } else {
      next = first_touch + 4.0 * (approach - first_touch);
    }
    previous_approach = approach;
    previous_load = load;
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
