// Contact forces on one wheelset summed over both wheels (wheelset_forces.hpp).
#include "conforma/wheelset_forces.hpp"

#include <cmath>

namespace conforma {

EquilibriumResult SolveRigidPose(const WheelsetTrackGeometry& geometry, const RigidPoseFunction& pose, double y_m,
                                 double psi_rad, const EquilibriumOptions& options, const WheelsetPose& guess) {
  if (pose) return pose(geometry, y_m, psi_rad, options);
  return geometry.SolveRigidEquilibrium(y_m, psi_rad, guess, options);
}

WheelsetContactForces EvaluateWheelsetContactForces(const WheelsetTrackGeometry& geometry,
                                                    const WheelContactFunction& contact,
                                                    const WheelContactOptions& contact_options,
                                                    const std::array<double, 2>& loads_N, double y_m, double psi_rad,
                                                    const WheelsetVelocity& velocity, const RigidPoseFunction& pose) {
  WheelsetContactForces f;
  EquilibriumOptions eo;  // the same touching rule as the contact's load control (elastic flange or not)
  eo.max_touching_contact_angle_rad = contact_options.max_touching_contact_angle_rad;
  const EquilibriumResult eq = SolveRigidPose(geometry, pose, y_m, psi_rad, eo);
  if (eq.status != EquilibriumStatus::Converged) return f;
  f.pose = eq.pose;
  f.velocity = velocity;
  for (Side side : {Side::Left, Side::Right}) {
    const int i = side_index(side);
    const double sigma = side_sign(side);
    WheelContactOptions o = contact_options;
    o.vertical_load_N = loads_N[i];
    f.report[i] = contact(geometry, side, f.pose, f.velocity, o);
    ++f.contact_evaluations;
    if (f.report[i].status != WheelContactStatus::Ok) {
      ++f.failed_contact_evaluations;
      return f;
    }
    for (const PatchReport& p : f.report[i].patches) {
      const double Fy = sigma * p.lateral_force_N;
      const double Fx = p.fx_N;
      const double yp = sigma * (geometry.rail_origin_eta_m(side) + p.y_contact_rail_m);
      f.lateral_N += Fy;
      f.yaw_moment_Nm += p.lead_m * Fy - (yp - y_m) * Fx + sigma * p.mz_Nm * std::cos(p.contact_angle_rad);
      f.axle_torque_Nm += Fx * p.rolling_radius_m;
    }
  }
  f.ok = true;
  return f;
}

}  // namespace conforma
