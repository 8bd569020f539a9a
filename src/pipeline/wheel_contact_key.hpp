#pragma once
// The WheelContactCache keys (wheel_contact.cpp), built from the option field tables of
// conforma/wheel_contact_fields.hpp: a new option that is visited there is in the keys (and the header's
// static_assert fails the build for one that is not visited).
#include <vector>

#include "conforma/wheel_contact.hpp"

namespace conforma {

// Key of the normal stage: everything SolveNormalStage reads -- the geometry's identity (its address), the side,
// the pose and VisitNormalOptionFields, in that order.
std::vector<double> NormalCacheKey(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                   const WheelContactOptions& options);

// Key of a whole report: the normal key, then the velocity and VisitTangentialOptionFields.
std::vector<double> ReportCacheKey(std::vector<double> normal_key, const WheelsetVelocity& velocity,
                                   const WheelContactOptions& options);

}  // namespace conforma
