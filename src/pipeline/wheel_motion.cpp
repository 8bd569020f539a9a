#include "pipeline/wheel_motion.hpp"

namespace conforma {

RigidBodyMotion WheelMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                       const WheelsetVelocity& velocity) {
  const double sigma = side_sign(side);
  const WheelsetTrackGeometry::Frame f = geometry.SideFrame(side, pose);
  RigidBodyMotion m;
  m.origin_m = f.centre;
  m.velocity_m_per_s = Eigen::Vector3d(velocity.forward_speed_m_s, sigma * velocity.lateral_velocity_m_s, 0.0);
  m.angular_velocity_rad_per_s =
      sigma * velocity.yaw_rate_rad_s * Eigen::Vector3d::UnitZ() + velocity.axle_angular_velocity_rad_s * f.rotation.col(1);
  m.rolling_speed_m_per_s = velocity.forward_speed_m_s;
  return m;
}

}  // namespace conforma
