#pragma once
// Rolling speed of a wheelset's axle from its torque balance (docs/physics-reference.md §12.3): the axle angular
// velocity Omega at which the longitudinal contact forces of both wheels balance the applied drive torque,
//   sum over the patches of both wheels  F_x r_p  =  T_applied      (T > 0 traction, < 0 braking, 0 free rolling)
// with F_x the longitudinal force on the wheel in its patch frame and r_p the patch's rolling radius. The
// contact torque rises with Omega (a faster wheel is driven by the rail), so the root is bracketed around the
// given start and found by SolveIncreasingRoot (root_finding.hpp). The quasi-static curving solves the same
// equation as one of its unknowns; this is the one-unknown form for a wheelset whose pose is given (the
// tangent-track samples).
#include <array>

#include "conforma/kinematics_quasistatic.hpp"

namespace conforma {

struct AxleRollingSpeedOptions {
  double applied_torque_Nm = 0.0;   // T_applied on the axle, N m, finite (+ traction, - braking, 0 free rolling)
  double torque_tolerance_Nm = 0.1; // |contact torque - T_applied| accepted, N m, > 0
  // Bracket search: first step and largest excursion of u = Omega r0 / V - 1 from the start (dimensionless).
  double first_step = 1e-4;         // > 0
  double max_excursion = 0.1;       // > first_step: beyond this the torque is taken as not transmittable
  void validate() const;            // throws InputError naming the option
};

enum class AxleRollingSpeedStatus {
  Converged,       // |residual| <= torque_tolerance_Nm
  NotConverged,    // the bracket search reached max_excursion (torque beyond adhesion) or the root stalled
  ContactFailed,   // a wheel's contact solve failed (status not ok) during the search
};
const char* to_string(AxleRollingSpeedStatus status);  // "converged", "not_converged", "contact_failed"

struct AxleRollingSpeedResult {
  AxleRollingSpeedStatus status = AxleRollingSpeedStatus::NotConverged;  // see AxleRollingSpeedStatus
  double axle_angular_velocity_rad_s = 0.0;  // Omega at the solution (the start when the contact failed), rad/s
  double contact_torque_Nm = 0.0;            // sum F_x r_p at that Omega, N m
  double residual_Nm = 0.0;                  // contact torque - T_applied, N m
  int contact_evaluations = 0;               // wheelset evaluations (two wheel solves each)
  std::array<WheelContactReport, 2> reports; // [Left, Right] at the returned Omega
};

// velocity: the wheelset's velocities; its axle_angular_velocity_rad_s is the start (e.g. V / r0).
// vertical_load_N: [Left, Right] per wheel (WheelContactOptions::vertical_load_N is overwritten per wheel).
// Throws InputError for bad options or a non-positive forward speed or nominal radius.
AxleRollingSpeedResult SolveAxleRollingSpeed(const WheelsetTrackGeometry& geometry, const WheelsetPose& pose,
                                             const WheelsetVelocity& velocity,
                                             const std::array<double, 2>& vertical_load_N,
                                             const WheelContactOptions& contact_options,
                                             const WheelContactFunction& contact, double nominal_radius_m,
                                             const AxleRollingSpeedOptions& options);

}  // namespace conforma
