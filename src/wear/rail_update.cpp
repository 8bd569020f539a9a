#include "conforma/rail_update.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "conforma/error.hpp"

namespace conforma {
namespace {

std::vector<double> normalised_weights(const std::vector<double>& weights, size_t n, const char* what) {
  if (weights.empty()) return std::vector<double>(n, 1.0 / static_cast<double>(n));
  if (weights.size() != n)
    throw InputError(std::string(what) + ": " + std::to_string(n) + " profiles but " + std::to_string(weights.size()) +
                     " weights");
  double sum = 0.0;
  for (double w : weights) {
    require_non_negative(w, what);
    sum += w;
  }
  if (std::abs(sum - 1.0) > 1e-9)
    throw InputError(std::string(what) + ": weights must sum to 1, got " + MessageNumber(sum, 12));
  return weights;
}

// Signed distance t along -n from q to the profile v on the line q + u t_dir (u free): the point of v
// on the normal line of the base at q. Returns t and the remaining residual of the line condition.
std::pair<double, double> distance_along_normal(const Profile& v, const Eigen::Vector2d& q, const Eigen::Vector2d& tangent,
                                                const Eigen::Vector2d& normal) {
  double sigma = v.closest_s(q);
  Eigen::Vector2d p = v.position(sigma);
  for (int it = 0; it < 20; ++it) {
    const double f = (p - q).dot(tangent);
    const double df = v.tangent(sigma).dot(tangent);
    if (std::abs(df) < 1e-12) break;
    const double next = std::clamp(sigma - f / df, 0.0, v.length());
    const bool done = std::abs(next - sigma) < 1e-13;
    sigma = next;
    p = v.position(sigma);
    if (done) break;
  }
  double residual = (p - q).dot(tangent);
  if (std::abs(residual) > 1e-10 && (sigma == 0.0 || sigma == v.length())) {
    // beyond an end of v: extend its end tangent
    const Eigen::Vector2d te = v.tangent(sigma);
    const double denom = te.dot(tangent);
    if (std::abs(denom) > 1e-12) {
      p -= (residual / denom) * te;
      residual = (p - q).dot(tangent);
    }
  }
  return {(q - p).dot(normal), std::abs(residual)};
}

}  // namespace

NormalAverageResult AverageAlongNormals(const Profile& base, const std::vector<Profile>& profiles,
                                        const std::vector<double>& weights, double output_spacing_m) {
  if (base.empty()) throw InputError("normal average: the base profile is empty");
  if (profiles.empty()) throw InputError("normal average: no profiles to average");
  for (const Profile& p : profiles)
    if (p.empty()) throw InputError("normal average: a profile to average is empty");
  const std::vector<double> w = normalised_weights(weights, profiles.size(), "normal average");
  NormalAverageResult r;
  r.mean_depth = WearDistribution::Zero(base.length(), base.spacing());
  std::vector<Eigen::Vector2d> points(r.mean_depth.size());
  for (size_t i = 0; i < r.mean_depth.size(); ++i) {
    const double s = r.mean_depth.s(i);
    const Eigen::Vector2d q = base.position(s), t = base.tangent(s), n = base.normal(s);
    double mean = 0.0;
    for (size_t j = 0; j < profiles.size(); ++j) {
      const auto [dist, residual] = distance_along_normal(profiles[j], q, t, n);
      mean += w[j] * dist;
      r.max_intersection_residual_m = std::max(r.max_intersection_residual_m, residual);
    }
    r.mean_depth.depth_m[i] = mean;
    points[i] = q - mean * n;
  }
  ProfileFitOptions fit;
  fit.sample_spacing_m = output_spacing_m > 0.0 ? output_spacing_m : base.spacing();
  fit.function_of_y = false;
  r.profile = Profile::FromPoints(std::move(points), base.kind(), fit, "normal average");
  return r;
}

RemovedAlongNormals MeasureRemovedAlongNormals(const Profile& base, const Profile& worn) {
  if (base.empty() || worn.empty()) throw InputError("removed material: empty profile");
  RemovedAlongNormals r;
  r.depth = WearDistribution::Zero(base.length(), base.spacing());  // the node grid of AverageAlongNormals
  for (size_t i = 0; i < r.depth.size(); ++i) {
    const double s = r.depth.s(i);
    const auto [t, residual] = distance_along_normal(worn, base.position(s), base.tangent(s), base.normal(s));
    r.depth.depth_m[i] = t;
    r.max_intersection_residual_m = std::max(r.max_intersection_residual_m, residual);
  }
  r.area_m2 = r.depth.area_m2();
  r.max_depth_m = std::max(0.0, r.depth.max_depth_m());
  return r;
}

RailStepResult UpdateRail(const Profile& rail, const std::vector<WearDistribution>& wear,
                          const std::vector<double>& weights, double passages_represented, const RailStepOptions& o) {
  const std::string step = "rail step " + std::to_string(o.step_index);
  RailStepResult r;
  r.rail = rail;
  if (o.keep_rail_fixed) {
    r.status = ProfileUpdateStatus::NoWear;
    r.message = step + ": rail kept fixed";
    return r;
  }
  if (wear.empty()) throw InputError(step + ": no rail wear distributions given");
  require_positive(passages_represented, "passages_represented");
  require_positive(o.max_depth_per_step_m, "rail max_depth_per_step_m");
  const std::vector<double> w = normalised_weights(weights, wear.size(), "rail update");
  r.weights = w;
  // smoothing of each distribution (mass-conserving, positively homogeneous) and their weighted mean
  std::vector<WearDistribution> smoothed;
  smoothed.reserve(wear.size());
  for (const WearDistribution& d : wear) smoothed.push_back(SmoothDepthMassConserving(d, o.smoothing).depth);
  WearDistribution mean = smoothed.front();
  std::fill(mean.depth_m.begin(), mean.depth_m.end(), 0.0);
  for (size_t j = 0; j < smoothed.size(); ++j) mean.add(smoothed[j], w[j]);
  const double mean_max = mean.max_depth_m();
  if (!(mean_max > 0.0)) {
    r.status = ProfileUpdateStatus::NoWear;
    r.message = step + ": no rail wear, rail unchanged";
    r.mean_removed_depth = mean;
    return r;
  }
  r.scale_factor = std::min(o.max_depth_per_step_m / mean_max, o.max_passages_per_step / passages_represented);
  r.passages_step = passages_represented * r.scale_factor;
  try {
    for (size_t j = 0; j < smoothed.size(); ++j) {
      WearDistribution d = smoothed[j];
      for (double& v : d.depth_m) v *= r.scale_factor;
      r.virtual_rails.push_back(
          RemoveAlongNormal(rail, d, o.output_spacing_m, step + ", virtual rail " + std::to_string(j)));
    }
    NormalAverageResult avg = AverageAlongNormals(rail, r.virtual_rails, w, o.output_spacing_m);
    r.mean_removed_depth = std::move(avg.mean_depth);
    r.validity = CheckProfileValidity(avg.profile, rail, o.validity);
    if (!r.validity.valid) {
      r.status = ProfileUpdateStatus::InvalidProfile;
      r.message = step + ": averaged rail is invalid: " + r.validity.reason;
      return r;
    }
    r.rail = std::move(avg.profile);
  } catch (const InputError& e) {
    r.status = ProfileUpdateStatus::InvalidProfile;
    r.message = e.what();
    return r;
  }
  r.status = ProfileUpdateStatus::Updated;
  return r;
}

}  // namespace conforma
