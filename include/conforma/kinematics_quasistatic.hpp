#pragma once
// Quasi-static curving of a bogie vehicle (paper 001 §§2-5 simplified to the steady state): for a track class
// (radius, cant, speed, friction) and a contact model, the steady lateral shift y and yaw psi of every wheelset
// and the lateral shift and yaw of every bogie frame, with the contact model in the loop.
//
// MODEL (one bogie at a time; the carbodies follow the track: each is the chord between two consecutive bogie
// centres, so the bogies only interact through the carbody yaw they see):
//   Unknowns of a bogie: y_j, psi_j, Omega_j of its wheelsets j = 0 (leading, x_0 = +a) and 1 (x_1 = -a), and
//   y_b, psi_b of the frame. Each wheelset is described in the local track frame at its own position (y from
//   the track centre line, psi from the local tangent), the frame in the local track frame at the bogie centre.
//   Curvature c = 1/R (signed as TrackClass: c > 0 turns left). Relative axlebox displacements (small angles):
//       Delta y_j   = y_j - (y_b + psi_b x_j - c x_j^2 / 2)      (track centre line offset c x^2/2 at x)
//       Delta psi_j = psi_j - (psi_b - c x_j)                    (local tangent turned by c x)
//   Unbalanced lateral acceleration a_nc = V^2 c - g h sign(c) / cant_base (h = cant), acting on every mass.
//   Wheelset j:  sum_wheels Y + (-2 k_y Delta y_j) - m_w a_nc = 0
//                sum_patches (x_p F_y - (y_p - y_j) F_x + M_spin) - 2 k_x b_x^2 Delta psi_j = 0
//                sum_patches F_x r_p = 0        (free axle rotation: no torque on an unpowered axle)
//   Bogie frame: sum_j 2 k_y Delta y_j - (m_b + m_c) a_nc = 0        (carbody share's force through the
//                                                                      secondary stage, carbody in equilibrium)
//                sum_j (2 k_x b_x^2 Delta psi_j + x_j 2 k_y Delta y_j) - k_s,psi (psi_b - psi_c) = 0
//   where psi_c is the mean yaw, relative to the tangent at the bogie centre, of the carbody chords joined to
//   the bogie: -c L/2 for the chord behind (leading bogie), +c L/2 for the chord ahead, 0 for a Jacobs bogie
//   between two chords. The contact forces Y, F_x, M_spin come from SolveWheelContact for each wheel (normal +
//   creep forces, load control with the wheel's vertical load, so the lateral components of the normal forces
//   -- the gravitational stiffness -- are included) at the wheelset velocity: forward V, lateral 0, yaw rate
//   V c (this reproduces the curve's longitudinal creepage -y_p c), axle angular velocity Omega_j. Vertical
//   position and roll of each wheelset come from the rigid two-rail equilibrium at (y_j, psi_j). Wheel loads:
//   Q = Q0 -/+ m a_nc h / (2 b0) on the inner/outer wheel (vehicle.hpp).
//   Solved with Ceres Levenberg-Marquardt on the 8 scaled residuals of a bogie (forces / Q0, moments / (Q0 b0),
//   axle torque / (Q0 r0)); unknowns in mm, mrad and (Omega r0 / V - 1) * 1e3. Jacobian: forward differences of
//   the contact forces (each wheelset's contact depends only on its own three unknowns), suspension terms exact.
//   Initial guess: radial-steering estimate (wheelsets parallel to the frame, frame on the chord, y where the
//   rolling radius difference Delta r(y) of the rigid equilibrium gives pure rolling, 2 b0 r0 / R, clipped at
//   flange contact). If the residual is not reached, a continuation in c = 1/R from the tangent solution; the
//   better of the two attempts is kept; if neither converged, up to three more starts in the flange regimes
//   (QuasiStaticOptions::multi_start) and the best attempt overall is kept.
//   Admissible solutions: every wheelset within derailment_margin_m of its flange-contact shift, and no wheelset
//   in flange contact whose lateral contact force falls as it moves on towards the flange (climbing_slope: the
//   wheel rides up its flange, an unstable equilibrium; both one-sided differences over 0.02 mm must show the
//   fall, so that a jump of the contact forces next to a stable state is not taken for a slope). An inadmissible
//   attempt is never Converged (BogieQuasiStaticReport::derailed / climbing when it is the best one left).
//   RIGID OR ELASTIC FLANGE: with the default rigid flange, the wheelset's vertical position and roll make the
//   smallest gap of each wheel zero, so a flange face steeper than ~80 deg under the angle of attack (worn
//   S1002 after a few hundred km) is a wall the wheelset can only pass by jumping onto it: no flange force is
//   available before the wall and no equilibrium exists. contact.max_touching_contact_angle_rad (elastic flange)
//   makes only the contact points up to that angle define the touching position; the flange then
//   interpenetrates and its elastic force follows (the scenario key elastic_flange_deg).
//   LIMITATION: the contact forces can still jump in (y, psi) where a rigid gap minimum is born with a negative
//   gap (a minimum appearing inside a region already in contact). An equilibrium lying on such a jump has no
//   exact solution: the solver then returns the least-squares point with status NotConverged and its
//   max_residual.
//
// TANGENT TRACK (c = 0): the equilibrium is solved as above, from tangent_start_offset_m (centred by symmetry for
// symmetric profiles). The samples are then the centred wheelset moving on a kinematic (Klingel) oscillation of
// amplitude tangent_amplitude_m: y = A sin(theta), psi = A k cos(theta), dy/dt = V psi, dpsi/dt = -V A k^2 sin(theta),
// k = 2 pi / L_K, L_K = 2 pi sqrt(r0 b0 / lambda) with the equivalent conicity lambda = -Delta r(-A) / (2 A) of
// the rigid equilibrium, at tangent_phases equally spaced phases theta (theta = 0 is the centred wheelset) with
// equal weights 1 / tangent_phases (the time average over one period). A = 0 gives the single centred sample.
// The axle speed of each sample follows from the axle's torque balance (free rolling, or axle_torque_Nm applied:
// axle_rolling_speed.hpp, docs/physics-reference.md §12.3), as in curves; a sample whose balance fails makes the
// status NotConverged (tangent_rolling_failures counts them).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/kinematics.hpp"
#include "conforma/vehicle.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/wheelset_forces.hpp"

namespace conforma {

// validate() throws InputError outside the ranges given.
struct QuasiStaticOptions {
  // Model, material, FASTSIM settings. vertical_load_N and friction_coefficient are set per wheel and class.
  WheelContactOptions contact;
  double gravity_m_s2 = 9.81;            // g, m/s^2, > 0
  double cant_base_m = 1.5;              // m, > 0: a_nc = V^2 / R - g h / cant_base (distance of the rail centres)
  bool free_axle_rotation = true;        // false: Omega = V / r0 and no axle torque equation
  // Drive torque applied to every axle (docs/physics-reference.md §12.3): the contact torque sum F_x r_p balances
  // it, in curves and on tangent track. N m, finite; > 0 traction, < 0 braking, 0 free (unpowered) rolling.
  double axle_torque_Nm = 0.0;
  // Tangent track samples (see the header comment).
  double tangent_amplitude_m = 3e-3;     // A, m, >= 0 (0: one centred sample per wheelset)
  int tangent_phases = 8;                // phases theta per wheelset, >= 1
  // Lateral shift of all wheelsets and frames at the start of the tangent-track solve. 0: centred start (the
  // exact solution for symmetric profiles; an off-centre start can stall on a contact jump, e.g. S1002/60E1
  // 1:40 with Hertz at |y| = 0.22 mm). The tests start 1 mm off centre to show the centre is found, not assumed.
  double tangent_start_offset_m = 0.0;     // m, finite
  // Solver.
  int max_iterations = 60;                 // LM iterations per attempt, >= 1
  double residual_tolerance = 1e-5;        // max |scaled residual| accepted as converged, > 0 (dimensionless)
  int continuation_steps = 4;              // steps in c when the direct solve fails (0: none), >= 0
  // When both fail: starts with the leading wheelset at the outer flange and the trailing one at the inner
  // flange, centred, or at the outer flange (the best attempt is kept).
  bool multi_start = true;
  // A solution with a wheelset more than this beyond its flange-contact shift (the flange of that side becomes
  // the smallest rigid gap) has climbed the flange: it is never Converged, and any admissible attempt beats it.
  double derailment_margin_m = 3e-3;       // m, >= 0
  // ... and so is a flange-contact state whose wheelset lateral contact force falls as the wheelset moves on
  // towards the flange faster than this (in Q0 per mm): the wheel is riding up its flange, an unstable
  // equilibrium (the rising flange force of a stable one grows by ~10-50 Q0 per mm).
  double climbing_slope = 0.05;            // Q0 per mm, >= 0
  double flange_contact_angle_rad = 0.5;   // rad, > 0: a patch steeper than this is a flange contact
  // Forward-difference steps of the scaled unknowns (mm, mrad, 1e-3 relative axle speed), > 0.
  double difference_step = 1e-3;
  void validate() const;  // throws InputError naming the option
};

// Converged: max |scaled residual| <= residual_tolerance at an admissible state; NotConverged: the best attempt
// misses it (or is inadmissible); NoContact: a wheel without contact at every attempt (non-finite residual), or a
// wheel unloaded by the load transfer (overturning).
enum class QuasiStaticStatus { Converged, NotConverged, NoContact };
const char* to_string(QuasiStaticStatus status);  // "converged", "not_converged", "no_contact"

// One wheel at the bogie's solution (SolveWheelContact re-evaluated there).
struct WheelQuasiStaticReport {
  WheelContactStatus status = WheelContactStatus::NoContact;  // of the wheel's contact solve
  int patch_count = 0;                // contact patches of the wheel
  bool flange_contact = false;        // any patch with contact angle > flange_contact_angle_rad
  double vertical_load_N = 0.0;       // Q, N: Q0 -/+ the load transfer (vehicle.hpp)
  double lateral_force_N = 0.0;       // Y in the track frame (+ towards the left rail), on the wheel, N
  double longitudinal_force_N = 0.0;  // sum of F_x on the wheel, N (patch contact frames)
  // Y/Q with Y positive when the rail pushes the wheel towards the track centre (flange climbing quotient).
  double y_over_q = 0.0;
  double max_contact_angle_rad = 0.0;  // largest contact angle over the patches, rad (0 without patches)
};

struct WheelsetQuasiStaticReport {
  int wheelset = 0, bogie = 0;        // indices within the vehicle (0 = leading); wheelset = 2 bogie + 0 / 1
  WheelsetPose pose;                  // y, psi solved; vertical, roll of the rigid equilibrium
  WheelsetVelocity velocity;          // V, lateral 0, yaw rate V c, solved axle angular velocity
  WheelQuasiStaticReport wheel[2];    // [Left, Right]
  double primary_lateral_force_N = 0.0;  // on the wheelset, N: -2 k_y Delta y_j (track frame, + towards left)
  double primary_yaw_moment_Nm = 0.0;    // on the wheelset, N m: -2 k_x b_x^2 Delta psi_j
};

// One bogie; bogies with the same carbody yaw share one solve (the counters are those of that solve).
struct BogieQuasiStaticReport {
  int bogie = 0;                          // index from the front (0 = leading)
  QuasiStaticStatus status = QuasiStaticStatus::NotConverged;  // of this bogie's solve, see QuasiStaticStatus
  double lateral_m = 0.0, yaw_rad = 0.0;  // frame, local track frame at the bogie centre; m, rad
  double carbody_yaw_rad = 0.0;           // psi_c used for the secondary yaw moment, rad
  // Lateral deflection of the secondary stage, m_c a_nc / k_s,y (the carbody share's lateral force goes
  // through it whatever its stiffness; 0 when the stiffness is 0).
  double secondary_lateral_deflection_m = 0.0;
  int iterations = 0;                     // LM iterations (all attempts)
  int contact_evaluations = 0;            // SolveWheelContact calls
  // ... of which without a solution (status not Ok, e.g. the load control stopped on a jump of the model's normal
  // force in the push-down): the minimizer cannot step there; many of them explain a NotConverged solve
  int failed_contact_evaluations = 0;
  double max_residual = 0.0;              // max |scaled residual| at the solution (dimensionless; inf: no contact)
  // The 8 scaled residuals at the solution: per wheelset j = 0, 1 lateral force / Q0, yaw moment / (Q0 b0),
  // axle torque / (Q0 r0); then the frame's lateral force / Q0 and yaw moment / (Q0 b0).
  std::array<double, 8> residuals{};
  bool continuation_used = false;         // the continuation in c = 1/R was tried (the direct solve failed)
  int extra_starts = 0;                   // multi-start attempts made
  bool derailed = false;                  // the kept attempt has a wheelset beyond derailment_margin_m
  bool climbing = false;                  // ... or a flange-contact wheelset climbing its flange (climbing_slope)
};

// When a wheel is unloaded by the load transfer (status NoContact) only unbalanced_acceleration_m_s2 is filled.
struct QuasiStaticResult {
  QuasiStaticStatus status = QuasiStaticStatus::NotConverged;  // worst over the bogies
  double unbalanced_acceleration_m_s2 = 0.0;                   // a_nc, m/s^2, + towards the curve centre
  KinematicsSeries series;                                     // one sample per wheelset (curve) or the tangent set
  std::vector<WheelsetQuasiStaticReport> wheelsets;            // equilibrium, one per wheelset
  std::vector<BogieQuasiStaticReport> bogies;                  // one per bogie, from the front
  double total_lateral_force_N = 0.0;                          // sum of Y over all wheels, N (= m_total a_nc)
  // Tangent-track samples whose axle torque balance did not converge (their axle speed is the best found).
  int tangent_rolling_failures = 0;
};

// WheelContactFunction (the contact evaluation used in the loop: SolveWheelContact or a substitute with the same
// contract) is declared in wheelset_forces.hpp, with the force summation both this model and the time-domain model
// use.

// Throws InputError for bad vehicle, class or options; convergence and contact failures are statuses.
QuasiStaticResult SolveQuasiStaticCurving(const VehicleParameters& vehicle, const WheelsetTrackGeometry& geometry,
                                          const TrackClass& track_class, const QuasiStaticOptions& options,
                                          const WheelContactFunction& contact);

// With the standard pipeline (SolveWheelContact). Inline so that the core library does not depend on the
// pipeline library (which depends on the core).
inline QuasiStaticResult SolveQuasiStaticCurving(const VehicleParameters& vehicle, const WheelsetTrackGeometry& geometry,
                                                 const TrackClass& track_class, const QuasiStaticOptions& options) {
  return SolveQuasiStaticCurving(vehicle, geometry, track_class, options, &SolveWheelContact);
}

// Curvature 1/R of a class (0 for tangent track: radius 0 or infinite).
double TrackClassCurvature(const TrackClass& track_class);

// Unbalanced lateral acceleration a_nc of a class in the track plane, + towards the curve centre (+y for c > 0):
// V^2 c - g h sign(c) / cant_base (docs/physics-reference.md §12.1).
double TrackClassUnbalancedAcceleration(const TrackClass& track_class, double gravity_m_s2, double cant_base_m);

// Quasi-static lateral load transfer per wheel under a_nc: m a_nc h / (2 b0) (vehicle.hpp; the outer wheel, -y side
// for a_nc > 0, carries Q0 + dQ).
double WheelLoadTransferN(const VehicleParameters& vehicle, double unbalanced_acceleration_m_s2);

}  // namespace conforma
