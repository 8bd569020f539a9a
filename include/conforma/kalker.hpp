#pragma once
// Kalker's creep coefficients C11, C22, C23 (and the unverified C33) of the linear rolling-contact theory
// (docs/physics-reference.md §2.1-2.2, Kalker 1990 Table E.3 as carried by CONTACT m_hertz.f90 `linrol`).
//
// Sign convention (Kalker; forces on body 1, the wheel; c = sqrt(a b)):
//     F_x = -G c^2 C11 xi
//     F_y = -G c^2 C22 eta - G c^3 C23 phi
//     M_z =  G c^3 C23 eta - G c^4 C33 phi
//
// Interpolation (documented choice, see src/kalker_coefficients.cpp):
//  * table rows g = 0.1 ... 1.0, g = min(a,b)/max(a,b), separate tables for a <= b and a > b;
//  * between rows, linear in g of the quantity that stays bounded as g -> 0:
//      a <= b: C11, C22, C23/sqrt(g) (C33: g C33);   a > b: g C11, g C22, g^1.5 C23
//    (the a > b choice is the "recommended improvement" of §2.2; CONTACT interpolates C linearly, which is
//    6-14 % off between g = 0.1 and 0.2). At the knots the table is reproduced exactly;
//  * g < 0.1: the asymptotes of §2.2 times a correction that goes linearly in g from 1 at g = 0 to
//    table/asymptote at g = 0.1, so the coefficients are continuous at g = 0.1 and exact as g -> 0;
//  * Poisson ratio: 1/C interpolated as a quadratic (Lagrange) through nu = 0, 0.25, 0.5 (CONTACT).
//  * the table value C23(g = 0.8, nu = 0.25, a <= b) is 1.25 (CONTACT's usetab_table.f90 has the typo 1.15).
// C33: only a recalled [MEM] table for a <= b exists (§2.2). It is returned with c33_verified = false for
// a <= b; for a > b c33_available = false and c33 = 0. Do not base results on C33 until it is checked
// against Kalker (1990) Table E.3.

namespace conforma {

struct CreepCoefficients {
  double c11 = 0.0;  // C11, longitudinal (dimensionless, > 0)
  double c22 = 0.0;  // C22, lateral (dimensionless, > 0)
  double c23 = 0.0;  // C23 = -C32, lateral-spin coupling (dimensionless, > 0)
  double c33 = 0.0;  // C33, spin moment (dimensionless); 0 when !c33_available, unverified otherwise
  bool c33_verified = false;   // always false: the C33 values are recalled, not checked against the source
  bool c33_available = false;  // false for a > b (no value recalled)
};

// a_over_b > 0 (a along the rolling direction), poisson_ratio in [0, 0.5]. Throws InputError otherwise.
CreepCoefficients KalkerCoefficients(double a_over_b, double poisson_ratio);

}  // namespace conforma
