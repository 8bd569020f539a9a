// Variable-friction FASTSIM (paper 002 §2.1; docs/physics-reference.md §7.2). The marching is that of the core
// (src/fastsim_core.cpp: traction at element centres, exact rigid-slip increment, or the classic full step);
// it is repeated here because the traction bound of an element depends on the element's own slip, which the
// core cannot know before it marches (the core takes the bound as a fixed per-element input). A constant law is
// dispatched to the core by SolveFastsimStripsWithLaw.
#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/root_finding.hpp"

namespace conforma {

namespace {

// Slip modulus of a slip element (paper 002 eq. 5, Gimenez et al.: the traction of the previous element is taken at
// the friction level of this one, i.e. the elastic slip is mu(gamma) L dp_n/dx, not the derivative of mu along x):
//   p_trial(gamma) = r(gamma) p_prev - L^-1 w h,   r = mu_eff(gamma) / mu_eff(0)
// (r = 1 at gamma = 0, so the slip starts from 0 where the adhesion bound is reached: continuous switches, and the
// element equation stays monotone for falling laws; the fully implicit form has several roots there).
//   p(gamma) = mu_eff(gamma) p_n p_trial / |p_trial|,  s(gamma) = L (p - p_trial) / h,   gamma = |s(gamma)|.
// F(gamma) = gamma - |s(gamma)| has F(0) <= 0 and F -> +inf: a bracket by doubling, then regula falsi (Illinois).
struct ElementSlip {
  double px_prev, py_prev, mu_prev;  // mu_prev <= 0: the previous traction is not at a friction bound
  double wx, wy;                     // L^-1 w h (traction increment of the rigid slip)
  double L1, L2, h, p_n;
  double gamma_memory;  // largest slip reached so far on the strip: mu(gamma) is used as mu(max(gamma, memory))
  const FrictionLaw* law;
  double Residual(double gamma, double* px, double* py) const {
    const double mu = (*law)(std::max(gamma, gamma_memory));
    const double ratio = mu_prev > 0.0 ? mu / mu_prev : 1.0;
    const double tx = ratio * px_prev - wx, ty = ratio * py_prev - wy;
    const double magnitude = std::hypot(tx, ty);
    const double scale = magnitude > 0.0 ? mu * p_n / magnitude : 0.0;
    *px = tx * scale;
    *py = ty * scale;
    return gamma - std::hypot(L1 * (*px - tx), L2 * (*py - ty)) / h;
  }
};

double SolveElementSlip(const ElementSlip& e, double guess) {
  double px, py;
  double lo = 0.0, f_lo = e.Residual(0.0, &px, &py);
  if (f_lo >= 0.0) return 0.0;
  double hi = std::max(1e-3 * guess, 1e-12), f_hi = e.Residual(hi, &px, &py);  // the root nearest the adhesion side
  for (int i = 0; i < 200 && f_hi < 0.0; ++i) {
    lo = hi;
    f_lo = f_hi;
    hi *= 2.0;
    f_hi = e.Residual(hi, &px, &py);
  }
  IllinoisBracket bracket(lo, f_lo, hi, f_hi);  // the one root finder's step (root_finding.hpp)
  double gamma = hi;
  for (int iteration = 0; iteration < 200 && bracket.high() - bracket.low() > 1e-15 * bracket.high(); ++iteration) {
    gamma = bracket.FalsePosition();
    if (!(gamma > bracket.low() && gamma < bracket.high())) gamma = 0.5 * (bracket.low() + bracket.high());
    const double f = e.Residual(gamma, &px, &py);
    if (f == 0.0) break;
    bracket.Replace(gamma, f, f < 0.0);
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
  double fx = 0.0, fy = 0.0, mz = 0.0, adhesion = 0.0, slip_area = 0.0, power = 0.0;
  for (const FastsimStrip& strip : patch.strips) {
    if (strip.n_elements == 0) continue;
    const double y = strip.y_m;
    const double dx = (strip.x_lead_m - strip.x_trail_m) / strip.n_elements;
    const double area = dx * strip.width_m;
    const double increment_x = xi_L1 - phi_L3 * y;
    double px = 0.0, py = 0.0, x_prev = strip.x_lead_m, gamma_memory = 0.0;
    double pn_prev = 0.0;          // bound pressure at the previous point (0 at the leading edge)
    bool previous_adhered = true;  // the leading edge counts as adhesion
    for (int i = 0; i < strip.n_elements; ++i) {
      const int e = strip.first_element + i;
      const double x_centre = strip.x_lead_m - (i + 0.5) * dx;
      const double h = classic ? dx : x_prev - x_centre;
      const double x_mid = classic ? x_centre : 0.5 * (x_prev + x_centre);
      const double px_trial = px - increment_x * h;
      const double py_trial = py - (eta_L2 + phi_L3 * x_mid) * h;
      const double p_n = patch.bound_pressure_Pa[e];
      const double magnitude2 = px_trial * px_trial + py_trial * py_trial;
      // Without recuperation of static friction (paper 002 §2.1, Piotrowski): along a strip the friction level
      // does not return once the surface has slipped, mu_eff(gamma) = mu(max(gamma, gamma_memory)), with
      // gamma_memory the largest slip reached so far on the strip (0 at the leading edge: the static mu(0)).
      // The adhesion test uses mu_eff(0); with it, every adhesion/slip switch is continuous in the creepage and in
      // the law's parameters (needed by the identification).
      const double mu_level = law(gamma_memory);
      const double limit = mu_level * p_n;
      double sx = 0.0, sy = 0.0;
      unsigned char slipping = 0;
      double report_x = 0.0, report_y = 0.0;  // traction integrated and reported for the element
      if (magnitude2 > limit * limit && h > 0.0) {  // slip element
        // Onset of slip after adhesion: the bound is first reached at tau* of the step (the adhesion traction and
        // the bound both linear in between). The slip step starts there, from a traction at the bound, and the
        // element reports the step-weighted mean of the bound traction at tau* and the slip traction, so a switch
        // between adhesion and slip moves continuously with the creepages and the law's parameters.
        double tau = 0.0;
        if (previous_adhered) {
          double lo = 0.0, hi = 1.0;
          for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            const double over = std::hypot(px + (px_trial - px) * mid, py + (py_trial - py) * mid) -
                                mu_level * (pn_prev + (p_n - pn_prev) * mid);
            if (over > 0.0) hi = mid; else lo = mid;
          }
          tau = 0.5 * (lo + hi);
        }
        const double start_x = px + (px_trial - px) * tau, start_y = py + (py_trial - py) * tau;
        const double h_slip = h * (1.0 - tau);
        const ElementSlip element{start_x, start_y, mu_level, (px - px_trial) * (1.0 - tau),
                                  (py - py_trial) * (1.0 - tau), L1, L2, h_slip, p_n, gamma_memory, &law};
        const double gamma = SolveElementSlip(element, std::hypot(L1 * (px - px_trial), L2 * (py - py_trial)) / h);
        double ptx, pty;
        const double mu = law(std::max(gamma, gamma_memory));
        const double ratio = mu_level > 0.0 ? mu / mu_level : 1.0;
        element.Residual(gamma, &ptx, &pty);  // traction at the solved slip
        const double tx = ratio * start_x - element.wx, ty = ratio * start_y - element.wy;
        px = ptx;
        py = pty;
        sx = L1 * (px - tx) / h_slip;
        sy = L2 * (py - ty) / h_slip;
        report_x = tau * start_x + (1.0 - tau) * px;
        report_y = tau * start_y + (1.0 - tau) * py;
        gamma_memory = std::max(gamma_memory, gamma);
        slipping = 1;
        previous_adhered = false;
        slip_area += area;
        power += std::abs(px * sx + py * sy) * area;
      } else {
        px = px_trial;
        py = py_trial;
        report_x = px;
        report_y = py;
        previous_adhered = true;
        adhesion += area;
      }
      pn_prev = p_n;
      r.px_Pa[e] = report_x;
      r.py_Pa[e] = report_y;
      r.sx[e] = sx;
      r.sy[e] = sy;
      r.in_slip[e] = slipping;
      fx += report_x * area;
      fy += report_y * area;
      mz += (x_centre * report_y - y * report_x) * area;
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
