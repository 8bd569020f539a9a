// Complete elliptic integrals by the arithmetic-geometric mean (docs/physics-reference.md §1.2, "AGM
// implementation": K = pi / (2 AGM(1, g)), E = K (1 - sum 2^(n-1) c_n^2)). The sum itself is (K - E)/K, so
// K - E comes out without cancellation when g -> 1 (nearly circular contact).
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"

namespace conforma {

CompleteEllipticIntegrals EllipticIntegralsFromComplementaryModulus(double g) {
  if (!(g > 0.0 && g <= 1.0)) throw InputError("EllipticIntegralsFromComplementaryModulus: g must lie in (0, 1]");
  double a = 1.0;
  double b = g;
  double c = std::sqrt((1.0 - g) * (1.0 + g));  // modulus k
  double weighted_sum = 0.5 * c * c;            // sum_n 2^(n-1) c_n^2, n = 0 term
  double power = 0.5;
  for (int iteration = 0; iteration < 64 && c > 1e-17 * a; ++iteration) {
    const double a_next = 0.5 * (a + b);
    const double b_next = std::sqrt(a * b);
    c = 0.5 * (a - b);
    power *= 2.0;
    weighted_sum += power * c * c;
    a = a_next;
    b = b_next;
  }
  CompleteEllipticIntegrals out;
  out.K = M_PI / (2.0 * a);
  out.K_minus_E = out.K * weighted_sum;
  out.E = out.K - out.K_minus_E;
  return out;
}

}  // namespace conforma
