#include "wheel_motion.hpp"

namespace conforma {

RigidBodyMotion WheelMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                       const WheelsetVelocity& velocity) {
  const SideFrameMotion s = WheelsetMotionInSideFrame(geometry, side, pose, velocity);
  RigidBodyMotion m;
  m.origin_m = s.centre_m;
  m.velocity_m_per_s = s.velocity_m_per_s;
  m.angular_velocity_rad_per_s = s.angular_velocity_rad_per_s;
  m.rolling_speed_m_per_s = velocity.forward_speed_m_s;
  return m;
}

}  // namespace conforma
