#pragma once
// Wheelset kinematics for the wear loop: where each wheelset is (pose), how it moves (velocities) and what it
// carries (vertical wheel loads), sampled along a track class. Two providers produce the same samples:
//   (a) the quasi-static curving model of a two-axle bogie / two-bogie vehicle on a curve of given radius,
//       cant and speed (kinematics_quasistatic.hpp), solved with the contact model in the loop;
//   (b) a time series imported from an external multibody code (kinematics_import.hpp), CSV with named columns.
// The wear loop only sees KinematicsSample, so both are interchangeable (and an exported quasi-static run
// re-imported must give the same wear).
#include <string>
#include <vector>

#include "conforma/creepage.hpp"
#include "conforma/geometry.hpp"

namespace conforma {

// One track class of the line (paper 001 §6; paper 003 §5): a curve (or tangent track, radius = inf) travelled
// at a speed, with its share of the line's length (weights sum to 1 over the classes of a scenario).
struct TrackClass {
  std::string name;
  // 0: tangent track; > 0: curve turning to the LEFT (centre on the +y side: the left rail is the inner, low
  // rail and the right rail the outer, high rail, flange contact on the right wheel of a leading wheelset);
  // < 0: the mirror image, turning right.
  double curve_radius_m = 0.0;
  double cant_m = 0.0;             // superelevation (height difference of the rails)
  double speed_m_s = 0.0;
  double share = 1.0;              // weight p_k of the class
  double friction_coefficient = 0.3;
  // Drive torque per axle in this class, N m (> 0 traction, < 0 braking; docs/physics-reference.md §12.3): the
  // operating phase of the class (accelerating out of / braking into a station). Added to the torque every class
  // gets (QuasiStaticOptions::axle_torque_Nm); used by the providers that solve the axle's torque balance.
  double axle_torque_Nm = 0.0;
};

// The state of one wheelset at one sample.
struct KinematicsSample {
  int wheelset = 0;                         // index within the vehicle (0 = leading)
  double time_s = 0.0;                      // time of the sample (0 for a quasi-static equilibrium)
  double weight = 1.0;                      // weight of the sample within its class (sum 1 per wheelset and class)
  WheelsetPose pose;                        // lateral, vertical, roll, yaw (track frame, geometry.hpp)
  WheelsetVelocity velocity;                // forward speed, lateral velocity, yaw rate, axle angular velocity
  double vertical_load_N[2] = {0.0, 0.0};   // per wheel [Left, Right]
  double track_curvature_per_m = 0.0;       // 1/R of the track at the sample (0 on tangent track)
};

struct KinematicsSeries {
  std::string source;                       // e.g. "quasi-static R=300 m" or the imported file name
  std::vector<KinematicsSample> samples;
};

}  // namespace conforma
