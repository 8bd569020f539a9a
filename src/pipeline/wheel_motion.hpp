#pragma once
// Rigid-body motion of a wheel relative to its (fixed) rail, in the side frame of geometry.hpp, for the
// local-slip computations of local_creepage.hpp. Private to the pipeline.
#include "conforma/creepage.hpp"
#include "conforma/geometry.hpp"
#include "conforma/local_creepage.hpp"

namespace conforma {

// v = (V, sigma dy/dt, 0) at the wheelset centre; omega = sigma yaw_rate z + axle_rate * axle (creepage.hpp).
RigidBodyMotion WheelMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                       const WheelsetVelocity& velocity);

}  // namespace conforma
