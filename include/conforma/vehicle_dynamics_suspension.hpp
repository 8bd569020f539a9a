#pragma once
// A suspension stage of the time-domain vehicle model (docs/physics-reference.md §16.2): spring and damper in
// parallel, lateral and yaw, between a parent body P (bogie frame or carbody) and a child C (wheelset or bogie
// frame) d = x_C - x_P ahead of it, each body described relative to the design centre line at its own station:
//   Delta y   = y_C + D - (y_P + psi_P d),           Delta psi = psi_C + dTheta - psi_P
//   Delta y'  = y_C' + V (dTheta - c(s_P) d) - y_P' - psi_P' d,   Delta psi' = psi_C' + V (c(s_C) - c(s_P)) - psi_P'
//   F_y = -(k_y Delta y + c_y Delta y') and M_z = -(k_psi Delta psi + c_psi Delta psi') on C;
//   -F_y and -(M_z + d F_y) on P
// (D, dTheta: RelativeTrackPosition from s_P to s_C = s_P + d; constant curvature: c d^2 / 2 and c d, the
// quasi-static model's relations, kinematics_quasistatic.hpp).
#include "conforma/vehicle_dynamics_track.hpp"

namespace conforma {

struct SuspensionStage {
  double lateral_stiffness_N_m = 0.0;   // k_y
  double yaw_stiffness_Nm_rad = 0.0;    // k_psi
  double lateral_damping_Ns_m = 0.0;    // c_y
  double yaw_damping_Nms_rad = 0.0;     // c_psi
};

// Lateral shift, yaw and their rates of a body in its local track frame (SI). The track itself (a carbody that
// follows it) is the zero state.
struct SuspensionBodyState {
  double y_m = 0.0, psi_rad = 0.0, y_rate_m_s = 0.0, psi_rate_rad_s = 0.0;
};

struct SuspensionForces {
  double child_lateral_N = 0.0, child_yaw_Nm = 0.0;    // F_y, M_z on the child
  double parent_lateral_N = 0.0, parent_yaw_Nm = 0.0;  // -F_y, -(M_z + d F_y) on the parent
};

// s_parent_m: the parent's station; d_m: x_child - x_parent; V: forward speed.
SuspensionForces EvaluateSuspension(const TrackInput& track, double speed_m_s, double s_parent_m, double d_m,
                                    const SuspensionStage& stage, const SuspensionBodyState& parent,
                                    const SuspensionBodyState& child);

}  // namespace conforma
