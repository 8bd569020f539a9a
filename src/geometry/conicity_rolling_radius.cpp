// Delta r(y) sweep by continuation of the rigid wheelset equilibrium (conicity.hpp).
#include <algorithm>
#include <cmath>

#include "conforma/conicity.hpp"
#include "conforma/error.hpp"

namespace conforma {

RollingRadiusDifferenceCurve ComputeRollingRadiusDifference(const WheelsetTrackGeometry& geometry,
                                                            std::vector<double> lateral_m, double yaw_rad,
                                                            const EquilibriumOptions& options) {
  for (size_t i = 0; i < lateral_m.size(); ++i) require_finite(lateral_m[i], "lateral_m");
  std::sort(lateral_m.begin(), lateral_m.end());
  const size_t n = lateral_m.size();
  RollingRadiusDifferenceCurve c;
  c.lateral_m = lateral_m;
  c.delta_r_m.assign(n, 0.0);
  c.roll_rad.assign(n, 0.0);
  c.vertical_m.assign(n, 0.0);
  c.left_wheel_y_m.assign(n, 0.0);
  c.right_wheel_y_m.assign(n, 0.0);
  c.status.assign(n, EquilibriumStatus::NoContact);
  if (n == 0) return c;
  size_t start = 0;
  for (size_t i = 1; i < n; ++i)
    if (std::abs(lateral_m[i]) < std::abs(lateral_m[start])) start = i;
  auto solve = [&](size_t i, const WheelsetPose& guess) {
    const EquilibriumResult r = geometry.SolveRigidEquilibrium(lateral_m[i], yaw_rad, guess, options);
    c.status[i] = r.status;
    c.delta_r_m[i] = r.rolling_radius_difference_m;
    c.roll_rad[i] = r.pose.roll_rad;
    c.vertical_m[i] = r.pose.vertical_m;
    if (!r.contact.wheel[0].points.empty()) c.left_wheel_y_m[i] = r.contact.wheel[0].points.front().wheel_profile_m.x();
    if (!r.contact.wheel[1].points.empty()) c.right_wheel_y_m[i] = r.contact.wheel[1].points.front().wheel_profile_m.x();
    return r.status == EquilibriumStatus::NoContact ? guess : r.pose;
  };
  const WheelsetPose first = solve(start, WheelsetPose{});
  WheelsetPose g = first;
  for (size_t i = start + 1; i < n; ++i) g = solve(i, g);
  g = first;
  for (size_t i = start; i-- > 0;) g = solve(i, g);
  return c;
}

}  // namespace conforma
