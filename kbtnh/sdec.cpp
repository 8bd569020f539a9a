// SDEC reduction of a strip patch (paper 003 §4.2; the measurement of W1, W2, W3 is documented in sdec.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/sdec.hpp"

namespace conforma {

const char* to_string(SdecStatus status) {
  switch (status) {
    case SdecStatus::Ok: return "ok";
    case SdecStatus::NoContact: return "no_contact";
  }
  return "unknown";
}

SdecResult ReduceToSdec(const std::vector<SdecStrip>& strips, const Material& material) {
  material.validate();
  SdecResult r;
  int first = -1, last = -1, longest = -1;
  for (size_t j = 0; j < strips.size(); ++j) {
    const SdecStrip& s = strips[j];
    if (!std::isfinite(s.s_m) || !std::isfinite(s.x_centre_m) || !std::isfinite(s.ds_m) || s.ds_m < 0.0 ||
        !std::isfinite(s.half_length_m) || s.half_length_m < 0.0)
      throw InputError("ReduceToSdec: strip " + std::to_string(j) + " has a NaN or negative width/half-length");
    if (s.half_length_m <= 0.0 || s.ds_m <= 0.0) continue;
    if (first < 0) first = static_cast<int>(j);
    last = static_cast<int>(j);
    r.area_m2 += 2.0 * s.half_length_m * s.ds_m;  // A_c
    if (longest < 0 || s.half_length_m > strips[longest].half_length_m) longest = static_cast<int>(j);
  }
  if (longest < 0) return r;  // NoContact
  // Longest strip line s* and c_max: vertex of the parabola through the longest strip and its neighbours.
  double s_star = strips[longest].s_m, c_max = strips[longest].half_length_m;
  r.longest_strip_x_m = strips[longest].x_centre_m;
  if (longest > first && longest < last) {
    const SdecStrip& m = strips[longest - 1];
    const SdecStrip& c = strips[longest];
    const SdecStrip& p = strips[longest + 1];
    const double h1 = c.s_m - m.s_m, h2 = p.s_m - c.s_m;
    if (h1 > 0.0 && h2 > 0.0 && m.half_length_m > 0.0 && p.half_length_m > 0.0) {
      // c(s) = c0 + d1 (s - s_c) + d2 (s - s_c)^2 through the three points.
      const double d_minus = (c.half_length_m - m.half_length_m) / h1, d_plus = (p.half_length_m - c.half_length_m) / h2;
      const double d2 = (d_plus - d_minus) / (h1 + h2);
      const double d1 = d_minus + d2 * h1;
      if (d2 < 0.0) {
        const double shift = std::max(-h1, std::min(h2, -d1 / (2.0 * d2)));
        s_star = c.s_m + shift;
        c_max = c.half_length_m + d1 * shift + d2 * shift * shift;
      }
    }
  }
  const double s_lo = strips[first].s_m - 0.5 * strips[first].ds_m;
  const double s_hi = strips[last].s_m + 0.5 * strips[last].ds_m;
  r.longest_strip_s_m = s_star;
  r.w1_m = std::max(0.0, s_star - s_lo);
  r.w2_m = std::max(0.0, s_hi - s_star);
  r.w3_m = 2.0 * c_max;
  const double width = r.w1_m + r.w2_m;
  r.a_m = std::sqrt(r.area_m2 / M_PI * r.w3_m / width);  // paper 003 §4.2
  r.b_m = std::sqrt(r.area_m2 / M_PI * width / r.w3_m);
  r.b_neg_m = 2.0 * r.b_m * r.w1_m / width;
  r.b_pos_m = 2.0 * r.b_m * r.w2_m / width;
  r.asymmetry = (r.b_pos_m - r.b_neg_m) / (2.0 * r.b_m);
  r.centroid_s_m = s_star + 2.0 * (r.b_pos_m * r.b_pos_m - r.b_neg_m * r.b_neg_m) / (3.0 * M_PI * r.b_m);
  r.coefficients = KalkerCoefficients(r.a_m / r.b_m, material.poisson_ratio);
  r.flexibilities = KalkerFlexibilities(r.a_m, r.b_m, r.coefficients, material.shear_modulus_Pa);
  r.status = SdecStatus::Ok;
  return r;
}

SdecResult ReduceToSdec(const KpResult& normal, const Material& material) {
  std::vector<SdecStrip> strips;
  strips.reserve(normal.strips.size());
  for (const KpStrip& k : normal.strips) strips.push_back({k.s_m, k.ds_m, k.x_centre_m, k.half_length_m});
  return ReduceToSdec(strips, material);
}

SdecLinearForces SdecLinearCreepForces(const SdecResult& sdec, const FastsimCreepages& creepages,
                                       double spin_centre_s_m, double shear_modulus_Pa) {
  require_positive(shear_modulus_Pa, "shear_modulus_Pa");
  SdecLinearForces f;
  if (sdec.status != SdecStatus::Ok) return f;
  const double c = std::sqrt(sdec.a_m * sdec.b_m), G = shear_modulus_Pa;
  const CreepCoefficients& C = sdec.coefficients;
  // docs/physics-reference.md §2.1 about the SDEC centroid; xi shifted by the spin's rigid slip there.
  f.fx_N = -G * c * c * C.c11 * (creepages.xi - creepages.phi_per_m * (sdec.centroid_s_m - spin_centre_s_m));
  f.fy_N = -G * c * c * C.c22 * creepages.eta - G * c * c * c * C.c23 * creepages.phi_per_m;
  return f;
}

}  // namespace conforma
