#pragma once
// Polach's analytic creep force for a pure longitudinal creepage, with the 2005 extension in which the slope reduction
// differs in the area of adhesion (k_A) and in the area of slip (k_S) (docs/physics-reference.md §7.3, §7.5):
//   eps = pi G a b C11 xi / (4 N mu)                                           (Polach 1999, §7.3)
//   F / N = (2 mu / pi) [k_A eps / (1 + (k_A eps)^2) + arctan(k_S eps)]         (Polach 2005, §7.3)
// Initial slope dF/dxi = (k_A + k_S)/2 G a b C11; k_A = k_S = 1 is Polach's 1999 model.

namespace conforma {

// -F_x / N for creepage xi >= 0; linear_slope_N = G a b C11 > 0 (unreduced), normal_force_N > 0, friction
// coefficient mu > 0, reductions 0 < k_S, 0 < k_A. InputError for a value out of range.
double PolachTractionCoefficient(double linear_slope_N, double normal_force_N, double adhesion_reduction,
                                 double slip_reduction, double friction_coefficient, double creepage);

}  // namespace conforma
