// Polach's analytic creep force with the 2005 slope reductions k_A, k_S (conforma/validation/roller_rig_polach.hpp,
// docs/physics-reference.md §7.3, §7.5).
#include "conforma/validation/roller_rig_polach.hpp"

#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

double PolachTractionCoefficient(double linear_slope_N, double normal_force_N, double adhesion_reduction,
                                 double slip_reduction, double friction_coefficient, double creepage) {
  require_positive(linear_slope_N, "Polach: linear slope G a b C11");
  require_positive(normal_force_N, "Polach: normal force");
  require_positive(adhesion_reduction, "Polach: k_A");
  require_positive(slip_reduction, "Polach: k_S");
  require_positive(friction_coefficient, "Polach: friction coefficient");
  require_non_negative(creepage, "Polach: creepage");
  constexpr double kPi = 3.14159265358979323846;
  // Polach 1999: eps = pi G a b C11 xi / (4 Q f) (docs/physics-reference.md §7.3)
  const double eps = kPi * linear_slope_N * creepage / (4.0 * normal_force_N * friction_coefficient);
  const double ea = adhesion_reduction * eps;
  // Polach 2005: F = (2 Q mu / pi) [k_A eps / (1 + (k_A eps)^2) + arctan(k_S eps)]
  return 2.0 * friction_coefficient / kPi * (ea / (1.0 + ea * ea) + std::atan(slip_reduction * eps));
}

}  // namespace conforma
