#pragma once
// Contact forces on one wheelset in its local track frame, summed over both wheels' patches: the force summation
// shared by the quasi-static curving model (kinematics_quasistatic.hpp) and the time-domain vehicle model
// (vehicle_dynamics_model.hpp), so that both see exactly the same contact forces at the same wheelset state.
//
// The wheelset's vertical position and roll come from the rigid two-rail equilibrium at (y, psi)
// (WheelsetTrackGeometry::SolveRigidEquilibrium, with the contact options' touching rule: elastic flange or not);
// each wheel's contact is then solved by the contact function in load control with its own vertical load.
// Sums in the track frame (docs/physics-reference.md §12.1):
//   Y   = sum sigma F_eta                                     (side frame -> track frame, + towards the left rail)
//   M_z = sum x_p F_y - (y_p - y) F_x + sigma m_z cos(delta)  (about the wheelset centre; m_z about the patch
//                                                              normal, mirrored in the right side frame)
//   T   = sum F_x r_p                                         (contact torque about the axle)
#include <array>
#include <functional>

#include "conforma/creepage.hpp"
#include "conforma/geometry.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

// The contact evaluation used in the loop (SolveWheelContact or a substitute with the same contract, e.g. a
// look-up table).
using WheelContactFunction = std::function<WheelContactReport(const WheelsetTrackGeometry&, Side, const WheelsetPose&,
                                                              const WheelsetVelocity&, const WheelContactOptions&)>;

// The rigid two-rail equilibrium at (y, psi) with the options' touching rule: WheelsetTrackGeometry::
// SolveRigidEquilibrium (empty function: that one), or a substitute with the same contract (a look-up table's
// tabulated equilibrium, contact_lut.hpp MakeLutPoseFunction).
using RigidPoseFunction =
    std::function<EquilibriumResult(const WheelsetTrackGeometry&, double y_m, double psi_rad, const EquilibriumOptions&)>;

// The rigid equilibrium by `pose` or, when empty, by the geometry's own solve started from `guess` (a pose function
// needs no start).
EquilibriumResult SolveRigidPose(const WheelsetTrackGeometry& geometry, const RigidPoseFunction& pose, double y_m,
                                 double psi_rad, const EquilibriumOptions& options, const WheelsetPose& guess = {});

struct WheelsetContactForces {
  bool ok = false;                           // equilibrium converged and both wheels' contact status Ok
  WheelsetPose pose;                         // of the rigid equilibrium (vertical, roll solved; y, psi as given)
  WheelsetVelocity velocity;                 // as given
  std::array<WheelContactReport, 2> report;  // [Left, Right]; the right one empty when the left one failed
  double lateral_N = 0.0;                    // Y, track frame, + towards the left rail, N
  double yaw_moment_Nm = 0.0;                // M_z about the wheelset centre, N m
  double axle_torque_Nm = 0.0;               // sum F_x r_p, N m
  int contact_evaluations = 0;               // contact-function calls made (0, 1 or 2)
  int failed_contact_evaluations = 0;        // ... of which with a status other than Ok (0 or 1)
};

// Contact forces at lateral shift y_m and yaw psi_rad (local track frame) moving with `velocity`; loads_N are the
// wheels' vertical loads [Left, Right] (each replaces contact_options.vertical_load_N). Stops at the first wheel
// whose contact fails (ok false); an equilibrium that does not converge gives ok false with no contact call.
// `pose`: the rigid equilibrium (empty: WheelsetTrackGeometry::SolveRigidEquilibrium).
WheelsetContactForces EvaluateWheelsetContactForces(const WheelsetTrackGeometry& geometry,
                                                    const WheelContactFunction& contact,
                                                    const WheelContactOptions& contact_options,
                                                    const std::array<double, 2>& loads_N, double y_m, double psi_rad,
                                                    const WheelsetVelocity& velocity,
                                                    const RigidPoseFunction& pose = {});

}  // namespace conforma
