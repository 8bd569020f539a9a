// Polach's analytic creep force with spin (Polach 1999, VSD 33 suppl.:728-739) and the slope reductions of Polach 2005
// (Wear 258:992-1000); formulas, the s_yC switch and their sources: docs/physics-reference.md §7.3.
// Polach writes the forces along the creepage; here they are the forces on the wheel (Kalker's sign, fastsim.hpp), so
// every Polach force appears with a minus sign (his K_M <= 0 makes his F_yS carry the sign of psi).
#include "conforma/polach_creep_force.hpp"

#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/kalker.hpp"

namespace conforma {

namespace {

constexpr double kPi = 3.14159265358979323846;

// x / (1 + x^2) for x >= 0 without overflow of x^2.
double AdhesionShape(double x) { return x < 1.0 ? x / (1.0 + x * x) : 1.0 / (x + 1.0 / x); }

// Polach's spin factor K_M(eps_psi) (§7.3), written with u = 1 - delta = 2/(1 + eps^2) so that nothing cancels:
//   delta^3/3 - delta^2/2 + 1/6 = u^2 (1/2 - u/3),   1 - delta^2 = u (2 - u).
// K_M = -(2/3) eps + (4/3) eps^3 + O(eps^5) for small eps, -> -2/(3 eps^3) for large eps; K_M <= 0.
double SpinFactor(double eps) {
  if (!(eps < 1e100)) return 0.0;  // the limit (|K_M| < 1e-300 there)
  const double u = 2.0 / (1.0 + eps * eps);
  const double t = u * (2.0 - u);
  return eps * u * u * (0.5 - u / 3.0) - t * std::sqrt(t) / 3.0;
}

}  // namespace

namespace {

// given: Kalker's coefficients of the input's ellipse, or null to compute them here
PolachResult Solve(const PolachInput& input, const CreepCoefficients* given) {
  require_positive(input.a_m, "Polach a_m");
  require_positive(input.b_m, "Polach b_m");
  require_positive(input.normal_force_N, "Polach normal_force_N");
  require_positive(input.friction_coefficient, "Polach friction_coefficient");
  require_positive(input.adhesion_reduction, "Polach adhesion_reduction (k_A)");
  require_positive(input.slip_reduction, "Polach slip_reduction (k_S)");
  // Polach 2005's range k_S <= k_A <= 1; it keeps |F| < mu N (with k_S > k_A, F exceeds mu N at large creepage)
  if (input.slip_reduction > input.adhesion_reduction || input.adhesion_reduction > 1.0) {
    throw InputError("Polach: the reductions must satisfy 0 < slip_reduction (k_S) <= adhesion_reduction (k_A) <= 1, got "
                     "k_S = " + MessageNumber(input.slip_reduction) + ", k_A = " +
                     MessageNumber(input.adhesion_reduction));
  }
  require_finite(input.creepages.xi, "Polach creepages.xi");
  require_finite(input.creepages.eta, "Polach creepages.eta");
  require_finite(input.creepages.phi_per_m, "Polach creepages.phi_per_m");
  input.material.validate();

  PolachResult r;
  const double sx = input.creepages.xi, sy = input.creepages.eta, psi = input.creepages.phi_per_m;
  r.zero_creepage = sx == 0.0 && sy == 0.0 && psi == 0.0;
  if (r.zero_creepage) return r;

  const double a = input.a_m, b = input.b_m, Q = input.normal_force_N, f = input.friction_coefficient;
  const double G = input.material.shear_modulus_Pa;
  // Resultant creepage with spin (Polach 1999; the switch as in Spiryagin, Polach & Cole 2013 and CONTACT's
  // m_solvpt.f90 fastsim_params, §7.3): the spin counts only where it adds to the lateral creepage.
  //   s_yC = s_y + psi a if |s_y + psi a| > |s_y|, else s_y;   s_C = sqrt(s_x^2 + s_yC^2)
  const double sy_with_spin = sy + psi * a;
  const double syc = std::abs(sy_with_spin) > std::abs(sy) ? sy_with_spin : sy;
  const double sc = std::hypot(sx, syc);
  if (!(sc > 0.0)) return r;  // only when psi a underflows to 0 with s_x = s_y = 0: the forces underflow too

  const CreepCoefficients c = given ? *given : KalkerCoefficients(a / b, input.material.poisson_ratio);
  const double s = std::hypot(sx, sy);
  double force = 0.0;  // Polach's F >= 0, the creep force of s_x, s_y (no spin part), along the creepage
  if (s > 0.0) {
    // Polach 1999: C_jj = sqrt((C11 s_x/s)^2 + (C22 s_y/s)^2), eps = pi G a b C_jj s_C / (4 Q f)   (§7.3)
    const double cjj = std::hypot(c.c11 * sx / s, c.c22 * sy / s);
    const double eps = kPi * G * a * b * cjj * sc / (4.0 * Q * f);
    r.stress_gradient_eps = eps;
    // Polach 2005: F = (2 Q f / pi) [k_A eps / (1 + (k_A eps)^2) + arctan(k_S eps)]; k_A = k_S = 1 is the 1999 form
    force = 2.0 * Q * f / kPi *
            (AdhesionShape(input.adhesion_reduction * eps) + std::atan(input.slip_reduction * eps));
  }
  // Polach 1999: F_x = F s_x / s_C, F_y = F s_y / s_C + F_yS (along the creepage; on the wheel with a minus sign)
  r.fx_N = -force * sx / sc;
  r.fy_N = -force * sy / sc;
  if (psi != 0.0) {
    // Polach 1999 spin part (§7.3): K_S = 1 + 6.3 (1 - e^{-a/b}),
    //   eps_psi = 8 b sqrt(a b) G C23 |s_yC| / (3 K_S Q f),  F_yS = -(9/16) a Q f K_M K_S psi / s_C (along the creepage)
    const double ks = 1.0 + 6.3 * (1.0 - std::exp(-a / b));
    const double eps_psi = 8.0 * b * std::sqrt(a * b) * G * c.c23 * std::abs(syc) / (3.0 * ks * Q * f);
    r.fy_N += 9.0 / 16.0 * a * Q * f * SpinFactor(eps_psi) * ks * psi / sc;
  }
  r.frictional_power_per_speed_N = -(r.fx_N * sx + r.fy_N * sy);
  return r;
}

}  // namespace

PolachResult SolvePolachCreepForce(const PolachInput& input) { return Solve(input, nullptr); }

PolachResult SolvePolachCreepForce(const PolachInput& input, const CreepCoefficients& coefficients) {
  return Solve(input, &coefficients);
}

}  // namespace conforma
