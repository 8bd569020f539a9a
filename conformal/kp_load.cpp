// Load-given mode of the KP solvers (kik_piotrowski.hpp): the one load control over the patch's approach.
#include <algorithm>
#include <cmath>
#include <limits>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/influence.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "kp_solver_internal.hpp"

namespace conforma {

namespace {

// Hertz approach of the patch carrying `load` alone; NaN without a Hertz solution (minimum at the end of the
// strips, B <= 0, ...).
double HertzApproachGuess(const PatchGeometry& geometry, double load, const Material& material) {
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
  if (!(A > 0.0 && B > 0.0 && std::isfinite(A) && std::isfinite(B))) return nan;
  const HertzResult hertz = SolveHertzForLoad(A, B, load, material);
  return hertz.status == HertzStatus::Ok && hertz.approach_m > 0.0 ? hertz.approach_m : nan;
}

}  // namespace

KpResult SolveKikPiotrowskiForLoad(const PatchGeometry& geometry, double load_N, const KpLoadOptions& options) {
  require_non_negative(load_N, "load_N");
  require_positive(options.relative_tolerance, "KpLoadOptions.relative_tolerance");
  require_positive(options.initial_approach_m, "KpLoadOptions.initial_approach_m");
  kp_detail::ValidateKpOptions(options.kp);
  (void)CombinedElasticConstants(options.kp.material);  // material errors before patch errors
  const kp_detail::PatchInterpolant patch(geometry);
  if (load_N == 0.0) return kp_detail::SolveKikPiotrowskiOnInterpolant(patch, 0.0, options.kp);
  double first_guess = options.initial_approach_m;
  if (options.hertz_initial_guess) {
    const double guess = HertzApproachGuess(geometry, load_N, options.kp.material);
    if (guess > 0.0) first_guess = guess;  // NaN: keep initial_approach_m
  }
  KpResult current;
  auto carried = [&](double push) {
    current = kp_detail::SolveKikPiotrowskiOnInterpolant(patch, std::max(first_guess + push, 0.0), options.kp);
    return current.fn_N;
  };
  const LoadControlResult load =
      SolveLoadControl(carried, load_N, first_guess, options.relative_tolerance, LoadResponse::HertzPower);
  // the last evaluation is at the solution's push; a missed load is a status, never a silent result
  if (load.status != LoadControlStatus::Ok && (current.status == KpStatus::Ok ||
                                               current.status == KpStatus::ContactAtPatchBoundary ||
                                               current.status == KpStatus::NoContact))
    current.status = KpStatus::LoadNotReached;
  return current;
}

}  // namespace conforma
