#pragma once
// Hertz elliptical contact, exact solution with complete elliptic integrals (physics-reference §1.2).
// Gap h(x, y) = A x^2 + B y^2 with x the rolling direction, y lateral; a is the semi-axis along x,
// b along y. Both bodies share one Material (E* = G / (1 - nu)).
#include "conforma/material.hpp"

namespace conforma {

enum class HertzStatus {
  Ok,
  NoSolution,  // A <= 0 or B <= 0: conformal or two-point contact, a non-Hertzian model is required
  NoContact,   // zero load / zero approach
};
const char* to_string(HertzStatus status);

struct HertzResult {
  HertzStatus status = HertzStatus::NoSolution;
  double a_m = 0.0;             // semi-axis along x (rolling)
  double b_m = 0.0;             // semi-axis along y (lateral)
  double p0_Pa = 0.0;           // maximum pressure 3N / (2 pi a b)
  double approach_m = 0.0;      // rigid approach delta
  double normal_force_N = 0.0;  // N
  double stiffness_N_per_m15 = 0.0;  // C_H in N = C_H delta^(3/2)
};

// Load given: semi-axes, p0 and approach. Throws InputError for NaN or negative load / bad material.
HertzResult SolveHertzForLoad(double A_per_m, double B_per_m, double normal_force_N, const Material& material);
// Approach given (multibody penetration mode): load, semi-axes and p0.
HertzResult SolveHertzForApproach(double A_per_m, double B_per_m, double approach_m, const Material& material);

}  // namespace conforma
