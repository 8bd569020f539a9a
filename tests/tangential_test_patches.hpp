#pragma once
// Strip patches for the tangential tests and benchmark: an exactly elliptic KP-like strip set.
#include <cmath>

#include "conforma/kik_piotrowski.hpp"

namespace conforma {
namespace tangential_test {

// Ellipse a (x) by b (s), load N: ny strips of equal width over [-b, b], c_j = a sqrt(1 - s_j^2/b^2), Hertz
// pressure peak_j = (3N / (2 pi a b)) sqrt(1 - s_j^2/b^2), normals all at alpha (0: flat).
inline KpResult EllipticStrips(double a, double b, double N, int ny, double alpha = 0.0) {
  KpResult r;
  r.status = KpStatus::Ok;
  const double ds = 2.0 * b / ny, p0 = 3.0 * N / (2.0 * M_PI * a * b);
  for (int j = 0; j < ny; ++j) {
    KpStrip k;
    k.s_m = -b + (j + 0.5) * ds;
    k.ds_m = ds;
    const double q = std::sqrt(1.0 - (k.s_m / b) * (k.s_m / b));
    k.half_length_m = a * q;
    k.peak_pressure_Pa = p0 * q;
    k.alpha_rad = alpha;
    k.position_m = Eigen::Vector2d(k.s_m * std::cos(alpha), -k.s_m * std::sin(alpha));  // on the tilted plane
    k.force_N = 0.5 * M_PI * k.peak_pressure_Pa * k.half_length_m * ds;
    r.fn_N += k.force_N;
    r.strips.push_back(k);
  }
  r.s_min_m = -b;
  r.s_max_m = b;
  return r;
}

}  // namespace tangential_test
}  // namespace conforma
