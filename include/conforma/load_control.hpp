#pragma once
// The one load control: the push of a contact (a wheel's vertical push, or one patch's approach) at which the load
// it carries equals a given load (docs/physics-reference.md §3.6). The carried load is a function of the push
// beyond a first guess (the Hertz push-down); it must increase with the push. The bracket is found by expanding
// from [-scale, 0.25 scale], then narrowed by the one root finder (root_finding.hpp). Used by the wheel pipeline
// (wheel_contact.hpp, every model and patch of a wheel together), the one patch solver (patch_solver.hpp) and the
// KP solver's load-given mode (kik_piotrowski.hpp).
#include <functional>

namespace conforma {

// Default relative load tolerance of a load-given contact solve (the one declaration; WheelContactOptions).
constexpr double kDefaultLoadTolerance = 1e-6;

enum class LoadControlStatus {
  Ok,            // |carried load - load| <= 10x the tolerance at push_m (the root finder's own stop is 1x)
  NoBracket,     // no push in the expansion range carries the load (e.g. no contact at all, or a model failure)
  NotConverged,  // the root finder stopped with a load error above 10x the tolerance: the last iterate is returned
};
const char* to_string(LoadControlStatus status);  // "ok", "no_bracket", "not_converged"

// With NoBracket every field is 0 (push_m is then not a solution).
// How the root is sought. Linear: on carried - load. HertzPower: on carried^(2/3) - load^(2/3), which is linear in
// the push for a Hertzian contact (N ~ delta^1.5, docs/physics-reference.md §1.2), so that false position lands
// on the root of a near-Hertzian patch in one or two steps; the tolerance is still on the load.
enum class LoadResponse { Linear, HertzPower };

struct LoadControlResult {
  LoadControlStatus status = LoadControlStatus::NoBracket;  // see LoadControlStatus
  double push_m = 0.0;      // m, beyond the first guess; carried_load was evaluated here last (Ok / NotConverged)
  double residual_N = 0.0;  // carried load - load at push_m, N
  int iterations = 0;       // root-finder evaluations (not counting the bracket's), >= 0
};

// carried_load(push) for push in metres beyond the first guess; scale_m (> 0) the size of the first bracket;
// tolerance: |carried - load| <= relative_tolerance * load. load_N > 0.
LoadControlResult SolveLoadControl(const std::function<double(double)>& carried_load, double load_N, double scale_m,
                                   double relative_tolerance, LoadResponse response = LoadResponse::Linear);

// Load control continued from a push where the carried load is already known (push 0 carries carried_at_zero_N),
// for an expensive carried_load (the wheel's total vertical force, docs/physics-reference.md §3.6.1): after the
// first step first_step_m (its sign turned towards the load), while the carried load has neither crossed the load
// nor come within the tolerance, the next push is the secant through the last two evaluations where it goes further
// the same way (at most 8 times, and not beyond the doubled step), else the step doubled, within |push| <= max_push_m
// (else NoBracket); a crossing is then narrowed by the one root finder. The secant and root-finder steps are taken
// on sign(F) |F|^(2/3) - load^(2/3) (linear in the push for a Hertzian contact, as LoadResponse::HertzPower), the
// tolerance on the carried load itself. carried_load must increase with the push on the bracket. iterations counts
// every evaluation (the bracket's too); if |carried_at_zero - load| is within the tolerance, push_m = 0 and no
// evaluation is made.
LoadControlResult SolveLoadControlFrom(const std::function<double(double)>& carried_load, double carried_at_zero_N,
                                       double load_N, double first_step_m, double max_push_m,
                                       double relative_tolerance);

}  // namespace conforma
