#pragma once
// Polach's analytic creep force with spin (Polach 1999, VSD 33 suppl.:728-739), with the slope reductions k_A, k_S of
// Polach 2005 (Wear 258:992-1000): a closed-form alternative to FASTSIM for the time-domain dynamics
// (docs/physics-reference.md §7.3, where the formulas, the s_yC switch and its sources, the tested limits and the
// differences to FASTSIM are given).
//
// Sign convention: that of fastsim.hpp and kalker.hpp (Kalker's, as CONTACT): forces ON BODY 1 (the wheel); for
// vanishing creepage and k_A = k_S = 1, with c = sqrt(a b),
//     pure xi:            F_x = -G c^2 C11 xi
//     pure eta:           F_y = -G c^2 C22 eta
//     pure phi:           F_y = -G c^3 C23 phi
//     xi = 0, any (eta, phi): F_y = -G c^2 C22 eta - G c^3 C23 phi   (Kalker's linear theory exactly)
// For combined xi and eta the 1999 form has one coefficient C_jj = sqrt((C11 xi/s)^2 + (C22 eta/s)^2) for both
// directions, and with xi != 0 the spin term is scaled by |s_yC|/s_C; these are the method's own linear limits
// (§7.3), not Kalker's. Polach gives no spin moment: mz_Nm is 0.
// |F| <= mu N for every creepage (to rounding); F -> mu N opposite to the creepage for large xi, eta; under pure spin
// F_y -> 0 for large spin (the traction turns around the patch centre).
//
// Cost: one KalkerCoefficients call, an exp, an atan and a few square roots; no allocation, no state. Thread-safe.
#include "conforma/fastsim.hpp"
#include "conforma/material.hpp"

namespace conforma {

// The Hertz ellipse, load, friction and creepages of one contact, as SolvePolachCreepForce takes them.
struct PolachInput {
  double a_m = 0.0;                   // semi-axis along x (rolling), m, > 0
  double b_m = 0.0;                   // semi-axis along y, m, > 0
  double normal_force_N = 0.0;        // normal load Q, N, > 0
  double friction_coefficient = 0.3;  // mu (Polach's f), > 0
  FastsimCreepages creepages;         // xi, eta (-), phi (1/m) in Kalker's convention (creepage.hpp), finite
  Material material;                  // G and nu: C11, C22, C23 from KalkerCoefficients(a/b, nu)
  double adhesion_reduction = 1.0;    // Polach 2005 k_A (slope reduction in the area of adhesion), (0, 1]; 1 = 1999
  double slip_reduction = 1.0;        // Polach 2005 k_S (slope reduction in the area of slip), (0, k_A]; 1 = 1999
};

// The creep forces of one contact (on the wheel, N) and the creep power per rolling speed.
struct PolachResult {
  double fx_N = 0.0;  // longitudinal creep force on the wheel, N
  double fy_N = 0.0;  // lateral creep force on the wheel (creepage part plus spin part F_yS), N
  double mz_Nm = 0.0;  // spin moment: always 0 (Polach's method gives none)
  // -(F_x xi + F_y eta), N: the creep power of the forces divided by the rolling speed (the T gamma of the wear
  // laws, §8.1). >= 0 whenever phi eta >= 0 (no spin, or spin adding to the lateral creepage); with spin against the
  // lateral creepage it can be negative, since the spin moment's share (-M_z phi) is not part of it.
  double frictional_power_per_speed_N = 0.0;
  // Polach's non-dimensional gradient of the tangential stress eps (§7.3 eq. of eps; k_A = k_S = 1). The adhesion
  // area shrinks as eps grows: eps = 0.1 -> |F| = 0.127 mu N, eps = 1 -> 0.82, eps = 10 -> 0.9996 (spin not included).
  double stress_gradient_eps = 0.0;
  // true when xi = eta = phi = 0: every field is exactly 0.
  bool zero_creepage = false;
};

// Polach's creep force (docs/physics-reference.md §7.3). InputError naming the field for a non-positive or non-finite
// a_m, b_m, normal_force_N, friction_coefficient, adhesion_reduction or slip_reduction, for reductions outside
// 0 < k_S <= k_A <= 1 (Polach 2005's range; k_S > k_A would let F exceed mu N), a non-finite creepage, or a material
// Material::validate rejects. The reductions scale the creep part only; the spin part F_yS is the 1999 form (§7.3).
PolachResult SolvePolachCreepForce(const PolachInput& input);
// The same with Kalker's coefficients of the input's ellipse already at hand (KalkerCoefficients(a_m / b_m,
// material.poisson_ratio)), for a caller that needs them too (the look-up table's centre shift): not computed twice.
PolachResult SolvePolachCreepForce(const PolachInput& input, const CreepCoefficients& coefficients);

}  // namespace conforma
