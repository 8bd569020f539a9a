// A suspension stage between two bodies on a curved track (vehicle_dynamics_suspension.hpp).
#include "conforma/vehicle_dynamics_suspension.hpp"

namespace conforma {

SuspensionForces EvaluateSuspension(const TrackInput& track, double V, double sp, double d, const SuspensionStage& k,
                                    const SuspensionBodyState& p, const SuspensionBodyState& c) {
  const double sc = sp + d;
  const TrackRelativePosition rel = RelativeTrackPosition(track, sp, sc);
  const double cp = track.curvature(sp), cc = track.curvature(sc);
  const double dy = c.y_m + rel.lateral_offset_m - (p.y_m + p.psi_rad * d);
  const double dpsi = c.psi_rad + rel.heading_change_rad - p.psi_rad;
  const double dyd = c.y_rate_m_s + V * (rel.heading_change_rad - cp * d) - p.y_rate_m_s - p.psi_rate_rad_s * d;
  const double dpsid = c.psi_rate_rad_s + V * (cc - cp) - p.psi_rate_rad_s;
  SuspensionForces f;
  f.child_lateral_N = -(k.lateral_stiffness_N_m * dy + k.lateral_damping_Ns_m * dyd);
  f.child_yaw_Nm = -(k.yaw_stiffness_Nm_rad * dpsi + k.yaw_damping_Nms_rad * dpsid);
  f.parent_lateral_N = -f.child_lateral_N;
  f.parent_yaw_Nm = -(f.child_yaw_Nm + d * f.child_lateral_N);
  return f;
}

}  // namespace conforma
