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

// KpPressureRule::StripCollocation (docs/physics-reference.md §5.3): the strips' peak pressures (Pa) that satisfy the
// contact condition at every strip's centre line point; strips with a non-positive amplitude carry none. unconstrained:
// the amplitudes of the first solve, before any strip was dropped (negative where the strip would pull). False when no
// positive solution exists (every amplitude dropped, or a singular system).
bool CollocateStripPeaks(const PatchInterpolant& patch, const std::vector<KpStrip>& strips, double delta,
                         const ElasticConstants& elastic, bool blanco, double coupling_K, std::vector<double>& peaks,
                         std::vector<double>& unconstrained);

}  // namespace kp_detail
}  // namespace conforma
