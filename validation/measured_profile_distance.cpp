// Simulated wheel profile at a measured km (blend of the bracketing wear steps) and its normal distance to a measured
// profile over the worn zone (measured_validation.hpp).
#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/validation/measured_validation.hpp"

namespace conforma {

const char* to_string(ProfileInterpolation mode) { return mode == ProfileInterpolation::Linear ? "linear" : "nearest"; }

const char* to_string(ProfileDistanceStatus status) {
  return status == ProfileDistanceStatus::Measured ? "measured" : "empty_zone";
}

void ProfileDistanceOptions::validate() const {
  require_positive(spacing_m, "ProfileDistanceOptions::spacing_m");
  require_non_negative(worn_zone_min_depth_m, "ProfileDistanceOptions::worn_zone_min_depth_m");
  if (lateral_range_m) {
    require_finite((*lateral_range_m)[0], "ProfileDistanceOptions::lateral_range_m[0]");
    require_finite((*lateral_range_m)[1], "ProfileDistanceOptions::lateral_range_m[1]");
    if (!((*lateral_range_m)[0] < (*lateral_range_m)[1]))
      throw InputError("ProfileDistanceOptions::lateral_range_m: y_min must be < y_max");
  }
}

Profile InterpolateProfile(const Profile& a, const Profile& b, double t) {
  if (a.empty() || b.empty()) throw InputError("InterpolateProfile: empty profile");
  if (!std::isfinite(t) || t < 0.0 || t > 1.0) throw InputError("InterpolateProfile: t must be in [0, 1]");
  if (t == 0.0) return a;
  std::vector<Eigen::Vector2d> points = a.samples();
  for (Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = b.position(b.closest_s(p));
    p += t * (q - p);
  }
  ProfileFitOptions fit;
  fit.smoothing_rms_m = 0.0;
  fit.sample_spacing_m = a.spacing();
  fit.function_of_y = false;  // keep a's arc-length order (a wheel profile folds back at the flange)
  return Profile::FromPoints(std::move(points), a.kind(), fit, "interpolated profile");
}

SimulatedProfile SimulatedProfileAt(const WearSimulationResult& result, double km, ProfileInterpolation mode) {
  // the same series as DimensionSeriesOf, with the profiles
  std::vector<const Profile*> profiles{&result.initial_wheel};
  std::vector<int> steps{0};
  std::vector<double> kms{0.0};
  const int last_rail = result.steps.empty() ? 0 : result.steps.back().rail_step;
  for (const WearStepRecord& r : result.steps) {
    if (r.rail_step != last_rail || !(r.km > kms.back())) continue;
    profiles.push_back(&r.wheel);
    steps.push_back(r.step);
    kms.push_back(r.km);
  }
  SimulatedProfile out;
  out.mode = mode;
  out.bracket = BracketKm(kms, km);
  out.step_before = steps[out.bracket.before];
  out.step_after = steps[out.bracket.after];
  out.km_before = kms[out.bracket.before];
  out.km_after = kms[out.bracket.after];
  if (out.bracket.status == InterpolationStatus::BeyondSimulation) return out;
  if (mode == ProfileInterpolation::Nearest || out.bracket.before == out.bracket.after) {
    const size_t k = out.bracket.weight <= 0.5 ? out.bracket.before : out.bracket.after;
    out.profile = *profiles[k];
    out.bracket.before = out.bracket.after = k;
    out.step_before = out.step_after = steps[k];
    out.km_before = out.km_after = kms[k];
    out.bracket.weight = 0.0;
    return out;
  }
  out.profile = InterpolateProfile(*profiles[out.bracket.before], *profiles[out.bracket.after], out.bracket.weight);
  return out;
}

ProfileDistanceResult MeasureProfileDistance(const Profile& simulated, const Profile& measured, const Profile& initial,
                                             const ProfileDistanceOptions& options) {
  options.validate();
  if (simulated.empty() || measured.empty()) throw InputError("MeasureProfileDistance: empty profile");
  if (!options.lateral_range_m && initial.empty())
    throw InputError("MeasureProfileDistance: the initial profile (worn zone) is empty and no lateral range is given");
  ProfileDistanceResult out;
  if (options.align_taping_line) {
    const std::optional<double> zs = simulated.height_at(0.0), zm = measured.height_at(0.0);
    if (!zs || !zm)
      throw InputError(std::string("MeasureProfileDistance: taping-line alignment needs both profiles at y = 0 (") +
                       (zs ? measured.source() : simulated.source()) + " does not reach it)");
    out.alignment_shift_m = *zs - *zm;
  }
  const Eigen::Vector2d shift(0.0, out.alignment_shift_m);  // measured + shift; applied to the query instead
  const double length_s = simulated.length(), length_m = measured.length(), length_i = initial.length();
  const int n = std::max(2, static_cast<int>(std::ceil(length_s / options.spacing_m)) + 1);
  const double end_tol = 1e-9;  // closest point at an end of a curve: the curve does not cover the sample
  double sum2 = 0.0, sum_signed = 0.0;
  out.zone_y_min_m = 1e300;
  out.zone_y_max_m = -1e300;
  for (int i = 0; i < n; ++i) {
    const double s = length_s * i / (n - 1);
    const Eigen::Vector2d q = simulated.position(s);
    bool in_zone;
    if (options.lateral_range_m) {
      in_zone = q[0] >= (*options.lateral_range_m)[0] && q[0] <= (*options.lateral_range_m)[1];
    } else {
      // depth of the simulated surface below the initial one, along the initial outward normal
      const double si = initial.closest_s(q);
      in_zone = si > end_tol && si < length_i - end_tol &&
                (initial.position(si) - q).dot(initial.normal(si)) > options.worn_zone_min_depth_m;
    }
    if (!in_zone) continue;
    const Eigen::Vector2d qm = q - shift;
    const double sm = measured.closest_s(qm);
    if (sm <= end_tol || sm >= length_m - end_tol) {
      ++out.outside_measurement;
      continue;
    }
    const Eigen::Vector2d d = measured.position(sm) - qm;  // along the measured normal at the closest point
    const double dist = d.norm();
    const double signed_dist = d.dot(simulated.normal(s)) >= 0.0 ? dist : -dist;
    ++out.points;
    out.sample_y_m.push_back(q[0]);
    out.sample_signed_distance_m.push_back(signed_dist);
    sum2 += dist * dist;
    sum_signed += signed_dist;
    if (dist > out.max_m) {
      out.max_m = dist;
      out.y_at_max_m = q[0];
    }
    out.zone_y_min_m = std::min(out.zone_y_min_m, q[0]);
    out.zone_y_max_m = std::max(out.zone_y_max_m, q[0]);
  }
  if (out.points == 0) {
    out.zone_y_min_m = out.zone_y_max_m = 0.0;
    return out;
  }
  out.status = ProfileDistanceStatus::Measured;
  out.rms_m = std::sqrt(sum2 / out.points);
  out.mean_signed_m = sum_signed / out.points;
  return out;
}

}  // namespace conforma
