#pragma once
// Rigid creepages (xi, eta, phi) of a wheel at a contact point from the wheelset velocities.
//
// Convention (Kalker / CONTACT, docs/physics-reference.md §2.1): creepage = velocity of the WHEEL material point
// relative to the rail at the contact point, divided by the forward speed V; spin = angular velocity of the
// wheel about the contact normal divided by V. Components in the contact frame of the side (right-side
// convention, as CONTACT reports the left wheel): x along the track (rolling direction), s along the rail
// profile towards the FIELD side, n the outward rail normal (contact angle delta, + towards the gauge side):
//     xi = v.x / V,   eta = v.s / V,   phi = omega.n / V   [1/m]
// so that, e.g., pure rolling at the nominal radius r0 on a contact of radius r gives xi = 1 - r / r0, a
// yaw psi gives eta = -sin(psi) cos(delta), and the rolling spin is phi = -sin(delta) / r0.
// For the right wheel the kinematics are mirrored into its side frame (geometry.hpp) so that both wheels
// report mirror-symmetric values. Checked against CONTACT's Manchester creepages
// (tests/test_manchester_geometry.cpp).
#include <Eigen/Core>

#include "conforma/geometry.hpp"

namespace conforma {

// Wheelset velocities in the track frame (geometry.hpp).
struct WheelsetVelocity {
  double forward_speed_m_s = 0.0;             // V along +x, m/s; > 0 for creepages (InputError otherwise)
  double lateral_velocity_m_s = 0.0;          // dy/dt (+ towards the left rail), m/s
  double yaw_rate_rad_s = 0.0;                // d(psi)/dt, rad/s
  double axle_angular_velocity_rad_s = 0.0;   // about the axle, rad/s, + rolling forwards (V / r0 for pure rolling)
};

// Rigid creepages at a contact point in the contact frame of the side (convention above).
struct Creepages {
  double longitudinal = 0.0;  // xi, dimensionless
  double lateral = 0.0;       // eta, dimensionless (+ towards the field side)
  double spin_per_m = 0.0;    // phi [1/m]
};

// Rigid-body motion of a wheel relative to its (fixed) rail, in the side frame of `side` (geometry.hpp; the right
// wheel mirrored): velocity of the wheelset centre v = (V, sigma dy/dt, 0) and angular velocity
// omega = sigma yaw_rate z + axle_rate * axle. The velocity of a wheel point P is v + omega x (P - centre).
struct SideFrameMotion {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();                    // wheelset centre, side frame, m
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();            // v of the centre, m/s
  Eigen::Vector3d angular_velocity_rad_per_s = Eigen::Vector3d::Zero();  // omega, rad/s
};
SideFrameMotion WheelsetMotionInSideFrame(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                          const WheelsetVelocity& velocity);

// wheel_point_m: the contact point on the wheel in the track frame (RigidContactPoint::wheel_point_m);
// contact_angle_rad: angle of the rail normal there (+ towards the gauge side). Throws InputError for a
// non-positive forward speed or non-finite input.
Creepages ComputeCreepages(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                           const WheelsetVelocity& velocity, const Eigen::Vector3d& wheel_point_m,
                           double contact_angle_rad);

}  // namespace conforma
