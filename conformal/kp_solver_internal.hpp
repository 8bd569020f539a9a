#pragma once
// Private to the KP solvers: the approach-given solve on a prepared PatchInterpolant, so that load control builds
// (and validates) each patch's interpolant once for all its iterations instead of once per solve.
#include "conforma/kik_piotrowski.hpp"
#include <vector>

#include "conforma/influence.hpp"
#include "kp_patch_interpolant.hpp"

namespace conforma {
namespace kp_detail {

// InputError for out-of-range KpOptions (the checks of SolveKikPiotrowskiForApproach).
void ValidateKpOptions(const KpOptions& options);

// SolveKikPiotrowskiForApproach on an interpolant of the patch; options already validated, approach >= 0.
KpResult SolveKikPiotrowskiOnInterpolant(const PatchInterpolant& patch, double approach_m, const KpOptions& options);

}  // namespace kp_detail
}  // namespace conforma
