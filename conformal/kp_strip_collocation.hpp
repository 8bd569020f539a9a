#pragma once
// Private to the KP solvers: the strip-collocation pressure rule (KpPressureRule::StripCollocation,
// docs/physics-reference.md §5.3): the strips' peak pressures from the contact condition collocated on coarse strips.
#include <functional>
#include <utility>
#include <vector>

#include "conforma/influence.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "kp_patch_interpolant.hpp"
#include "kp_ranges.hpp"

namespace conforma {
namespace kp_detail {

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

// Lays strips on the given (low, high) edges, each with its virtual half-length at its centre line.
using StripLayer = std::function<std::vector<KpStrip>(const std::vector<std::pair<double, double>>&)>;

// The strips' peak pressures by collocation on `collocation_strips` coarse strips per lobe (the strips themselves when
// that is >= per_lobe), their ratio P / c interpolated onto the strips; the contact range cut where the collocated
// amplitude vanishes (then *range and *strips are the strips laid anew over the cut lobes, per_lobe each). strips:
// laid by strips_on over `lobes` (per_lobe each); peaks: one per strip on return. False: no positive collocation
// (KpStatus::InfluenceNotPositive).
bool CollocateStripPressure(const PatchInterpolant& patch, const std::vector<ContactRange>& lobes, int per_lobe,
                            int collocation_strips, const StripLayer& strips_on, double delta,
                            const ElasticConstants& elastic, bool blanco, double coupling_K, ContactRange* range,
                            std::vector<KpStrip>* strips, std::vector<double>* peaks);

}  // namespace kp_detail
}  // namespace conforma
