// Reference BEM on a PatchGeometry (docs/physics-reference.md §10.4): a grid of element_dx x element_ds rectangles
// that covers the interpenetration region {h(x, s) < delta}, which contains the contact area (the elastic
// displacement is >= 0 for |alpha_J - alpha_I| < 90 deg), plus a margin; the strip data is interpolated onto its
// columns.
#include <algorithm>
#include <cmath>
#include <string>

#include "bem_operator.hpp"
#include "conforma/bem_reference.hpp"
#include "conforma/error.hpp"

namespace conforma {
namespace {


void ValidatePatch(const PatchGeometry& patch) {
  const size_t n = patch.strips();
  if (n < 1) throw InputError("PatchGeometry: no strips");
  require_positive(patch.ds_m, "PatchGeometry.ds_m");
  if (patch.gap_m.size() != n || patch.longitudinal_curvature_per_m.size() != n)
    throw InputError("PatchGeometry: gap_m and longitudinal_curvature_per_m must have one entry per strip");
  if (!patch.alpha_rad.empty() && patch.alpha_rad.size() != n)
    throw InputError("PatchGeometry: alpha_rad must be empty or have one entry per strip");
  if (!patch.x_offset_m.empty() && patch.x_offset_m.size() != n)
    throw InputError("PatchGeometry: x_offset_m must be empty or have one entry per strip");
  for (size_t j = 0; j < n; ++j) {
    const std::string where = "PatchGeometry strip " + std::to_string(j) + ": ";
    if (!std::isfinite(patch.s_m[j]) || !std::isfinite(patch.gap_m[j]))
      throw InputError(where + "s_m and gap_m must be finite");
    if (!(patch.longitudinal_curvature_per_m[j] > 0.0) || !std::isfinite(patch.longitudinal_curvature_per_m[j]))
      throw InputError(where + "longitudinal_curvature_per_m must be finite and > 0");
    // strips are ds apart, or a whole number of ds where the candidate search left strips out (a silhouette the
    // rail normal cannot reach, contact_candidates.cpp): the hole is interpolated (SampleStrips)
    if (j > 0) {
      const double step = (patch.s_m[j] - patch.s_m[j - 1]) / patch.ds_m;
      if (!(step > 0.5) || std::fabs(step - std::round(step)) > 1e-6 * std::round(step))
        throw InputError(where + "strip centres must be a whole number of ds_m apart, increasing (found " +
                         MessageNumber(step) + " ds_m)");
    }
  }
}

void ValidateGridOptions(const BemOptions& options) {
  require_positive(options.element_dx_m, "BemOptions.element_dx_m");
  require_positive(options.element_ds_m, "BemOptions.element_ds_m");
  require_positive(options.x_margin, "BemOptions.x_margin");
  if (options.max_elements < 1) throw InputError("BemOptions.max_elements must be >= 1");
}

double Offset(const PatchGeometry& patch, size_t j) { return patch.x_offset_m.empty() ? 0.0 : patch.x_offset_m[j]; }

// Approach estimate for a prescribed force: Hertz with the equivalent radius of the curvatures at the
// closest strip, A from the patch and B from a least-squares parabola of the strip gaps
// (delta = (9 N^2 / (16 R_e E*^2))^(1/3), R_e = 1 / (2 sqrt(A B)); Johnson 1985 §4.2). Only a starting
// point: the solve is repeated on a grid built from the computed approach.
double EstimateApproach(const PatchGeometry& patch, double force, const Material& material) {
  size_t k = 0;
  for (size_t j = 1; j < patch.strips(); ++j)
    if (patch.gap_m[j] < patch.gap_m[k]) k = j;
  const double A = patch.longitudinal_curvature_per_m[k];
  double num = 0.0, den = 0.0;
  for (size_t j = 0; j < patch.strips(); ++j) {
    const double d2 = std::pow(patch.s_m[j] - patch.s_m[k], 2);
    num += (patch.gap_m[j] - patch.gap_m[k]) * d2;
    den += d2 * d2;
  }
  double B = den > 0.0 ? num / den : A;
  if (!(B > 0.0)) B = A;
  const double radius = 1.0 / (2.0 * std::sqrt(A * B));
  const double e_star = material.combined_modulus_Pa();
  return patch.gap_m[k] + std::cbrt(9.0 * force * force / (16.0 * radius * e_star * e_star));
}

// Strip data interpolated linearly in s (clamped to the first / last strip).
struct StripSample {
  double gap, curvature, alpha, offset;
};
StripSample SampleStrips(const PatchGeometry& patch, double s) {
  const size_t n = patch.strips();
  const double t = (s - patch.s_m.front()) / patch.ds_m;
  size_t k = t <= 0.0 ? 0 : std::min(static_cast<size_t>(t), n - 1);
  size_t k1 = std::min(k + 1, n - 1);
  double w = k1 == k ? 0.0 : std::clamp(t - static_cast<double>(k), 0.0, 1.0);
  const bool holes = std::fabs(patch.s_m.back() - patch.s_m.front() - (n - 1.0) * patch.ds_m) > 0.5 * patch.ds_m;
  if (holes) {  // strips left out (ValidatePatch): the two strips around s
    k = static_cast<size_t>(std::upper_bound(patch.s_m.begin(), patch.s_m.end(), s) - patch.s_m.begin());
    k = k == 0 ? 0 : k - 1;
    k1 = std::min(k + 1, n - 1);
    w = k1 == k ? 0.0 : std::clamp((s - patch.s_m[k]) / (patch.s_m[k1] - patch.s_m[k]), 0.0, 1.0);
  }
  auto lerp = [&](const std::vector<double>& v) { return v.empty() ? 0.0 : (1.0 - w) * v[k] + w * v[k1]; };
  return {lerp(patch.gap_m), lerp(patch.longitudinal_curvature_per_m), lerp(patch.alpha_rad), lerp(patch.x_offset_m)};
}

// §10.4: the grid of element_dx x element_ds rectangles over the interpenetration region {h < approach} plus a margin.
BemGrid GridFromPatch(const PatchGeometry& patch, double approach, const BemOptions& options) {
  const double dx = options.element_dx_m, ds = options.element_ds_m;
  double x_lo = 0.0, x_hi = 0.0, s_lo = 0.0, s_hi = 0.0;
  bool any = false;
  for (size_t j = 0; j < patch.strips(); ++j) {
    const double depth = approach - patch.gap_m[j];
    if (depth <= 0.0) continue;
    const double half = options.x_margin * std::sqrt(depth / patch.longitudinal_curvature_per_m[j]);
    const double lo = Offset(patch, j) - half, hi = Offset(patch, j) + half;
    x_lo = any ? std::min(x_lo, lo) : lo;
    x_hi = any ? std::max(x_hi, hi) : hi;
    s_lo = any ? std::min(s_lo, patch.s_m[j]) : patch.s_m[j];
    s_hi = any ? std::max(s_hi, patch.s_m[j]) : patch.s_m[j];
    any = true;
  }
  if (!any) {  // nothing interpenetrates: a token grid at the closest strip (the solve reports no contact)
    size_t k = 0;
    for (size_t j = 1; j < patch.strips(); ++j)
      if (patch.gap_m[j] < patch.gap_m[k]) k = j;
    x_lo = Offset(patch, k) - dx;
    x_hi = Offset(patch, k) + dx;
    s_lo = s_hi = patch.s_m[k];
  }
  // Margin along s: the interpenetration boundary lies within one strip of the outer interpenetrating strips; one
  // element more on each side.
  s_lo -= patch.ds_m + ds;
  s_hi += patch.ds_m + ds;
  const double s0 = patch.s_m.front();
  const double m_lo = std::ceil((s_lo - s0) / ds - 1e-9);
  const double m_hi = std::max(m_lo, std::floor((s_hi - s0) / ds + 1e-9));
  const double ns = m_hi - m_lo + 1.0;
  const double nx = std::max(1.0, std::ceil((x_hi - x_lo) / dx - 1e-9));
  bem_detail::CheckGridBudget(nx, ns, dx, ds, options.max_elements);  // before any allocation (and cast)
  BemGrid grid;
  grid.nx = static_cast<int>(nx);
  grid.ns = static_cast<int>(ns);
  grid.dx_m = dx;
  grid.ds_m = ds;
  grid.x_first_m = 0.5 * (x_lo + x_hi) - 0.5 * (nx - 1.0) * dx;
  grid.s_first_m = s0 + m_lo * ds;
  grid.gap_m.resize(grid.nx, grid.ns);
  if (!patch.alpha_rad.empty()) grid.alpha_rad.resize(static_cast<size_t>(grid.ns));
  for (int j = 0; j < grid.ns; ++j) {
    const StripSample c = SampleStrips(patch, grid.s_centre_m(j));
    if (!patch.alpha_rad.empty()) grid.alpha_rad[static_cast<size_t>(j)] = c.alpha;
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.x_centre_m(i) - c.offset;
      grid.gap_m(i, j) = c.gap + c.curvature * x * x;  // patch.hpp
    }
  }
  return grid;
}

}  // namespace

BemResult SolveBemNormal(const PatchGeometry& patch, const Material& material, const BemOptions& options) {
  ValidatePatch(patch);
  material.validate();
  if (options.control == BemLoadControl::NormalForce) {
    require_non_negative(options.normal_force_N, "BemOptions.normal_force_N");
    ValidateGridOptions(options);
    double estimate = EstimateApproach(patch, options.normal_force_N, material);
    BemResult result;
    // The contact lies inside {h < delta}: re-grid until the grid was built for an approach between
    // delta and 1.15 delta (at most a few passes; the Hertz estimate is usually within 20 %).
    for (int pass = 1; pass <= 6; ++pass) {
      result = SolveBemNormal(GridFromPatch(patch, estimate, options), material, options);
      result.regrids = pass;
      if (result.status == BemStatus::NoContact) break;
      const double delta = result.approach_m;
      if (estimate >= delta && estimate <= 1.15 * delta + 1e-15) break;
      estimate = 1.05 * delta;
    }
    return result;
  }
  require_finite(options.approach_m, "BemOptions.approach_m");
  ValidateGridOptions(options);
  BemResult result = SolveBemNormal(GridFromPatch(patch, options.approach_m, options), material, options);
  result.regrids = 1;
  return result;
}

}  // namespace conforma
