// Planar projection of a curvilinear patch (threshold.hpp, FlattenPatch).
#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/validation/threshold.hpp"

namespace conforma {

namespace {

// Linear interpolation of v over increasing nodes y at q (q inside [y.front(), y.back()]).
double Interpolate(const std::vector<double>& y, const std::vector<double>& v, double q) {
  const size_t k = static_cast<size_t>(std::upper_bound(y.begin(), y.end(), q) - y.begin());
  if (k == 0) return v.front();
  if (k >= y.size()) return v.back();
  const double t = (q - y[k - 1]) / (y[k] - y[k - 1]);
  return v[k - 1] + t * (v[k] - v[k - 1]);
}

}  // namespace

PatchGeometry FlattenPatch(const PatchGeometry& c) {
  const size_t n = c.strips();
  if (n < 2 || c.gap_m.size() != n || c.alpha_rad.size() != n || c.longitudinal_curvature_per_m.size() != n ||
      c.wheel_radius_m.size() != n || c.x_offset_m.size() != n || !(c.ds_m > 0.0))
    throw InputError("FlattenPatch: inconsistent patch (strip arrays of different sizes, < 2 strips or ds <= 0)");
  // the usable range: strips whose normal is turned by less than 85 degrees, contiguous around s = 0
  const double limit = 85.0 * M_PI / 180.0;
  size_t centre = 0;
  for (size_t j = 0; j < n; ++j)
    if (std::fabs(c.s_m[j]) < std::fabs(c.s_m[centre])) centre = j;
  size_t lo = centre, hi = centre;
  while (lo > 0 && std::fabs(c.alpha_rad[lo - 1]) < limit) --lo;
  while (hi + 1 < n && std::fabs(c.alpha_rad[hi + 1]) < limit) ++hi;
  // rail points (Y, Z) in the reference frame (t0, n0) by trapezoidal integration of the tangent, wheel points
  std::vector<double> yr, zr, yw, zw, j_of;
  double Y = 0.0, Z = 0.0;
  for (size_t j = lo; j <= hi; ++j) {
    if (j > lo) {
      const double a0 = c.alpha_rad[j - 1], a1 = c.alpha_rad[j], h = c.s_m[j] - c.s_m[j - 1];
      Y += 0.5 * h * (std::cos(a0) + std::cos(a1));
      Z -= 0.5 * h * (std::sin(a0) + std::sin(a1));
    }
    yr.push_back(Y), zr.push_back(Z);
    yw.push_back(Y + c.gap_m[j] * std::sin(c.alpha_rad[j]));
    zw.push_back(Z + c.gap_m[j] * std::cos(c.alpha_rad[j]));
  }
  // keep the part where both surfaces advance along t0 (functions of the lateral coordinate)
  const size_t m = yr.size();
  size_t first = centre - lo, last = centre - lo;
  while (first > 0 && yr[first - 1] < yr[first] && yw[first - 1] < yw[first]) --first;
  while (last + 1 < m && yr[last + 1] > yr[last] && yw[last + 1] > yw[last]) ++last;
  if (last <= first) throw InputError("FlattenPatch: the patch has no lateral extent after projection");
  const std::vector<double> yr_k(yr.begin() + first, yr.begin() + last + 1), zr_k(zr.begin() + first, zr.begin() + last + 1),
      yw_k(yw.begin() + first, yw.begin() + last + 1), zw_k(zw.begin() + first, zw.begin() + last + 1);
  std::vector<double> A, r, x0;
  for (size_t j = lo + first; j <= lo + last; ++j)
    A.push_back(c.longitudinal_curvature_per_m[j]), r.push_back(c.wheel_radius_m[j]), x0.push_back(c.x_offset_m[j]);
  // reference point: the rail point at s = 0 (interpolated in strip index space)
  std::vector<double> s_k(c.s_m.begin() + lo + first, c.s_m.begin() + lo + last + 1);
  const double y_ref = Interpolate(s_k, yr_k, 0.0);
  const double y_begin = std::max(yr_k.front(), yw_k.front()), y_end = std::min(yr_k.back(), yw_k.back());
  const int strips = static_cast<int>(std::floor((y_end - y_begin) / c.ds_m)) + 1;
  if (strips < 2) throw InputError("FlattenPatch: the projected patch is narrower than two strips");
  PatchGeometry f = c;
  f.s_m.clear(), f.gap_m.clear(), f.longitudinal_curvature_per_m.clear(), f.wheel_radius_m.clear();
  f.alpha_rad.clear(), f.x_offset_m.clear();
  // align the grid with the reference point so that s = 0 stays a strip centre when it is inside
  const double start = y_ref - std::floor((y_ref - y_begin) / c.ds_m) * c.ds_m;
  for (double y = start; y <= y_end + 1e-12 * c.ds_m; y += c.ds_m) {
    f.s_m.push_back(y - y_ref);
    f.gap_m.push_back(Interpolate(yw_k, zw_k, y) - Interpolate(yr_k, zr_k, y));
    f.longitudinal_curvature_per_m.push_back(Interpolate(yr_k, A, y));
    f.wheel_radius_m.push_back(Interpolate(yr_k, r, y));
    f.x_offset_m.push_back(Interpolate(yr_k, x0, y));
    f.alpha_rad.push_back(0.0);
  }
  if (f.s_m.size() < 2) throw InputError("FlattenPatch: the projected patch is narrower than two strips");
  const double gmin = *std::min_element(f.gap_m.begin(), f.gap_m.end());
  for (double& g : f.gap_m) g -= gmin;
  f.rigid_approach_m = c.rigid_approach_m + gmin;
  return f;
}

}  // namespace conforma
