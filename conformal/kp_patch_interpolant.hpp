#pragma once
// Private to the KP solvers: continuous view of a PatchGeometry along s. The gap is a C1 cubic Hermite
// interpolant with three-point slopes (exact for quadratic gaps on any node spacing); the other strip
// quantities are interpolated linearly. Beyond the end nodes (up to half a strip width) the end pieces are
// extended.
#include <vector>

#include "conforma/patch.hpp"

namespace conforma {
namespace kp_detail {

class PatchInterpolant {
 public:
  // Validates the patch (InputError naming the field and strip).
  explicit PatchInterpolant(const PatchGeometry& patch);

  double gap(double s) const;
  double curvature(double s) const { return Linear(patch_.longitudinal_curvature_per_m, s); }
  double alpha(double s) const { return has_alpha_ ? Linear(patch_.alpha_rad, s) : 0.0; }
  double x_offset(double s) const { return has_x_offset_ ? Linear(patch_.x_offset_m, s) : 0.0; }
  bool has_x_offset() const { return has_x_offset_; }

  double domain_low() const { return domain_low_; }
  double domain_high() const { return domain_high_; }
  const std::vector<double>& nodes() const { return patch_.s_m; }
  const std::vector<double>& node_gaps() const { return patch_.gap_m; }

  // Location of the smallest gap: the lowest node refined by the parabola through its neighbours (computed once).
  double MinimumGapLocation() const { return minimum_gap_location_; }

 private:
  // i with nodes[i] <= s < nodes[i+1], clamped to [0, n-2]: a guess from the mean node spacing, corrected by
  // stepping (O(1) for the near-uniform strips of a PatchGeometry, exact for any increasing nodes).
  size_t Segment(double s) const;
  double Linear(const std::vector<double>& values, double s) const;
  double LocateMinimumGap() const;

  const PatchGeometry& patch_;
  std::vector<double> slope_;
  bool has_alpha_ = false;
  bool has_x_offset_ = false;
  double domain_low_ = 0.0;
  double domain_high_ = 0.0;
  double inverse_mean_spacing_ = 0.0;
  double minimum_gap_location_ = 0.0;
};

}  // namespace kp_detail
}  // namespace conforma
