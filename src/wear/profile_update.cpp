#include "conforma/profile_update.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(ProfileUpdateStatus status) {
  switch (status) {
    case ProfileUpdateStatus::Updated: return "updated";
    case ProfileUpdateStatus::NoWear: return "no wear";
    case ProfileUpdateStatus::InvalidProfile: return "invalid profile";
  }
  return "?";
}

namespace {

// A profile through points in the arc-length order of the profile they came from (not sorted by y).
Profile RefitInArcLengthOrder(std::vector<Eigen::Vector2d> points, ProfileKind kind, double spacing_m,
                              double smoothing_rms_m, const std::string& context) {
  ProfileFitOptions fit;
  fit.smoothing_rms_m = smoothing_rms_m;
  fit.sample_spacing_m = spacing_m;
  fit.function_of_y = false;
  return Profile::FromPoints(std::move(points), kind, fit, context);
}

}  // namespace

// paper 003 eqs. 18-19, paper 001 eq. 30: P_new(s) = P(s) - d(s) n(s), then arc-length re-parametrisation
Profile RemoveAlongNormal(const Profile& profile, const WearDistribution& depth, double output_spacing_m,
                          const std::string& context) {
  if (profile.empty()) throw InputError(context + ": the profile is empty");
  require_non_negative(output_spacing_m, "output_spacing_m");
  if (depth.size() < 2 || std::abs(depth.length_m() - profile.length()) > 1e-9 + 1e-9 * profile.length()) {
    std::ostringstream m;
    m << context << ": depth grid length " << depth.length_m() * 1e3 << " mm does not match the profile arc length "
      << profile.length() * 1e3 << " mm";
    throw InputError(m.str());
  }
  std::vector<Eigen::Vector2d> points(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) {
    const double s = depth.s(i), d = depth.depth_m[i];
    if (!std::isfinite(d)) throw InputError(context + ": depth at node " + std::to_string(i) + " is not finite");
    points[i] = profile.position(s) - d * profile.normal(s);
  }
  return RefitInArcLengthOrder(std::move(points), profile.kind(),
                               output_spacing_m > 0.0 ? output_spacing_m : profile.spacing(), 0.0, context);
}

// RMS distance of the spline refitted through a cut profile to the cut points [m]
constexpr double kOverhangCutRoundingRms = 5e-6;

double CutOverhangs(std::vector<Eigen::Vector2d>* points) {
  std::vector<Eigen::Vector2d>& p = *points;
  double area = 0.0, running_min = std::numeric_limits<double>::infinity();
  for (size_t k = p.size(); k-- > 0;) {
    if (p[k].x() > running_min) {
      // horizontal strip between the old and the new point, over the segment's height (trapezoid in z)
      const double dz = k + 1 < p.size() ? std::abs(p[k + 1].y() - p[k].y()) : 0.0;
      area += (p[k].x() - running_min) * dz;
      p[k].x() = running_min;
    }
    running_min = std::min(running_min, p[k].x());
  }
  return area;
}

namespace {

// Reversals of the lateral coordinate y along the polyline (a profile single-valued in y has none), with
// hysteresis: a reversal counts only once y has moved back by more than `tolerance` from its running extreme in the
// current direction. Sub-tolerance wiggles of a vertical face (the spline refit after an overhang cut leaves
// ~0.5 um) are not folds; a face leaning back by more than the tolerance is, however gently it leans.
int count_y_folds(const std::vector<Eigen::Vector2d>& p, double tolerance) {
  if (p.empty()) return 0;
  int folds = 0, direction = 0;  // +1: y increasing, -1: decreasing, 0: not yet moved beyond the tolerance
  double low = p[0].x(), high = p[0].x();  // running extremes since the last reversal
  for (size_t i = 1; i < p.size(); ++i) {
    const double y = p[i].x();
    low = std::min(low, y);
    high = std::max(high, y);
    if (direction >= 0 && y < high - tolerance) {  // moved back from the maximum
      if (direction > 0) ++folds;
      direction = -1;
      low = high = y;
    } else if (direction <= 0 && y > low + tolerance) {  // moved back from the minimum
      if (direction < 0) ++folds;
      direction = 1;
      low = high = y;
    }
  }
  return folds;
}

}  // namespace

ProfileValidity CheckProfileValidity(const Profile& updated, const Profile& previous, const ProfileValidityOptions& o) {
  require_positive(o.max_curvature_1_m, "max_curvature_1_m");
  require_positive(o.fold_tolerance_m, "fold_tolerance_m");
  ProfileValidity v;
  const auto pts = updated.samples();
  for (const auto& p : pts)
    if (!p.allFinite()) {
      v.valid = false;
      v.reason = "the profile has non-finite points";
      return v;
    }
  if (auto hit = find_self_intersection(pts)) {
    std::ostringstream m;
    m << "the profile self-intersects near y = " << pts[hit->first].x() * 1e3 << " mm and y = "
      << pts[hit->second].x() * 1e3 << " mm";
    v.valid = false;
    v.reason = m.str();
    return v;
  }
  v.y_folds_before = count_y_folds(previous.samples(), o.fold_tolerance_m);
  v.y_folds_after = count_y_folds(pts, o.fold_tolerance_m);
  if (v.y_folds_after > v.y_folds_before) {
    v.valid = false;
    v.reason = "the profile is no longer single-valued in y: " + std::to_string(v.y_folds_after) +
               " folds, the previous profile had " + std::to_string(v.y_folds_before);
    return v;
  }
  // curvature: sampled at the new profile's nodes; old curvature near the corresponding arc length
  const double h = updated.spacing(), ratio = previous.length() / updated.length(), window = 2e-3;
  const double hp = previous.spacing();
  for (size_t i = 0; i < pts.size(); ++i) {
    const double s = h * i;
    const double kappa = std::abs(updated.curvature(s));
    v.max_abs_curvature_1_m = std::max(v.max_abs_curvature_1_m, kappa);
    if (kappa <= o.max_curvature_1_m) continue;
    double old_max = 0.0;
    for (double so = s * ratio - window; so <= s * ratio + window; so += hp)
      old_max = std::max(old_max, std::abs(previous.curvature(so)));
    if (kappa > o.max_curvature_1_m && (old_max <= o.max_curvature_1_m || kappa > 1.2 * old_max)) {
      std::ostringstream m;
      m << "kink: |curvature| = " << kappa << " 1/m (radius " << 1e3 / kappa << " mm) at s = " << s * 1e3
        << " mm, y = " << pts[i].x() * 1e3 << " mm exceeds the limit " << o.max_curvature_1_m
        << " 1/m (previous profile there: " << old_max << " 1/m)";
      v.valid = false;
      v.reason = m.str();
    }
  }
  return v;
}

ProfileUpdateResult UpdateProfile(const Profile& profile, const WearDistribution& accumulated,
                                  double distance_represented_m, const ProfileUpdateOptions& o) {
  require_positive(distance_represented_m, "distance_represented_m");
  require_positive(o.max_depth_per_step_m, "max_depth_per_step_m");
  if (!(o.max_distance_step_m > 0.0)) throw InputError("max_distance_step_m must be > 0");
  const std::string step = "wear step " + std::to_string(o.step_index) + " (" + to_string(profile.kind()) + ")";
  if (profile.empty()) throw InputError(step + ": the profile is empty");
  if (accumulated.size() < 2 || std::abs(accumulated.length_m() - profile.length()) > 1e-9 + 1e-9 * profile.length()) {
    std::ostringstream m;
    m << step << ": depth grid length " << accumulated.length_m() * 1e3
      << " mm does not match the profile arc length " << profile.length() * 1e3 << " mm";
    throw InputError(m.str());
  }
  ProfileUpdateResult r;
  r.profile = profile;
  // 1. mass-conserving smoothing (before scaling; S is positively homogeneous)
  r.smoothing = SmoothDepthMassConserving(accumulated, o.smoothing);
  const double smoothed_max = r.smoothing.depth.max_depth_m();
  if (!(smoothed_max > 0.0)) {
    r.status = ProfileUpdateStatus::NoWear;
    r.message = step + ": no wear to remove";
    r.removed_depth = r.smoothing.depth;
    return r;
  }
  // 2. scaling: the largest depth of the step equals the cap (paper 003 §6), km_step = km_sim * factor
  r.scale_factor = std::min(o.max_depth_per_step_m / smoothed_max, o.max_distance_step_m / distance_represented_m);
  r.distance_step_m = distance_represented_m * r.scale_factor;
  r.removed_depth = r.smoothing.depth;
  for (double& v : r.removed_depth.depth_m) v *= r.scale_factor;
  r.max_depth_m = r.removed_depth.max_depth_m();
  r.removed_area_m2 = r.removed_depth.area_m2();
  // 3. removal along the normal and re-parametrisation, 4. validity
  Profile updated;
  try {
    updated = RemoveAlongNormal(profile, r.removed_depth, o.output_spacing_m, step);
  } catch (const InputError& e) {
    r.status = ProfileUpdateStatus::InvalidProfile;
    r.message = e.what();
    return r;
  }
  r.validity = CheckProfileValidity(updated, profile, o.validity);
  if (!r.validity.valid && o.cut_overhangs && r.validity.y_folds_before == 0 &&
      r.validity.y_folds_after > r.validity.y_folds_before) {
    std::vector<Eigen::Vector2d> points = updated.samples();
    r.overhang_cut_area_m2 = CutOverhangs(&points);
    try {  // the rounding keeps the corners of the cut from being kinks
      updated = RefitInArcLengthOrder(std::move(points), profile.kind(), updated.spacing(), kOverhangCutRoundingRms, step);
      r.validity = CheckProfileValidity(updated, profile, o.validity);
    } catch (const InputError& e) {
      r.validity.valid = false;
      r.validity.reason = std::string("after cutting the overhang: ") + e.what();
    }
  }
  if (!r.validity.valid) {
    r.status = ProfileUpdateStatus::InvalidProfile;
    r.message = step + ": updated profile is invalid: " + r.validity.reason;
    return r;
  }
  r.status = ProfileUpdateStatus::Updated;
  r.profile = std::move(updated);
  return r;
}

}  // namespace conforma
