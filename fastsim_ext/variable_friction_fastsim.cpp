// Variable-friction FASTSIM (paper 002 §2.1; physics-reference §7.2). The marching is that of the core
// (src/fastsim_core.cpp: traction at element centres, exact rigid-slip increment, or the classic full step);
// it is repeated here because the traction bound of an element depends on the element's own slip, which the
// core cannot know before it marches (the core takes the bound as a fixed per-element input). A constant law is
// dispatched to the core by SolveFastsimStripsWithLaw.
#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"

namespace conforma {

namespace {

// Smallest-from-adhesion root of g(gamma) = gamma - K (|p_trial| - mu(gamma) p_n) on [0, K |p_trial|], where
// g(0) < 0 (the element is in slip) and g(K |p_trial|) = K mu p_n >= 0. Safeguarded Newton from gamma = 0.
double SolveElementSlip(const FrictionLaw& law, double K, double trial, double p_n) {
  double lo = 0.0, hi = K * trial;
  double gamma = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double g = gamma - K * (trial - law(gamma) * p_n);
    if (g < 0.0) lo = gamma; else hi = gamma;
    if (std::abs(g) <= 1e-15 * (K * trial) || hi - lo <= 1e-15 * (K * trial)) break;
    const double slope = 1.0 + K * p_n * law.derivative(gamma);
    double next = slope > 0.0 ? gamma - g / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // keep inside the bracket
    gamma = next;
  }
  return gamma;
}

}  // namespace

void SolveFastsimStripsVariableFriction(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                                        const FastsimCreepages& creepages, const FrictionLaw& law,
                                        double rolling_speed_m_per_s, const FastsimOptions& options,
                                        FastsimResult* result) {
  if (result == nullptr) throw InputError("SolveFastsimStripsVariableFriction: result must not be null");
  law.validate();
  if (!patch.friction_coefficient.empty())
    throw InputError("SolveFastsimStripsVariableFriction: patch.friction_coefficient must be empty (the law sets mu)");
  // Let the core validate everything else and size the result (a zero-friction dry run costs one pass).
  SolveFastsimStrips(patch, flexibilities, creepages, 0.0, rolling_speed_m_per_s, options, result);
  FastsimResult& r = *result;
  if (patch.elements() == 0) return;

  const double L1 = flexibilities.L1, L2 = flexibilities.L2;
  const double xi_L1 = creepages.xi / L1, eta_L2 = creepages.eta / L2, phi_L3 = creepages.phi_per_m / flexibilities.L3;
  const bool classic = options.marching == FastsimMarching::ClassicFullStep;
  const double mu_static = law(0.0);
  double fx = 0.0, fy = 0.0, mz = 0.0, adhesion = 0.0, slip_area = 0.0, power = 0.0;
  for (const FastsimStrip& strip : patch.strips) {
    if (strip.n_elements == 0) continue;
    const double y = strip.y_m;
    const double dx = (strip.x_lead_m - strip.x_trail_m) / strip.n_elements;
    const double area = dx * strip.width_m;
    const double increment_x = xi_L1 - phi_L3 * y;
    double px = 0.0, py = 0.0, x_prev = strip.x_lead_m;
    for (int i = 0; i < strip.n_elements; ++i) {
      const int e = strip.first_element + i;
      const double x_centre = strip.x_lead_m - (i + 0.5) * dx;
      const double h = classic ? dx : x_prev - x_centre;
      const double x_mid = classic ? x_centre : 0.5 * (x_prev + x_centre);
      const double px_trial = px - increment_x * h;
      const double py_trial = py - (eta_L2 + phi_L3 * x_mid) * h;
      const double p_n = patch.bound_pressure_Pa[e];
      const double magnitude2 = px_trial * px_trial + py_trial * py_trial;
      const double static_limit = mu_static * p_n;
      double sx = 0.0, sy = 0.0;
      unsigned char slipping = 0;
      if (magnitude2 > static_limit * static_limit && h > 0.0) {  // paper 002 §2.1: slip element
        const double trial = std::sqrt(magnitude2);
        const double K = std::hypot(L1 * px_trial, L2 * py_trial) / (h * trial);
        const double gamma = SolveElementSlip(law, K, trial, p_n);
        const double scale = law(gamma) * p_n / trial;
        px = px_trial * scale;
        py = py_trial * scale;
        sx = L1 * (px - px_trial) / h;
        sy = L2 * (py - py_trial) / h;
        slipping = 1;
        slip_area += area;
        power += std::abs(px * sx + py * sy) * area;
      } else {
        px = px_trial;
        py = py_trial;
        adhesion += area;
      }
      r.px_Pa[e] = px;
      r.py_Pa[e] = py;
      r.sx[e] = sx;
      r.sy[e] = sy;
      r.in_slip[e] = slipping;
      fx += px * area;
      fy += py * area;
      mz += (x_centre * py - y * px) * area;
      x_prev = x_centre;
    }
  }
  r.fx_N = fx;
  r.fy_N = fy;
  r.mz_Nm = mz;
  r.adhesion_area_m2 = adhesion;
  r.slip_area_m2 = slip_area;
  r.frictional_power_W = power * rolling_speed_m_per_s;
  r.status = adhesion > 0.0 ? FastsimStatus::Ok : FastsimStatus::FullSlip;
}

void SolveFastsimStripsWithLaw(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                               const FastsimCreepages& creepages, const FrictionLaw& law,
                               double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result) {
  if (law.is_constant()) {
    law.validate();
    SolveFastsimStrips(patch, flexibilities, creepages, law.parameters[0], rolling_speed_m_per_s, options, result);
  } else {
    SolveFastsimStripsVariableFriction(patch, flexibilities, creepages, law, rolling_speed_m_per_s, options, result);
  }
}

}  // namespace conforma
