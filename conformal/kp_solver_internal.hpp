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

// Strip collocation at a steep lobe edge (docs/physics-reference.md §5.3): a strip whose virtual half-length is a
// small fraction of its lobe's largest has its contact condition blended with KP's rule "the ratio P / c equals the
// inward neighbour's": row = weight (contact condition) + (1 - weight) A_anchor (P / c - P_nb / c_nb) c, A_anchor
// the self-influence of the lobe's longest strip. weight 1: the contact condition alone (no neighbour needed).
struct CollocationEdgeTie {
  double weight = 1.0;
  int neighbour = -1;  // the adjacent strip towards the lobe's longest
  int anchor = -1;     // the lobe's longest strip
};

// KpPressureRule::StripCollocation (docs/physics-reference.md §5.3): the strips' peak pressures (Pa) that satisfy the
// contact condition at every strip's centre line point (blended with the neighbour's ratio where `ties` has a weight
// below 1; empty: none); strips with a non-positive amplitude carry none. unconstrained: the amplitudes of the first
// solve, before any strip was dropped (negative where the strip would pull). False when no positive solution exists
// (every amplitude dropped, or a singular system).
bool CollocateStripPeaks(const PatchInterpolant& patch, const std::vector<KpStrip>& strips,
                         const std::vector<CollocationEdgeTie>& ties, double delta, const ElasticConstants& elastic,
                         bool blanco, double coupling_K, std::vector<double>& peaks,
                         std::vector<double>& unconstrained);

}  // namespace kp_detail
}  // namespace conforma
