// The WheelContactCache keys from the option field tables (wheel_contact_key.hpp).
#include "wheel_contact_key.hpp"

#include <cstdint>

#include "conforma/wheel_contact_fields.hpp"

namespace conforma {

namespace {
// Appends every visited option field as a double (enums by their value, bools as 0 or 1).
struct AppendToKey {
  std::vector<double>& key;
  template <class T>
  void operator()(const char*, const T& value) const {
    key.push_back(static_cast<double>(value));
  }
};
}  // namespace

std::vector<double> NormalCacheKey(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                   const WheelContactOptions& options) {
  std::vector<double> key = {static_cast<double>(reinterpret_cast<std::uintptr_t>(&geometry)),
                             static_cast<double>(side_index(side)), pose.lateral_m, pose.vertical_m, pose.roll_rad,
                             pose.yaw_rad};
  VisitNormalOptionFields(options, AppendToKey{key});
  return key;
}

std::vector<double> ReportCacheKey(std::vector<double> normal_key, const WheelsetVelocity& velocity,
                                   const WheelContactOptions& options) {
  normal_key.insert(normal_key.end(), {velocity.forward_speed_m_s, velocity.lateral_velocity_m_s,
                                       velocity.yaw_rate_rad_s, velocity.axle_angular_velocity_rad_s});
  VisitTangentialOptionFields(options, AppendToKey{normal_key});
  return normal_key;
}

}  // namespace conforma
