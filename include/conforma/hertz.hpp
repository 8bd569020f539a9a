#pragma once
// Hertz elliptical contact, exact solution with complete elliptic integrals (docs/physics-reference.md §1.2).
// Gap h(x, y) = A x^2 + B y^2 with x the rolling direction, y lateral; a is the semi-axis along x,
// b along y. Both bodies share one Material (E* = G / (1 - nu)).
#include "conforma/material.hpp"

namespace conforma {

enum class HertzStatus {
  Ok,          // contact solved: every field of HertzResult filled
  NoSolution,  // A <= 0 or B <= 0: conformal or two-point contact, a non-Hertzian model is required
  NoContact,   // zero load / zero approach
};
const char* to_string(HertzStatus status);  // "ok", "no_solution", "no_contact"

// The Hertz solution (docs/physics-reference.md §1.2). With NoSolution every field is 0; with NoContact only a_over_b,
// elliptic_K and elliptic_E are set (the ellipse shape, which does not depend on the load), the rest is 0.
struct HertzResult {
  HertzStatus status = HertzStatus::NoSolution;  // see HertzStatus
  double a_m = 0.0;             // semi-axis along x (rolling), m; > 0 when Ok
  double b_m = 0.0;             // semi-axis along y (lateral), m; > 0 when Ok
  double p0_Pa = 0.0;           // maximum pressure 3N / (2 pi a b), Pa
  double approach_m = 0.0;      // rigid approach delta of the two bodies, m (the given one in SolveHertzForApproach)
  double normal_force_N = 0.0;  // normal load N, N (the given one in SolveHertzForLoad)
  double stiffness_N_per_m15 = 0.0;  // C_H in N = C_H delta^(3/2), N/m^1.5
  double a_over_b = 0.0;        // semi-axis ratio a/b (also set for NoContact when A, B > 0), > 0
  double elliptic_K = 0.0;      // K(k), k^2 = 1 - g^2, g = min(a,b)/max(a,b) (dimensionless)
  double elliptic_E = 0.0;      // E(k) (dimensionless)
};

// A_per_m, B_per_m: the gap h = A x^2 + B y^2 (1/m). Hertzian only when A > 0 and B > 0 (NoSolution otherwise).
// Load given (normal_force_N >= 0, N): semi-axes, p0 and approach. Throws InputError for NaN or negative load / bad
// material.
HertzResult SolveHertzForLoad(double A_per_m, double B_per_m, double normal_force_N, const Material& material);
// Approach given (approach_m >= 0, m; multibody penetration mode): load, semi-axes and p0. Throws as above.
HertzResult SolveHertzForApproach(double A_per_m, double B_per_m, double approach_m, const Material& material);

// Hertz pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) at (x, y); 0 outside the ellipse or without a solution.
double HertzPressure(const HertzResult& hertz, double x_m, double y_m);

// Complete elliptic integrals K(k), E(k) (modulus k, k^2 = 1 - g^2) from the complementary modulus g in (0, 1],
// by the arithmetic-geometric mean; also returns K - E accurately (no cancellation as g -> 1).
struct CompleteEllipticIntegrals {
  double K = 0.0;          // K(k), first kind
  double E = 0.0;          // E(k), second kind
  double K_minus_E = 0.0;  // K(k) - E(k), without cancellation
};
CompleteEllipticIntegrals EllipticIntegralsFromComplementaryModulus(double g);

}  // namespace conforma
