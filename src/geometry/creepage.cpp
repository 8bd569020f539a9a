// Rigid creepages at a contact point (creepage.hpp).
#include "conforma/creepage.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "conforma/error.hpp"

namespace conforma {

SideFrameMotion WheelsetMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                          const WheelsetVelocity& velocity) {
  const double sigma = side_sign(side);
  const WheelsetTrackGeometry::Frame f = geometry.SideFrame(side, pose);
  SideFrameMotion m;
  m.centre_m = f.centre;
  m.velocity_m_per_s = Eigen::Vector3d(velocity.forward_speed_m_s, sigma * velocity.lateral_velocity_m_s, 0.0);
  // body axle direction (towards the field side) is the rotation's second column
  m.angular_velocity_rad_per_s =
      sigma * velocity.yaw_rate_rad_s * Eigen::Vector3d::UnitZ() + velocity.axle_angular_velocity_rad_s * f.rotation.col(1);
  return m;
}

Creepages ComputeCreepages(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                           const WheelsetVelocity& velocity, const Eigen::Vector3d& wheel_point_m,
                           double contact_angle_rad) {
  require_positive(velocity.forward_speed_m_s, "WheelsetVelocity.forward_speed_m_s");
  require_finite(velocity.lateral_velocity_m_s, "WheelsetVelocity.lateral_velocity_m_s");
  require_finite(velocity.yaw_rate_rad_s, "WheelsetVelocity.yaw_rate_rad_s");
  require_finite(velocity.axle_angular_velocity_rad_s, "WheelsetVelocity.axle_angular_velocity_rad_s");
  require_finite(contact_angle_rad, "contact_angle_rad");
  if (!wheel_point_m.allFinite()) throw InputError("ComputeCreepages: wheel_point_m is not finite");
  const double sigma = side_sign(side);
  // everything in the side frame (mirror image for the right wheel, which then rolls like a left wheel)
  const SideFrameMotion m = WheelsetMotionInSideFrame(geometry, side, pose, velocity);
  const Eigen::Vector3d p(wheel_point_m(0), sigma * wheel_point_m(1), wheel_point_m(2));
  const Eigen::Vector3d& omega = m.angular_velocity_rad_per_s;
  const Eigen::Vector3d v = m.velocity_m_per_s + omega.cross(p - m.centre_m);  // rail at rest in the track frame
  const double sd = std::sin(contact_angle_rad), cd = std::cos(contact_angle_rad);
  const Eigen::Vector3d n(0.0, -sd, cd), s(0.0, cd, sd);
  const double V = velocity.forward_speed_m_s;
  Creepages c;
  c.longitudinal = v(0) / V;
  c.lateral = v.dot(s) / V;
  c.spin_per_m = omega.dot(n) / V;
  return c;
}

}  // namespace conforma
