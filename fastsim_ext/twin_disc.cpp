// Twin-disc line contact with FASTSIM and a friction law (paper 002 §3.2, eqs. 10, 12; see friction_fit.hpp).
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/friction_fit.hpp"

namespace conforma {

namespace {
double EffectiveRadius(const TwinDiscSetup& s) { return s.radius_1_m * s.radius_2_m / (s.radius_1_m + s.radius_2_m); }
double EffectiveModulus(const TwinDiscSetup& s) {
  return s.material.shear_modulus_Pa / (1.0 - s.material.poisson_ratio);  // E* = E / (2 (1 - nu^2)), E = 2G(1+nu)
}
double SemiEllipseIntegral(double t) {
  t = std::max(-1.0, std::min(1.0, t));
  return 0.5 * (t * std::sqrt(std::max(0.0, 1.0 - t * t)) + std::asin(t));
}
}  // namespace

void TwinDiscSetup::validate() const {
  require_positive(radius_1_m, "radius_1_m");
  require_positive(radius_2_m, "radius_2_m");
  require_positive(width_m, "width_m");
  require_positive(normal_force_N, "normal_force_N");
  material.validate();
  if (elements < 1) throw InputError("TwinDiscSetup: elements must be >= 1");
}

TwinDiscContact TwinDiscHertz(const TwinDiscSetup& setup) {
  setup.validate();
  const double R = EffectiveRadius(setup), E = EffectiveModulus(setup), P = setup.normal_force_N / setup.width_m;
  TwinDiscContact c;
  c.a_m = std::sqrt(4.0 * P * R / (M_PI * E));  // line-contact Hertz
  c.p0_Pa = 2.0 * P / (M_PI * c.a_m);
  const double nu = setup.material.poisson_ratio;
  c.c11 = M_PI * M_PI / (4.0 * (1.0 - nu));  // docs/physics-reference.md §2.2, a/b -> 0
  c.L1_m_per_Pa = 4.0 * c.a_m / (c.c11 * setup.material.shear_modulus_Pa);  // paper 002 eq. 10
  return c;
}

double TwinDiscForceForPeakPressure(const TwinDiscSetup& setup, double p0_Pa) {
  require_positive(p0_Pa, "p0_Pa");
  const double a = 2.0 * p0_Pa * EffectiveRadius(setup) / EffectiveModulus(setup);  // paper 002 eq. 12
  return M_PI * a * setup.width_m * p0_Pa / 2.0;
}

std::vector<double> TwinDiscCreepCurve(const TwinDiscSetup& setup, const FrictionLaw& law, double slope_reduction,
                                       const std::vector<double>& creepages, FastsimMarching marching) {
  const TwinDiscContact contact = TwinDiscHertz(setup);
  law.validate();
  const int n = setup.elements;
  FastsimPatch patch;
  patch.strips.resize(1);
  patch.strips[0] = {0.0, setup.width_m, contact.a_m, -contact.a_m, 0, n};
  patch.bound_pressure_Pa.resize(n);
  double upper = SemiEllipseIntegral(1.0), load = 0.0;
  for (int i = 0; i < n; ++i) {
    const double lower = SemiEllipseIntegral(1.0 - 2.0 * (i + 1) / n);
    patch.bound_pressure_Pa[i] = contact.p0_Pa * (upper - lower) * (0.5 * n);
    load += patch.bound_pressure_Pa[i] * (2.0 * contact.a_m / n) * setup.width_m;
    upper = lower;
  }
  for (double& p : patch.bound_pressure_Pa) p *= setup.normal_force_N / load;  // discrete load = N
  const double L = contact.L1_m_per_Pa;
  const FastsimFlexibilities flexibilities = ReducedFlexibilities({L, L, L}, slope_reduction);
  FastsimOptions options;
  options.marching = marching;
  FastsimResult result;
  std::vector<double> curve;
  curve.reserve(creepages.size());
  for (double xi : creepages) {
    require_finite(xi, "creepage");
    SolveFastsimStripsWithLaw(patch, flexibilities, {xi, 0.0, 0.0}, law, 0.0, options, &result);
    curve.push_back(-result.fx_N / setup.normal_force_N);
  }
  return curve;
}

}  // namespace conforma
