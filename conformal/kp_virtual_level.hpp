#pragma once
// Private to the KP solvers: KPEC's virtual penetration level eps(s) delta (docs/physics-reference.md §3.3): the
// equivalent ellipse of the eps = 0.5 region and, where the gap has separate wells, one ellipse per well.
#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "conforma/material.hpp"
#include "kp_patch_interpolant.hpp"

namespace conforma {
namespace kp_detail {

// KPEC's equivalent ellipses: eps(s) = clamp((a^2 A - spread t^2) / delta, 0, 1), t = (s - s_mid) / b (§3.3 step 3)
// Each well of the gap is such an ellipse of its own (bottom gap g_k, approach delta_k = delta - g_k): its virtual
// level is g_k + weight eps_k(s) delta_k inside its valley where eps_k > 0, none (0) elsewhere. The main well (the
// contact point, g = 0) has approach delta.
struct EquivalentEllipse {
  double s_mid = 0.0, a_squared_A = 0.0, spread = 0.0, b = 1.0;
  double bottom_gap = 0.0, weight = 1.0;
  double valley_low = -std::numeric_limits<double>::infinity(), valley_high = std::numeric_limits<double>::infinity();
  // The main well beyond the crest of a well of weight w < 1 (outwards on either side): its level times the
  // product of (1 - w) of the crests passed, (crest s, that product) in order outwards (§3.3 "wells")
  std::vector<std::pair<double, double>> fade_low, fade_high;
  double eps(double s, double approach) const {
    const double t = (s - s_mid) / b;
    return std::clamp((a_squared_A - spread * t * t) / approach, 0.0, 1.0);
  }
  double level(double s, double delta) const {
    if (s < valley_low || s > valley_high) return 0.0;
    const double e = eps(s, delta - bottom_gap);
    if (!(e > 0.0)) return 0.0;
    double factor = weight;
    for (const auto& f : fade_low)
      if (s < f.first) factor = weight * f.second;
    for (const auto& f : fade_high)
      if (s > f.first) factor = weight * f.second;
    return bottom_gap + factor * e * (delta - bottom_gap);
  }
};

// The virtual level of KPEC at approach delta: the combined ellipse, blended with the separate wells' levels.
struct KpecVirtualLevel {
  EquivalentEllipse combined;            // one ellipse over every lobe of the eps = 0.5 region
  std::vector<EquivalentEllipse> wells;  // one per well, the main one first, when the wells are separate contacts
  double separation_weight = 0.0;        // 0: the combined ellipse, 1: the separate wells, blended between
  // eps(s) delta at s (the virtual interpenetration is this minus the gap)
  double Level(double s, double delta) const {
    double level = combined.eps(s, delta) * delta;
    if (separation_weight > 0.0) {
      double level_separate = 0.0;
      for (const EquivalentEllipse& e : wells) level_separate = std::max(level_separate, e.level(s, delta));
      level = (1.0 - separation_weight) * level + separation_weight * level_separate;
    }
    return level;
  }
};

enum class KpecBuild {
  Ok,
  NoRegion,   // no eps = 0.5 region at the contact point (delta / 2 <= its gap): no contact
  NoEllipse,  // the equivalent Hertz problem of the region has no solution (KpStatus::NoEquivalentEllipse)
};

// KPEC steps 2-3 on the patch at approach delta > 0, the contact point (smallest gap) at s_contact.
KpecBuild BuildKpecVirtualLevel(const PatchInterpolant& patch, double delta, double s_contact, const Material& material,
                                KpecVirtualLevel* virtual_level);

}  // namespace kp_detail
}  // namespace conforma
