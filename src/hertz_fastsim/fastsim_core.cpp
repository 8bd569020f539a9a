// FASTSIM strip core (Kalker 1982; docs/physics-reference.md §2.4, steps 1-4, after CONTACT m_solvpt.f90
// modif_fastsim), written for a general strip patch.
//
// Discretisation: the traction is evaluated at the element centres. The rigid-slip increment between two
// consecutive points of a strip is integrated exactly (it is linear in x), so in adhesion the traction is
// exact at every centre and the force sum is second-order accurate (the classic end-of-element assignment
// over-estimates the linear-theory force by a factor 1 + 1/n_x).
//   Step from x_prev to the centre x_c (h = x_prev - x_c, x_prev = x_lead for the first element):
//     p_x <- p_x - (xi/L1 - phi y/L3) h,       p_y <- p_y - (eta/L2 + phi x_m/L3) h,    x_m = (x_prev + x_c)/2
//   Bound: if |p| > mu p_n, p <- p mu p_n / |p| (slip element).
//   Slip: s = w + L (p_new - p_prev)/h = L (p_new - p_trial)/h componentwise with L = (L1, L2).
// FastsimMarching::ClassicFullStep instead uses h = dx and x_m = x_c for every element (CONTACT modif_fastsim).
#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"

namespace conforma {

const char* to_string(FastsimStatus status) {
  switch (status) {
    case FastsimStatus::Ok: return "ok";
    case FastsimStatus::FullSlip: return "full_slip";
    case FastsimStatus::NoContact: return "no_contact";
  }
  return "unknown";
}

FastsimFlexibilities KalkerFlexibilities(double a_m, double b_m, const CreepCoefficients& coefficients,
                                         double shear_modulus_Pa) {
  require_positive(a_m, "a_m");
  require_positive(b_m, "b_m");
  require_positive(shear_modulus_Pa, "shear_modulus_Pa");
  require_positive(coefficients.c11, "c11");
  require_positive(coefficients.c22, "c22");
  require_positive(coefficients.c23, "c23");
  FastsimFlexibilities L;  // §2.3, CONTACT simpflex
  L.L1 = 8.0 * a_m / (3.0 * coefficients.c11 * shear_modulus_Pa);
  L.L2 = 8.0 * a_m / (3.0 * coefficients.c22 * shear_modulus_Pa);
  L.L3 = M_PI * a_m * std::sqrt(a_m / b_m) / (4.0 * coefficients.c23 * shear_modulus_Pa);
  return L;
}

FastsimFlexibilities BlendedFlexibilities(const FastsimFlexibilities& three, double a_m, double b_m,
                                          const CreepCoefficients& coefficients, double shear_modulus_Pa,
                                          double friction_coefficient, double normal_force_N,
                                          const FastsimCreepages& creepages) {
  const double c = std::sqrt(a_m * b_m);
  const double G = shear_modulus_Pa;
  const double xi = creepages.xi, eta = creepages.eta, phi = creepages.phi_per_m;
  const double q = phi * (M_PI * a_m * a_m / 4.0) / (8.0 * a_m / 3.0);  // dimensionless
  const double numerator = xi * xi + eta * eta + q * q;
  const double denominator = xi * xi / three.L1 + eta * eta / three.L2 + q * q / three.L3;
  if (!(denominator > 0.0)) return three;  // no creepage: nothing to blend
  const double combined = numerator / denominator;
  const double mu_N = friction_coefficient * normal_force_N;
  const double ch_xi = mu_N / (c * c * G * coefficients.c11);
  const double ch_eta = mu_N / (c * c * G * coefficients.c22);
  const double ch_phi_per_mm = mu_N / (c * c * c * G * coefficients.c23) * 1e-3;
  const double phi_per_mm = phi * 1e-3;
  const double ch2 = ch_xi * ch_xi + ch_eta * ch_eta + ch_phi_per_mm * ch_phi_per_mm;
  const double f = ch2 > 0.0 ? std::sqrt((xi * xi + eta * eta + phi_per_mm * phi_per_mm) / ch2) : 3.0;
  const double w = std::min(1.0, std::max(0.0, f / 3.0));
  FastsimFlexibilities out;
  out.L1 = (1.0 - w) * three.L1 + w * combined;
  out.L2 = (1.0 - w) * three.L2 + w * combined;
  out.L3 = (1.0 - w) * three.L3 + w * combined;
  return out;
}

namespace {

// The result sized for n elements, its totals zeroed (every solve starts from it)
void ResetResult(int n, FastsimResult* r) {
  r->x_m.resize(n);
  r->y_m.resize(n);
  r->area_m2.resize(n);
  r->px_Pa.resize(n);
  r->py_Pa.resize(n);
  r->sx.resize(n);
  r->sy.resize(n);
  r->in_slip.resize(n);
  r->fx_N = r->fy_N = r->mz_Nm = 0.0;
  r->adhesion_area_m2 = r->slip_area_m2 = r->frictional_power_W = 0.0;
}

void ValidatePatch(const FastsimPatch& patch) {
  const int n = patch.elements();
  if (!patch.friction_coefficient.empty() && static_cast<int>(patch.friction_coefficient.size()) != n)
    throw InputError("SolveFastsimStrips: friction_coefficient has " + std::to_string(patch.friction_coefficient.size()) +
                     " entries, expected " + std::to_string(n));
  for (size_t j = 0; j < patch.strips.size(); ++j) {
    const FastsimStrip& s = patch.strips[j];
    if (s.n_elements < 0 || s.first_element < 0 || s.first_element + s.n_elements > n ||
        !std::isfinite(s.y_m) || !std::isfinite(s.width_m) || s.width_m < 0.0 || !std::isfinite(s.x_lead_m) ||
        !std::isfinite(s.x_trail_m) || s.x_lead_m < s.x_trail_m)
      throw InputError("SolveFastsimStrips: strip " + std::to_string(j) +
                       " is inconsistent (elements out of range, negative width or x_lead < x_trail)");
  }
}

}  // namespace

namespace {

void ValidateInputs(const FastsimFlexibilities& flexibilities, double friction_coefficient,
                    double rolling_speed_m_per_s, FastsimResult* result) {
  if (result == nullptr) throw InputError("SolveFastsimStrips: result must not be null");
  require_positive(flexibilities.L1, "L1");
  require_positive(flexibilities.L2, "L2");
  require_positive(flexibilities.L3, "L3");
  require_non_negative(friction_coefficient, "friction_coefficient");
  require_non_negative(rolling_speed_m_per_s, "rolling_speed_m_per_s");
}

void ValidateCreepages(const FastsimCreepages& creepages) {
  require_finite(creepages.xi, "xi");
  require_finite(creepages.eta, "eta");
  require_finite(creepages.phi_per_m, "phi_per_m");
}

struct Totals {  // sums over elements, in element order
  double fx = 0.0, fy = 0.0, mz = 0.0, adhesion = 0.0, slip_area = 0.0, power = 0.0;
};

// The march along one strip (§2.4 steps 1-4): element i of the strip from element i-1 (step(i) in order
// i = 0, 1, ...). One object per strip; strips are independent, so two marches can be interleaved.
struct StripMarch {
  const FastsimStrip& strip;
  double L1, L2, xi_L1, eta_L2, phi_L3, friction_coefficient;
  const double* bound;
  const double* mu_field;
  bool classic;
  FastsimResult& r;
  Totals& sums;
  bool& any_bad_bound;
  double y = strip.y_m;
  double dx = (strip.x_lead_m - strip.x_trail_m) / strip.n_elements;
  double area = dx * strip.width_m;
  double increment_x = xi_L1 - phi_L3 * y;  // (xi - phi y L1/L3)/L1, §2.4 step 1
  double px = 0.0, py = 0.0;
  double x_prev = strip.x_lead_m;

  inline void step(int i) {
    const int e = strip.first_element + i;
    const double x_centre = strip.x_lead_m - (i + 0.5) * dx;
    const double h = classic ? dx : x_prev - x_centre;
    const double x_mid = classic ? x_centre : 0.5 * (x_prev + x_centre);
    const double px_trial = px - increment_x * h;
    const double py_trial = py - (eta_L2 + phi_L3 * x_mid) * h;
    const double mu = mu_field ? mu_field[e] : friction_coefficient;
    const double p_n = bound[e];
    any_bad_bound |= !(p_n >= 0.0) || !(mu >= 0.0);
    const double limit = mu * p_n;
    const double magnitude2 = px_trial * px_trial + py_trial * py_trial;
    double sx = 0.0, sy = 0.0;
    unsigned char slipping = 0;
    if (magnitude2 > limit * limit) {  // §2.4 step 3: traction bound
      const double scale = limit / std::sqrt(magnitude2);
      px = px_trial * scale;
      py = py_trial * scale;
      sx = L1 * (px - px_trial) / h;
      sy = L2 * (py - py_trial) / h;
      slipping = 1;
      sums.slip_area += area;
      sums.power += std::abs(px * sx + py * sy) * area;
    } else {
      px = px_trial;
      py = py_trial;
      sums.adhesion += area;
    }
    r.x_m[e] = x_centre;
    r.y_m[e] = y;
    r.area_m2[e] = area;
    r.px_Pa[e] = px;
    r.py_Pa[e] = py;
    r.sx[e] = sx;
    r.sy[e] = sy;
    r.in_slip[e] = slipping;
    sums.fx += px * area;  // §2.4 step 4
    sums.fy += py * area;
    sums.mz += (x_centre * py - y * px) * area;
    x_prev = x_centre;
  }
};

}  // namespace

void SolveFastsimStrips(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                        const FastsimCreepages& creepages, double friction_coefficient,
                        double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result) {
  if (result == nullptr) throw InputError("SolveFastsimStrips: result must not be null");
  require_positive(flexibilities.L1, "L1");
  require_positive(flexibilities.L2, "L2");
  require_positive(flexibilities.L3, "L3");
  ValidateCreepages(creepages);
  require_non_negative(friction_coefficient, "friction_coefficient");
  require_non_negative(rolling_speed_m_per_s, "rolling_speed_m_per_s");
  ValidatePatch(patch);

  FastsimResult& r = *result;
  const int n = patch.elements();
  ResetResult(n, &r);
  if (n == 0) {
    r.status = FastsimStatus::NoContact;
    return;
  }

  const double inv_L1 = 1.0 / flexibilities.L1, inv_L2 = 1.0 / flexibilities.L2, inv_L3 = 1.0 / flexibilities.L3;
  const double xi_L1 = creepages.xi * inv_L1, eta_L2 = creepages.eta * inv_L2, phi_L3 = creepages.phi_per_m * inv_L3;
  const double* mu_field = patch.friction_coefficient.empty() ? nullptr : patch.friction_coefficient.data();
  bool any_bad_bound = false;
  const bool classic = options.marching == FastsimMarching::ClassicFullStep;
  Totals sums;  // one sum over every element of every strip
  for (const FastsimStrip& strip : patch.strips) {
    if (strip.n_elements == 0) continue;
    StripMarch march{strip, flexibilities.L1, flexibilities.L2, xi_L1, eta_L2, phi_L3, friction_coefficient,
                     patch.bound_pressure_Pa.data(), mu_field, classic, r, sums, any_bad_bound};
    for (int i = 0; i < strip.n_elements; ++i) march.step(i);
  }
  if (any_bad_bound)
    throw InputError("SolveFastsimStrips: bound_pressure_Pa and friction_coefficient must be finite and >= 0");
  r.fx_N = sums.fx;
  r.fy_N = sums.fy;
  r.mz_Nm = sums.mz;
  r.adhesion_area_m2 = sums.adhesion;
  r.slip_area_m2 = sums.slip_area;
  r.frictional_power_W = sums.power * rolling_speed_m_per_s;
  r.status = sums.adhesion > 0.0 ? FastsimStatus::Ok : FastsimStatus::FullSlip;
}

void SolveFastsimStripsEach(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                            const std::vector<FastsimCreepages>& creepages, double friction_coefficient,
                            double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result,
                            std::vector<FastsimStripTotals>* strip_totals) {
  ValidateInputs(flexibilities, friction_coefficient, rolling_speed_m_per_s, result);
  if (strip_totals == nullptr) throw InputError("SolveFastsimStripsEach: strip_totals must not be null");
  const size_t ns = patch.strips.size();
  if (creepages.size() != ns)
    throw InputError("SolveFastsimStripsEach: " + std::to_string(creepages.size()) + " creepages for " +
                     std::to_string(ns) + " strips");
  for (const FastsimCreepages& c : creepages) ValidateCreepages(c);
  ValidatePatch(patch);

  FastsimResult& r = *result;
  const int n = patch.elements();
  ResetResult(n, &r);
  strip_totals->assign(ns, FastsimStripTotals{});
  r.status = FastsimStatus::NoContact;
  if (n == 0) return;

  const double inv_L1 = 1.0 / flexibilities.L1, inv_L2 = 1.0 / flexibilities.L2, inv_L3 = 1.0 / flexibilities.L3;
  const double* mu_field = patch.friction_coefficient.empty() ? nullptr : patch.friction_coefficient.data();
  bool any_bad_bound = false;
  const bool classic = options.marching == FastsimMarching::ClassicFullStep;
  std::vector<Totals> sums(ns);
  auto march_of = [&](size_t j) {
    const FastsimCreepages& c = creepages[j];
    return StripMarch{patch.strips[j], flexibilities.L1, flexibilities.L2, c.xi * inv_L1, c.eta * inv_L2,
                      c.phi_per_m * inv_L3, friction_coefficient, patch.bound_pressure_Pa.data(), mu_field, classic,
                      r, sums[j], any_bad_bound};
  };
  // two strips at a time: each march is a chain of dependent divisions and roots, two chains overlap in the CPU
  size_t j = 0;
  for (; j + 1 < ns; j += 2) {
    const int na = patch.strips[j].n_elements, nb = patch.strips[j + 1].n_elements;
    if (na == 0 || nb == 0) break;
    StripMarch a = march_of(j), b = march_of(j + 1);
    const int common = std::min(na, nb);
    for (int i = 0; i < common; ++i) {
      a.step(i);
      b.step(i);
    }
    for (int i = common; i < na; ++i) a.step(i);
    for (int i = common; i < nb; ++i) b.step(i);
  }
  for (; j < ns; ++j) {
    if (patch.strips[j].n_elements == 0) continue;
    StripMarch a = march_of(j);
    for (int i = 0; i < patch.strips[j].n_elements; ++i) a.step(i);
  }
  if (any_bad_bound)
    throw InputError("SolveFastsimStrips: bound_pressure_Pa and friction_coefficient must be finite and >= 0");
  for (size_t k = 0; k < ns; ++k) {
    FastsimStripTotals& t = (*strip_totals)[k];
    t.fx_N = sums[k].fx;
    t.fy_N = sums[k].fy;
    t.mz_Nm = sums[k].mz;
    t.adhesion_area_m2 = sums[k].adhesion;
    t.slip_area_m2 = sums[k].slip_area;
    t.frictional_power_W = sums[k].power * rolling_speed_m_per_s;
  }
}

}  // namespace conforma
