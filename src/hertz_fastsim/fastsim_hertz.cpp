// FASTSIM on a Hertz ellipse (docs/physics-reference.md §2.3-2.4): Kalker's elliptic mesh (ny strips of equal width,
// nx elements of equal length per strip between -a(y) and a(y), a(y) = a sqrt(1 - y^2/b^2)), C_ij from
// KalkerCoefficients, flexibilities from KalkerFlexibilities, the strip core of fastsim_core.cpp.
#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"

namespace conforma {

namespace {

// Antiderivatives of the normalised pressure shapes along a strip, t = x / a(y) in [-1, 1].
double EllipticShapeIntegral(double t) { return 0.5 * (t * std::sqrt(std::max(0.0, 1.0 - t * t)) + std::asin(t)); }
double ParabolicShapeIntegral(double t) { return t - t * t * t / 3.0; }

void ClearResult(FastsimResult* r) {
  *r = FastsimResult{};
  r->status = FastsimStatus::NoContact;
}

}  // namespace

void BuildFastsimHertzPatch(const FastsimHertzInput& input, const FastsimOptions& options, FastsimPatch* patch) {
  if (patch == nullptr) throw InputError("SolveFastsimHertz: patch must not be null");
  require_positive(input.a_m, "a_m");
  require_positive(input.b_m, "b_m");
  require_non_negative(input.normal_force_N, "normal_force_N");
  require_non_negative(input.friction_coefficient, "friction_coefficient");
  require_finite(input.creepages.xi, "xi");
  require_finite(input.creepages.eta, "eta");
  require_finite(input.creepages.phi_per_m, "phi_per_m");
  require_non_negative(input.rolling_speed_m_per_s, "rolling_speed_m_per_s");
  input.material.validate();
  if (input.nx < 1 || input.ny < 1) throw InputError("SolveFastsimHertz: nx and ny must be >= 1");
  if (input.normal_force_N == 0.0) {
    patch->strips.clear();
    patch->bound_pressure_Pa.clear();
    patch->friction_coefficient.clear();
    return;
  }
  const double a = input.a_m, b = input.b_m, N = input.normal_force_N;
  const int nx = input.nx, ny = input.ny;
  const bool elliptic = options.bound == TractionBound::Elliptic;

  patch->strips.resize(ny);
  patch->bound_pressure_Pa.resize(static_cast<size_t>(nx) * ny);
  patch->friction_coefficient.clear();
  double* bound = patch->bound_pressure_Pa.data();

  // Mean of the normalised shape over each element of a strip (the same for every strip of the elliptic mesh),
  // stored first in the slots of strip 0 and spread to the strips below in descending order.
  double upper = elliptic ? EllipticShapeIntegral(1.0) : ParabolicShapeIntegral(1.0);
  for (int i = 0; i < nx; ++i) {
    const double t_lower = 1.0 - 2.0 * (i + 1) / nx;
    const double lower = elliptic ? EllipticShapeIntegral(t_lower) : ParabolicShapeIntegral(t_lower);
    bound[i] = (upper - lower) * (0.5 * nx);
    upper = lower;
  }
  // Peak pressure and its lateral factor (§2.4 step 3).
  const double peak = elliptic ? 3.0 * N / (2.0 * M_PI * a * b) : 2.0 * N / (M_PI * a * b);
  const double dy = 2.0 * b / ny;
  double load = 0.0;
  for (int j = ny - 1; j >= 0; --j) {
    const double y = -b + (j + 0.5) * dy;
    const double q = 1.0 - (y / b) * (y / b);
    const double half_length = a * std::sqrt(q);
    const double lateral = elliptic ? std::sqrt(q) : q;
    FastsimStrip& s = patch->strips[j];
    s.y_m = y;
    s.width_m = dy;
    s.x_lead_m = half_length;
    s.x_trail_m = -half_length;
    s.first_element = j * nx;
    s.n_elements = nx;
    double strip_sum = 0.0;
    for (int i = 0; i < nx; ++i) {
      const double p = peak * lateral * bound[i];
      bound[j * nx + i] = p;
      strip_sum += p;
    }
    load += strip_sum * (2.0 * half_length / nx) * dy;
  }
  // Discrete load = N exactly (the correction is O(1/ny^2) from the lateral midpoint rule).
  const double scale = N / load;
  for (double& p : patch->bound_pressure_Pa) p *= scale;
}

FastsimFlexibilities FastsimHertzFlexibilities(const FastsimHertzInput& input, const FastsimOptions& options) {
  return FastsimHertzFlexibilities(input, options, KalkerCoefficients(input.a_m / input.b_m, input.material.poisson_ratio));
}

FastsimFlexibilities FastsimHertzFlexibilities(const FastsimHertzInput& input, const FastsimOptions& options,
                                               const CreepCoefficients& coefficients) {
  const double a = input.a_m, b = input.b_m;
  FastsimFlexibilities flexibilities = KalkerFlexibilities(a, b, coefficients, input.material.shear_modulus_Pa);
  if (options.blend_flexibilities)
    flexibilities = BlendedFlexibilities(flexibilities, a, b, coefficients, input.material.shear_modulus_Pa,
                                         input.friction_coefficient, input.normal_force_N, input.creepages);
  return flexibilities;
}

void SolveFastsimHertz(const FastsimHertzInput& input, const FastsimOptions& options, FastsimPatch* patch,
                       FastsimResult* result) {
  if (result == nullptr) throw InputError("SolveFastsimHertz: patch and result must not be null");
  BuildFastsimHertzPatch(input, options, patch);
  if (patch->strips.empty()) {  // N = 0
    ClearResult(result);
    return;
  }
  SolveFastsimStrips(*patch, FastsimHertzFlexibilities(input, options), input.creepages, input.friction_coefficient,
                     input.rolling_speed_m_per_s, options, result);
}

FastsimResult SolveFastsimHertz(const FastsimHertzInput& input, const FastsimOptions& options) {
  FastsimPatch patch;
  FastsimResult result;
  SolveFastsimHertz(input, options, &patch, &result);
  return result;
}

}  // namespace conforma
