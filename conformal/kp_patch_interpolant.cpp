// Continuous view of a PatchGeometry along s for the KP solvers.
#include "kp_patch_interpolant.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "conforma/error.hpp"

namespace conforma {
namespace kp_detail {

namespace {
void RequireSize(const std::vector<double>& values, size_t strips, const char* name, bool optional) {
  if (optional && values.empty()) return;
  if (values.size() != strips)
    throw InputError("PatchGeometry." + std::string(name) + ": has " + std::to_string(values.size()) +
                     " values for " + std::to_string(strips) + " strips");
}
void RequireFiniteAll(const std::vector<double>& values, const char* name) {
  // Fast pass: a value is not finite when its exponent bits are all ones (an integer OR-reduction, vectorised);
  // only then look for the index to name.
  constexpr std::uint64_t kExponent = 0x7ff0000000000000ULL;
  std::uint64_t any_non_finite = 0;
  for (const double value : values) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    any_non_finite |= static_cast<std::uint64_t>((bits & kExponent) == kExponent);
  }
  if (any_non_finite == 0) return;
  for (size_t j = 0; j < values.size(); ++j)
    if (!std::isfinite(values[j]))
      throw InputError("PatchGeometry." + std::string(name) + "[" + std::to_string(j) + "] is not finite");
}
}  // namespace

PatchInterpolant::PatchInterpolant(const PatchGeometry& patch) : patch_(patch) {
  const size_t n = patch.s_m.size();
  if (n < 2) throw InputError("PatchGeometry.s_m: at least 2 strips are needed, got " + std::to_string(n));
  require_positive(patch.ds_m, "PatchGeometry.ds_m");
  RequireSize(patch.gap_m, n, "gap_m", false);
  RequireSize(patch.longitudinal_curvature_per_m, n, "longitudinal_curvature_per_m", false);
  RequireSize(patch.alpha_rad, n, "alpha_rad", true);
  RequireSize(patch.x_offset_m, n, "x_offset_m", true);
  RequireFiniteAll(patch.s_m, "s_m");
  RequireFiniteAll(patch.gap_m, "gap_m");
  RequireFiniteAll(patch.longitudinal_curvature_per_m, "longitudinal_curvature_per_m");
  RequireFiniteAll(patch.alpha_rad, "alpha_rad");
  RequireFiniteAll(patch.x_offset_m, "x_offset_m");
  for (size_t j = 0; j < n; ++j) {
    if (!(patch.longitudinal_curvature_per_m[j] > 0.0))
      throw InputError("PatchGeometry.longitudinal_curvature_per_m[" + std::to_string(j) + "] must be > 0");
    if (j > 0 && !(patch.s_m[j] > patch.s_m[j - 1]))
      throw InputError("PatchGeometry.s_m[" + std::to_string(j) + "] must increase strictly");
  }
  has_alpha_ = !patch.alpha_rad.empty();
  has_x_offset_ = !patch.x_offset_m.empty();
  domain_low_ = patch.s_m.front() - 0.5 * patch.ds_m;
  domain_high_ = patch.s_m.back() + 0.5 * patch.ds_m;
  inverse_mean_spacing_ = static_cast<double>(n - 1) / (patch.s_m.back() - patch.s_m.front());
  // Three-point slopes (exact for a quadratic on non-uniform nodes); one-sided three-point at the ends.
  slope_.resize(n);
  const auto& s = patch.s_m;
  const auto& g = patch.gap_m;
  if (n == 2) {
    slope_[0] = slope_[1] = (g[1] - g[0]) / (s[1] - s[0]);
    minimum_gap_location_ = LocateMinimumGap();
    return;
  }
  auto three_point = [&](size_t a, size_t b, size_t c, double at) {
    // derivative at 'at' of the parabola through nodes a, b, c
    const double la = ((at - s[b]) + (at - s[c])) / ((s[a] - s[b]) * (s[a] - s[c]));
    const double lb = ((at - s[a]) + (at - s[c])) / ((s[b] - s[a]) * (s[b] - s[c]));
    const double lc = ((at - s[a]) + (at - s[b])) / ((s[c] - s[a]) * (s[c] - s[b]));
    return la * g[a] + lb * g[b] + lc * g[c];
  };
  slope_[0] = three_point(0, 1, 2, s[0]);
  for (size_t j = 1; j + 1 < n; ++j) slope_[j] = three_point(j - 1, j, j + 1, s[j]);
  slope_[n - 1] = three_point(n - 3, n - 2, n - 1, s[n - 1]);
  minimum_gap_location_ = LocateMinimumGap();
}

size_t PatchInterpolant::Segment(double s) const {
  const auto& nodes = patch_.s_m;
  const size_t last = nodes.size() - 2;
  const double guess = (s - nodes.front()) * inverse_mean_spacing_;
  size_t i = 0;
  if (guess >= static_cast<double>(last)) {
    i = last;
  } else if (guess > 0.0) {
    i = static_cast<size_t>(guess);
  }  // else (also NaN): 0
  while (i > 0 && nodes[i] > s) --i;
  while (i < last && nodes[i + 1] <= s) ++i;
  return i;
}

double PatchInterpolant::gap(double s) const {
  const size_t i = Segment(s);
  const double s0 = patch_.s_m[i];
  const double h = patch_.s_m[i + 1] - s0;
  const double t = (s - s0) / h;
  const double t2 = t * t;
  const double t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * patch_.gap_m[i] + (t3 - 2 * t2 + t) * h * slope_[i] +
         (-2 * t3 + 3 * t2) * patch_.gap_m[i + 1] + (t3 - t2) * h * slope_[i + 1];
}

double PatchInterpolant::Linear(const std::vector<double>& values, double s) const {
  const size_t i = Segment(s);
  const double t = (s - patch_.s_m[i]) / (patch_.s_m[i + 1] - patch_.s_m[i]);
  return values[i] + t * (values[i + 1] - values[i]);
}

double PatchInterpolant::LocateMinimumGap() const {
  const auto& g = patch_.gap_m;
  const auto& s = patch_.s_m;
  const size_t i = static_cast<size_t>(std::min_element(g.begin(), g.end()) - g.begin());
  if (i == 0 || i + 1 == g.size()) return s[i];
  // Vertex of the parabola through the three nodes, kept between the neighbours.
  const double d1 = (g[i] - g[i - 1]) / (s[i] - s[i - 1]);
  const double d2 = (g[i + 1] - g[i]) / (s[i + 1] - s[i]);
  const double curvature = (d2 - d1) / (s[i + 1] - s[i - 1]);
  if (!(curvature > 0.0)) return s[i];
  const double vertex = 0.5 * (s[i - 1] + s[i]) - d1 / (2.0 * curvature);  // d1 is the slope at the mid-point
  const double located = std::clamp(vertex, s[i - 1], s[i + 1]);
  return gap(located) <= g[i] ? located : s[i];
}

}  // namespace kp_detail
}  // namespace conforma
