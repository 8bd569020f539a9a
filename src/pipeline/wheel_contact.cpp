// One wheel's contact from pose to per-patch forces (wheel_contact.hpp).
#include "conforma/wheel_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "conforma/error.hpp"
#include "wheel_contact_key.hpp"
#include "wheel_contact_stages.hpp"

namespace conforma {

bool BalancesTotalVerticalForce(const WheelContactOptions& options) {
  return options.load_balance != LoadBalance::Pressure && options.vertical_load_N > 0.0 && options.solve_tangential;
}

const PatchReport* MainPatch(const WheelContactReport& report) {
  const PatchReport* main = nullptr;
  for (const PatchReport& p : report.patches)
    if (!main || p.fn_N > main->fn_N) main = &p;
  return main;
}

double BalancedVerticalForce(const WheelContactReport& report, const WheelContactOptions& options) {
  return BalancesTotalVerticalForce(options) ? report.vertical_force_N : report.pressure_vertical_force_N;
}

const char* to_string(WheelContactStatus status) {
  switch (status) {
    case WheelContactStatus::Ok: return "ok";
    case WheelContactStatus::NoContact: return "no_contact";
    case WheelContactStatus::NotConverged: return "not_converged";
  }
  return "?";
}

const char* to_string(LoadBalance balance) {
  switch (balance) {
    case LoadBalance::Total: return "total";
    case LoadBalance::Pressure: return "pressure";
    case LoadBalance::TotalConsistent: return "total-consistent";
  }
  return "?";
}

LoadBalance ParseLoadBalance(const std::string& name) {
  if (name == "total") return LoadBalance::Total;
  if (name == "pressure") return LoadBalance::Pressure;
  if (name == "total-consistent") return LoadBalance::TotalConsistent;
  throw InputError("load balance: unknown name '" + name + "' (expected total, pressure or total-consistent)");
}

void WheelContactOptions::validate() const {
  material.validate();
  require_non_negative(friction_coefficient, "friction_coefficient");
  if (!friction_law.is_constant()) friction_law.validate();
  require_finite(vertical_load_N, "vertical_load_N");
  RequireWheelLoad(vertical_load_N, "vertical_load_N");
  require_positive(load_tolerance, "load_tolerance");
  require_positive(candidate_strip_width_m, "candidate_strip_width_m");
  require_non_negative(patch_combine_distance_m, "patch_combine_distance_m");
  require_finite(conformity_threshold_deg, "conformity_threshold_deg");
  if (fastsim_elements < 2 || fastsim_elements > kMaxFastsimElements)
    throw InputError("option 'fastsim_elements' must lie in [2, " + std::to_string(kMaxFastsimElements) + "], got " +
                     std::to_string(fastsim_elements));
  if (kp_strips < 3 || kp_strips > kMaxKpStrips)
    throw InputError("option 'kp_strips' must lie in [3, " + std::to_string(kMaxKpStrips) + "], got " +
                     std::to_string(kp_strips));
  require_positive(exact_element_size_m, "exact_element_size_m");
  if (exact_max_elements < 1) throw InputError("option 'exact_max_elements' must be >= 1");
  auto_selection.validate();
  if (creepages_given) {
    require_finite(creepages.longitudinal, "creepages.xi");
    require_finite(creepages.lateral, "creepages.eta");
    require_finite(creepages.spin_per_m, "creepages.phi_per_m");
    const std::pair<double, const char*> given[] = {{creepages.longitudinal, "creepages.xi"},
                                                    {creepages.lateral, "creepages.eta"},
                                                    {creepages.spin_per_m, "creepages.phi_per_m"}};
    for (const auto& [value, name] : given)
      if (std::fabs(value) > kMaxGivenCreepage) {
        char text[200];
        std::snprintf(text, sizeof text, "%s = %.6g is beyond +-%g: not a creepage (full slip sets in far below)",
                      name, value, kMaxGivenCreepage);
        throw InputError(text);
      }
  }
}

void RequireRollingVelocity(const WheelsetVelocity& v, double nominal_radius_m, const std::string& where) {
  require_positive(v.forward_speed_m_s, (where + ".forward_speed_m_s").c_str());
  require_finite(v.lateral_velocity_m_s, (where + ".lateral_velocity_m_s").c_str());
  require_finite(v.yaw_rate_rad_s, (where + ".yaw_rate_rad_s").c_str());
  require_finite(v.axle_angular_velocity_rad_s, (where + ".axle_angular_velocity_rad_s").c_str());
  const double V = v.forward_speed_m_s;
  const std::pair<double, const char*> rigid[] = {
      {v.lateral_velocity_m_s / V, "lateral_velocity_m_s / forward_speed_m_s"},
      {v.axle_angular_velocity_rad_s * nominal_radius_m / V - 1.0, "axle_angular_velocity_rad_s * r0 / forward_speed_m_s - 1"},
      {v.yaw_rate_rad_s / V, "yaw_rate_rad_s / forward_speed_m_s [1/m]"}};
  for (const auto& [value, name] : rigid)
    if (!(std::fabs(value) <= kMaxGivenCreepage)) {
      char text[320];
      std::snprintf(text, sizeof text, "%s: %s = %.6g is beyond +-%g: the creepages would be beyond any slip (unit?)",
                    where.c_str(), name, value, kMaxGivenCreepage);
      throw InputError(text);
    }
}

void RequireWheelLoad(double load_N, const std::string& name) {
  if (!(load_N <= kMaxWheelLoadN)) {
    char text[240];
    std::snprintf(text, sizeof text, "%s = %.6g N is above %.6g N (10 MN, ~1,000 t on one wheel): not a wheel load "
                  "(unit?)", name.c_str(), load_N, kMaxWheelLoadN);
    throw InputError(text);
  }
}

void RequireApproach(double approach_m, const std::string& name) {
  if (std::isfinite(approach_m) && std::fabs(approach_m) <= kMaxApproach_m) return;
  char text[240];
  std::snprintf(text, sizeof text,
                "%s = %g m: the push-down below rigid contact is an elastic approach, within +-%g m (tens of "
                "micrometres for a wheel load)", name.c_str(), approach_m, kMaxApproach_m);
  throw InputError(text);
}

FrictionLaw WheelContactOptions::effective_friction_law() const {
  return friction_law.is_constant() ? FrictionLaw::Constant(friction_coefficient) : friction_law;
}

using namespace wheel_contact_detail;

struct WheelContactCache::Impl {
  size_t max_entries = 0;
  mutable std::mutex mutex;
  std::map<std::vector<double>, std::shared_ptr<const NormalStage>> normal;
  std::map<std::vector<double>, std::shared_ptr<const WheelContactReport>> reports;
  Stats stats;
};

WheelContactCache::WheelContactCache(size_t max_entries) : impl_(std::make_unique<Impl>()) {
  impl_->max_entries = std::max<size_t>(1, max_entries);
}
WheelContactCache::~WheelContactCache() = default;

WheelContactCache::Stats WheelContactCache::stats() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->stats;
}

WheelContactReport SolveWheelContact(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                     const WheelsetVelocity& velocity, const WheelContactOptions& options) {
  options.validate();
  return FinishWheelContact(SolveNormalStage(geometry, side, pose, velocity, options), geometry, side, velocity,
                            options);
}

WheelContactReport SolveWheelContactCached(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                           const WheelsetVelocity& velocity, const WheelContactOptions& options,
                                           WheelContactCache& cache) {
  options.validate();
  WheelContactCache::Impl& c = *cache.impl_;
  // With total-force load control the normal stage holds the tangential solution too (it reads everything): it is
  // keyed as the whole report, and a changed velocity or tangential option solves it again.
  const std::vector<double> report_key = ReportCacheKey(NormalCacheKey(geometry, side, pose, options), velocity, options);
  const std::vector<double> normal_key =
      BalancesTotalVerticalForce(options) ? report_key : NormalCacheKey(geometry, side, pose, options);
  // a NaN cannot be a map key (no ordering): such calls go uncached (and throw where the pipeline throws)
  for (double v : report_key)
    if (!std::isfinite(v)) return SolveWheelContact(geometry, side, pose, velocity, options);
  std::shared_ptr<const NormalStage> stage;
  {
    std::lock_guard<std::mutex> lock(c.mutex);
    const auto r = c.reports.find(report_key);
    if (r != c.reports.end()) {
      ++c.stats.report_hits;
      return *r->second;
    }
    const auto s = c.normal.find(normal_key);
    if (s != c.normal.end()) {
      ++c.stats.normal_hits;
      stage = s->second;
    } else {
      ++c.stats.misses;
    }
  }
  // solved outside the lock (two threads may solve the same pose at once: same result, one is kept)
  if (!stage) stage = std::make_shared<const NormalStage>(SolveNormalStage(geometry, side, pose, velocity, options));
  auto report = std::make_shared<const WheelContactReport>(FinishWheelContact(*stage, geometry, side, velocity, options));
  std::lock_guard<std::mutex> lock(c.mutex);
  if (c.normal.size() >= c.max_entries) c.normal.clear();  // bounded memory; clearing keeps results exact
  if (c.reports.size() >= c.max_entries) c.reports.clear();
  c.normal.emplace(normal_key, stage);
  c.reports.emplace(report_key, report);
  return *report;
}

}  // namespace conforma
