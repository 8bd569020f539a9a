// Hertz elliptical contact, exact solution with complete elliptic integrals (docs/physics-reference.md §1.2,
// after CONTACT m_hertz.f90 hzcalc3d). Both bodies share one Material, E* = G / (1 - nu) (§0).
#include "conforma/hertz.hpp"

#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(HertzStatus status) {
  switch (status) {
    case HertzStatus::Ok: return "ok";
    case HertzStatus::NoSolution: return "no_solution";
    case HertzStatus::NoContact: return "no_contact";
  }
  return "unknown";
}

namespace {

// Curvature ratio r(g) = g^2 (K - E) / (E - g^2 K) of §1.2 step 1, with E - g^2 K = k^2 K - (K - E).
double CurvatureRatioOfAxisRatio(double g) {
  if (g >= 1.0) return 1.0;
  const CompleteEllipticIntegrals ei = EllipticIntegralsFromComplementaryModulus(g);
  const double k2 = (1.0 - g) * (1.0 + g);
  return g * g * ei.K_minus_E / (k2 * ei.K - ei.K_minus_E);
}

// Solve r(g) = r for g in (0, 1]; ln r is a smooth, monotone function of ln g (slope ~ 1.2 ... 2), so a
// secant iteration in logarithms, safeguarded by a bracket and bisection, converges in a few steps.
double AxisRatioOfCurvatureRatio(double r) {
  if (r >= 1.0) return 1.0;
  const double target = std::log(r);
  double lo = std::log(1e-12);  // ln g bracket: F(lo) < 0 <= F(hi)
  double hi = 0.0;
  auto F = [&](double ln_g) { return std::log(CurvatureRatioOfAxisRatio(std::exp(ln_g))) - target; };
  // Starting guess from the Hamrock-Brewe fit a_long/a_short ~ 1.0339 (1/r)^0.636 (§1.4).
  double x0 = std::clamp(0.636 * target - std::log(1.0339), lo + 1.0, -1e-9);
  double f0 = F(x0);
  if (f0 < 0) lo = x0; else hi = x0;
  double x1 = std::clamp(x0 + 0.01, lo, hi);
  double f1 = F(x1);
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (f1 < 0) lo = std::max(lo, x1); else hi = std::min(hi, x1);
    if (std::abs(f1) < 1e-15 || hi - lo < 1e-15) break;
    double x2 = (f1 != f0) ? x1 - f1 * (x1 - x0) / (f1 - f0) : 0.5 * (lo + hi);
    if (!(x2 > lo && x2 < hi)) x2 = 0.5 * (lo + hi);
    x0 = x1;
    f0 = f1;
    x1 = x2;
    f1 = F(x1);
  }
  return std::exp(x1);
}

void ValidateCurvaturesAndMaterial(double A_per_m, double B_per_m, const Material& material) {
  require_finite(A_per_m, "A_per_m");
  require_finite(B_per_m, "B_per_m");
  material.validate();
}

// Shape part of the solution (depends on A, B only): g, K, E and the assignment of the semi-axes.
struct HertzShape {
  double g = 1.0;
  CompleteEllipticIntegrals ei;
  double rho = 0.0;       // 2 / (A + B)
  bool a_is_long = true;  // A <= B: the longer semi-axis lies along x
};

HertzShape ComputeShape(double A_per_m, double B_per_m) {
  HertzShape shape;
  const double r = std::min(A_per_m, B_per_m) / std::max(A_per_m, B_per_m);
  shape.g = AxisRatioOfCurvatureRatio(r);
  shape.ei = EllipticIntegralsFromComplementaryModulus(shape.g);
  shape.rho = 2.0 / (A_per_m + B_per_m);
  shape.a_is_long = A_per_m <= B_per_m;
  return shape;
}

// §1.2 step 2 and 3 for a given load N > 0.
HertzResult FromShapeAndLoad(const HertzShape& shape, double normal_force_N, double e_star) {
  const double g = shape.g;
  const double K = shape.ei.K;
  const double E = shape.ei.E;
  HertzResult out;
  out.status = HertzStatus::Ok;
  out.elliptic_K = K;
  out.elliptic_E = E;
  const double c = std::cbrt(3.0 * normal_force_N * shape.rho * E / (4.0 * M_PI * e_star * std::sqrt(g)));
  out.a_m = shape.a_is_long ? c / std::sqrt(g) : c * std::sqrt(g);
  out.b_m = shape.a_is_long ? c * std::sqrt(g) : c / std::sqrt(g);
  out.a_over_b = out.a_m / out.b_m;
  out.normal_force_N = normal_force_N;
  out.p0_Pa = 3.0 * normal_force_N / (2.0 * M_PI * out.a_m * out.b_m);
  out.approach_m = 2.0 * g * c * c * K / (shape.rho * E);
  out.stiffness_N_per_m15 = (4.0 * M_PI * e_star / (3.0 * g)) * std::sqrt(shape.rho * E) / std::pow(2.0 * K, 1.5);
  return out;
}

HertzResult NoContactResult(const HertzShape& shape) {
  HertzResult out;
  out.status = HertzStatus::NoContact;
  out.a_over_b = shape.a_is_long ? 1.0 / shape.g : shape.g;
  out.elliptic_K = shape.ei.K;
  out.elliptic_E = shape.ei.E;
  return out;
}

}  // namespace

HertzResult SolveHertzForLoad(double A_per_m, double B_per_m, double normal_force_N, const Material& material) {
  ValidateCurvaturesAndMaterial(A_per_m, B_per_m, material);
  require_non_negative(normal_force_N, "normal_force_N");
  if (A_per_m <= 0.0 || B_per_m <= 0.0) return HertzResult{};  // NoSolution: not a Hertzian gap
  const HertzShape shape = ComputeShape(A_per_m, B_per_m);
  if (normal_force_N == 0.0) return NoContactResult(shape);
  return FromShapeAndLoad(shape, normal_force_N, material.combined_modulus_Pa());
}

HertzResult SolveHertzForApproach(double A_per_m, double B_per_m, double approach_m, const Material& material) {
  ValidateCurvaturesAndMaterial(A_per_m, B_per_m, material);
  require_non_negative(approach_m, "approach_m");
  if (A_per_m <= 0.0 || B_per_m <= 0.0) return HertzResult{};
  const HertzShape shape = ComputeShape(A_per_m, B_per_m);
  if (approach_m == 0.0) return NoContactResult(shape);
  const double e_star = material.combined_modulus_Pa();
  // Load-approach law N = C_H delta^(3/2) (§1.2).
  const double K = shape.ei.K;
  const double E = shape.ei.E;
  const double stiffness = (4.0 * M_PI * e_star / (3.0 * shape.g)) * std::sqrt(shape.rho * E) / std::pow(2.0 * K, 1.5);
  HertzResult out = FromShapeAndLoad(shape, stiffness * std::pow(approach_m, 1.5), e_star);
  out.approach_m = approach_m;  // exact by construction; avoids a round-off difference
  return out;
}

double HertzPressure(const HertzResult& hertz, double x_m, double y_m) {
  if (hertz.status != HertzStatus::Ok) return 0.0;
  const double u = x_m / hertz.a_m;
  const double v = y_m / hertz.b_m;
  const double q = 1.0 - u * u - v * v;
  return q > 0.0 ? hertz.p0_Pa * std::sqrt(q) : 0.0;
}

}  // namespace conforma
