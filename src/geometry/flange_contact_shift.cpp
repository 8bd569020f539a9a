// Lateral shift of flange contact (geometry.hpp): a scan of the rigid wheelset equilibrium.
#include <algorithm>

#include "conforma/geometry.hpp"

namespace conforma {

double FlangeContactShift(const WheelsetTrackGeometry& geometry, double curvature_sign, double flange_angle_rad) {
  const double dir = curvature_sign >= 0.0 ? -1.0 : 1.0;  // c > 0: towards the right (outer) rail, y < 0
  const Side outer = dir < 0.0 ? Side::Right : Side::Left;
  WheelsetPose guess;
  for (double y = 0.0; y <= 20e-3 + 1e-12; y += 0.1e-3) {
    const EquilibriumResult eq = geometry.SolveRigidEquilibrium(dir * y, 0.0, guess);
    if (eq.status == EquilibriumStatus::NoContact) continue;
    guess = eq.pose;
    for (const RigidContactPoint& p : eq.contact.wheel[side_index(outer)].points)
      if (p.gap_m < 1e-6 + eq.contact.wheel[side_index(outer)].points.front().gap_m && p.contact_angle_rad > flange_angle_rad)
        // the flange has become the rigid contact: the wheelset jumped onto its flange (tread lifted). The flange
        // position is the last shift before that jump, where the tread still carries and the flange gap is below
        // the scan resolution (under load both touch: two-point contact).
        return dir * std::max(0.0, y - 0.1e-3);
  }
  return dir * 20e-3;
}

}  // namespace conforma
