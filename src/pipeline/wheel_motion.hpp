#pragma once
// Rigid-body motion of a wheel relative to its (fixed) rail, in the side frame of geometry.hpp, for the
// local-slip computations of local_creepage.hpp. Private to the pipeline.
#include "conforma/creepage.hpp"
#include "conforma/geometry.hpp"
#include "conforma/local_creepage.hpp"

namespace conforma {

// WheelsetMotionInSideFrame (creepage.hpp) in the form local_creepage.hpp takes.
RigidBodyMotion WheelMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                       const WheelsetVelocity& velocity);

}  // namespace conforma
