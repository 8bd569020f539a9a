// Reference BEM on a PatchGeometry: the strips are the grid columns, the x grid is chosen from the gap so
// that it covers the interpenetration region {h(x, s) < delta}, which contains the contact area (the
// elastic displacement is >= 0 for |alpha_J - alpha_I| < 90 deg).
#include <algorithm>
#include <cmath>
#include <string>

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
    if (j > 0 && std::fabs(patch.s_m[j] - patch.s_m[j - 1] - patch.ds_m) > 1e-6 * patch.ds_m)
      throw InputError(where + "strip centres must be uniformly spaced by ds_m");
  }
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

BemGrid GridFromPatch(const PatchGeometry& patch, double approach, int nx, double margin) {
  BemGrid grid;
  grid.ns = static_cast<int>(patch.strips());
  grid.nx = nx;
  grid.ds_m = patch.ds_m;
  grid.s_first_m = patch.s_m.front();
  double x_lo = 0.0, x_hi = 0.0;
  bool any = false;
  for (size_t j = 0; j < patch.strips(); ++j) {
    const double depth = approach - patch.gap_m[j];
    if (depth <= 0.0) continue;
    const double half = margin * std::sqrt(depth / patch.longitudinal_curvature_per_m[j]);
    const double lo = Offset(patch, j) - half, hi = Offset(patch, j) + half;
    x_lo = any ? std::min(x_lo, lo) : lo;
    x_hi = any ? std::max(x_hi, hi) : hi;
    any = true;
  }
  if (!any) {  // nothing interpenetrates: a token grid around the closest strip (the solve reports no contact)
    x_lo = -patch.ds_m;
    x_hi = patch.ds_m;
  }
  grid.dx_m = (x_hi - x_lo) / nx;
  grid.x_first_m = x_lo + 0.5 * grid.dx_m;
  grid.gap_m.resize(nx, grid.ns);
  grid.alpha_rad = patch.alpha_rad;
  for (int j = 0; j < grid.ns; ++j) {
    const size_t js = static_cast<size_t>(j);
    for (int i = 0; i < nx; ++i) {
      const double x = grid.x_centre_m(i) - Offset(patch, js);
      grid.gap_m(i, j) = patch.gap_m[js] + patch.longitudinal_curvature_per_m[js] * x * x;  // patch.hpp
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
    if (options.x_elements < 2) throw InputError("BemOptions.x_elements must be >= 2");
    double estimate = EstimateApproach(patch, options.normal_force_N, material);
    BemResult result;
    // The contact lies inside {h < delta}: re-grid until the grid was built for an approach between
    // delta and 1.15 delta (at most a few passes; the Hertz estimate is usually within 20 %).
    for (int pass = 1; pass <= 6; ++pass) {
      result = SolveBemNormal(GridFromPatch(patch, estimate, options.x_elements, options.x_margin), material, options);
      result.regrids = pass;
      if (result.status == BemStatus::NoContact) break;
      const double delta = result.approach_m;
      if (estimate >= delta && estimate <= 1.15 * delta + 1e-15) break;
      estimate = 1.05 * delta;
    }
    return result;
  }
  require_finite(options.approach_m, "BemOptions.approach_m");
  BemResult result =
      SolveBemNormal(GridFromPatch(patch, options.approach_m, options.x_elements, options.x_margin), material, options);
  result.regrids = 1;
  return result;
}

}  // namespace conforma
