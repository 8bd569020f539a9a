// The rigid two-rail equilibrium read from a contact look-up table (contact_lut.hpp, EvaluateLutRigidPose).
#include <cmath>

#include "conforma/contact_lut.hpp"
#include "conforma/error.hpp"
#include "lut_locate.hpp"

namespace conforma {

EquilibriumResult EvaluateLutRigidPose(const ContactLut& lut, double y_m, double psi_rad) {
  const ContactLutGrid& g = lut.grid;
  size_t iy, ip;
  double ty, tp;
  LocateOnLutAxis(g.lateral_m, y_m, "lateral shift y", "mm", 1e3, &iy, &ty);
  LocateOnLutAxis(g.yaw_rad, psi_rad, "yaw psi", "mrad", 1e3, &ip, &tp);
  // the equilibrium does not depend on the load: the lowest load layer of the left wheel's nodes
  const std::vector<LutNode>& nodes = lut.nodes[side_index(Side::Left)];
  const LutNode* corner[4];
  double w[4];
  for (int c = 0; c < 4; ++c) {
    const int dy = c >> 1 & 1, dp = c & 1;
    corner[c] = &nodes[g.index(iy + dy, ip + dp, 0)];
    w[c] = (dy ? ty : 1.0 - ty) * (dp ? tp : 1.0 - tp);
  }
  // as the contact's interpolation: the nearest corner decides (a corner without equilibrium is never averaged in)
  int nearest = 0;
  for (int c = 1; c < 4; ++c)
    if (w[c] > w[nearest]) nearest = c;
  EquilibriumResult r;
  r.pose.lateral_m = y_m;
  r.pose.yaw_rad = psi_rad;
  if (corner[nearest]->status == kLutNoEquilibrium) {
    r.status = EquilibriumStatus::NotConverged;
    return r;
  }
  double wsum = 0.0;
  for (int c = 0; c < 4; ++c) {
    if (corner[c]->status == kLutNoEquilibrium) continue;
    r.pose.vertical_m += w[c] * corner[c]->vertical_m;
    r.pose.roll_rad += w[c] * corner[c]->roll_rad;
    wsum += w[c];
  }
  r.pose.vertical_m /= wsum;
  r.pose.roll_rad /= wsum;
  r.status = EquilibriumStatus::Converged;
  return r;
}

LutPoseFunction MakeLutPoseFunction(std::shared_ptr<const ContactLut> lut) {
  if (!lut) throw InputError("contact LUT: no table given");
  return [lut](const WheelsetTrackGeometry&, double y_m, double psi_rad, const EquilibriumOptions& options) {
    if (options.max_touching_contact_angle_rad != lut->header.max_touching_contact_angle_rad)
      throw InputError("contact LUT: the equilibrium's elastic-flange angle differs from the table's");
    return EvaluateLutRigidPose(*lut, y_m, psi_rad);
  };
}

}  // namespace conforma
