#pragma once
// Patch builders shared by the KP tests and the KP benchmark.
#include <cmath>

#include "conforma/hertz.hpp"
#include "conforma/patch.hpp"

namespace conforma {
namespace kp_test {

// Hertzian patch: gap = B s^2, A constant, alpha = 0, strips over [-half_range, half_range].
inline PatchGeometry HertzianPatch(double A, double B, double half_range_m, int strips) {
  PatchGeometry patch;
  patch.ds_m = 2.0 * half_range_m / (strips - 1);
  for (int j = 0; j < strips; ++j) {
    const double s = -half_range_m + j * patch.ds_m;
    patch.s_m.push_back(s);
    patch.gap_m.push_back(B * s * s);
    patch.longitudinal_curvature_per_m.push_back(A);
    patch.wheel_radius_m.push_back(0.5 / A);
    patch.alpha_rad.push_back(0.0);
    patch.x_offset_m.push_back(0.0);
  }
  return patch;
}

// A and B with Hertz semi-axis ratio a/b = ratio and A + B = curvature_sum (bisection on log(A/B)).
struct Curvatures {
  double A = 0.0;
  double B = 0.0;
};
inline Curvatures CurvaturesForRatio(double ratio, double curvature_sum, const Material& material) {
  double low = -12.0, high = 12.0;  // log(A/B); a/b decreases as A/B grows
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    const double q = std::exp(mid);
    const HertzResult h = SolveHertzForLoad(curvature_sum * q / (1 + q), curvature_sum / (1 + q), 1.0e4, material);
    if (h.a_m / h.b_m > ratio) low = mid; else high = mid;
  }
  const double q = std::exp(0.5 * (low + high));
  return {curvature_sum * q / (1 + q), curvature_sum / (1 + q)};
}

// Circular wheel (profile radius R_w) in a circular groove (R_g > R_w), rolling radius r0 at the groove bottom
// (CONTACT groove case, docs/data.md). Gap along the groove normal vs groove arc length s, alpha = -s/R_g (the
// outward rail normal of a concave groove turns towards -s, patch.hpp convention), A = cos(alpha) / (2 r(s)).
inline PatchGeometry GroovePatch(double wheel_radius_m, double groove_radius_m, double rolling_radius_m,
                                 double half_range_m, int strips) {
  PatchGeometry patch;
  patch.ds_m = 2.0 * half_range_m / (strips - 1);
  const double e = groove_radius_m - wheel_radius_m;  // centre distance
  for (int j = 0; j < strips; ++j) {
    const double s = -half_range_m + j * patch.ds_m;
    const double theta = s / groove_radius_m;
    // Ray from the groove point towards the groove centre hits the wheel circle at radius rho from that centre.
    const double rho = e * std::cos(theta) + std::sqrt(wheel_radius_m * wheel_radius_m -
                                                        e * e * std::sin(theta) * std::sin(theta));
    const double height = groove_radius_m - rho * std::cos(theta);  // wheel point above the groove bottom
    const double r = rolling_radius_m - height;
    patch.s_m.push_back(s);
    patch.gap_m.push_back(groove_radius_m - rho);
    patch.wheel_radius_m.push_back(r);
    patch.longitudinal_curvature_per_m.push_back(std::cos(theta) / (2.0 * r));
    patch.alpha_rad.push_back(-theta);
    patch.x_offset_m.push_back(0.0);
  }
  return patch;
}

}  // namespace kp_test
}  // namespace conforma
