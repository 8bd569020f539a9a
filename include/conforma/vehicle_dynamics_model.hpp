#pragma once
// Equations of motion of the time-domain lateral vehicle model (docs/physics-reference.md §16): the bogie vehicle of
// vehicle.hpp (two-axle bogies, carbodies as chords between consecutive bogies) running at constant speed V over a
// TrackInput (vehicle_dynamics_track.hpp).
//
// DEGREES OF FREEDOM (small angles, each body relative to the design centre line at its own station s = s_ref + x,
//   s_ref = s0 + V t at the centre of the leading bogie, x the body's longitudinal position, bogie i at -i L,
//   wheelsets at +/- a from their bogie centre, carbody k between bogies k and k+1 at -(k + 1/2) L):
//   wheelset j: lateral y_j, yaw psi_j, and (nonlinear contact with free axle rotation) the axle speed
//               Omega_j = V / r0 (1 + w_j) (needed for the longitudinal creepage balance that the quasi-static
//               model solves as its third equation per wheelset: sum F_x r_p = applied torque)
//   bogie frame i: y_b, psi_b;  carbody k (2 bogies or more): y_c, psi_c. One bogie alone: its secondary stage
//   acts against a carbody that follows the track (y_c = psi_c = 0), whose mass share loads the frame with its
//   quasi-static force -m_c a_nc (as in the curving model). Roll, bounce and pitch are not modelled: the
//   wheelset's vertical position and roll follow the rigid two-rail equilibrium (as in the curving model) and the
//   wheel loads are quasi-static, Q = Q0 -/+ m a_nc h / (2 b0) (vehicle.hpp).
// EQUATIONS (rotating local track frames; the standard small-angle forms of Garg & Dukkipati 1984 (curving
//   dynamics), Iwnicki (ed.) 2006 "Handbook of Railway Vehicle Dynamics" and Wickens 2003, whose equation numbers
//   are not checked here: docs/physics-reference.md §11 item 13):
//   m (d2y/dt2 + a_nc(s)) = sum F_y          a_nc = V^2 c(s) - g (cant(s) + cross_level(s)) / cant_base
//   I_z (d2psi/dt2 + V^2 dc/ds) = sum M_z    (d2Theta/dt2 = V^2 dc/ds: the local frame's angular acceleration)
//   I_wy dOmega/dt = T_applied - sum F_x r_p (wheelsets)
//   Wheelset yaw also carries the gyroscopic moment -I_wy Omega dphi/dt of the spinning axle (Wickens 2003:
//   the I_y V / r0 term of the wheelset's yaw equation), phi the roll of the rigid equilibrium.
// SUSPENSION (vehicle_dynamics_suspension.hpp: spring and damper in parallel, lateral and yaw, between a parent
//   and a child body on the curved track; constant curvature gives the curving model's relations).
//   Primary per wheelset: k_y = 2 k_y,axlebox, k_psi = 2 k_x b_x^2 (dampers likewise). Secondary per bogie,
//   shared equally between the carbodies resting on it (a Jacobs bogie carries half of each carbody end).
// CONTACT at the wheelset's relative pose (y - y_irr, psi - y_irr') and velocity (forward V, lateral
//   dy/dt - V y_irr', yaw rate dpsi/dt + V c, axle Omega) through a WheelContactFunction with the force sums of
//   wheelset_forces.hpp (nonlinear), or the linear contact of vehicle_dynamics_linear_contact.hpp.
// STATE (what the integrator sees, scaled so that one tolerance fits all): q = (y_j, psi_j, y_b, psi_b, y_c,
//   psi_c) in mm and mrad, their rates in mm/s and mrad/s, then w_j in 1e-3 (per mille).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conforma/geometry.hpp"
#include "conforma/vehicle.hpp"
#include "conforma/vehicle_dynamics_linear_contact.hpp"
#include "conforma/vehicle_dynamics_suspension.hpp"
#include "conforma/vehicle_dynamics_track.hpp"
#include "conforma/wheel_contact_options.hpp"
#include "conforma/wheelset_forces.hpp"

namespace conforma {

// Nonlinear: a WheelContactFunction with the rigid equilibrium (wheelset_forces.hpp); Linear: Wickens' linear
// wheelset (vehicle_dynamics_linear_contact.hpp).
enum class DynamicsContactKind { Nonlinear, Linear };
const char* to_string(DynamicsContactKind kind);  // "nonlinear", "linear"

// validate() throws InputError naming the option.
struct DynamicsModelOptions {
  double speed_m_s = 20.0;                 // V, m/s, > 0 (constant)
  double start_position_m = 0.0;           // s0: station of the leading bogie centre at t = 0, m, finite
  DynamicsContactKind contact_kind = DynamicsContactKind::Nonlinear;  // see DynamicsContactKind
  // Nonlinear contact: model, material, FASTSIM settings (vertical_load_N is set per wheel) and the friction.
  WheelContactOptions contact;
  double friction_coefficient = 0.3;       // replaces contact.friction_coefficient, >= 0
  LinearWheelsetContact linear;            // linear contact parameters
  double gravity_m_s2 = 9.81;              // > 0
  double cant_base_m = 1.5;                // > 0 (as QuasiStaticOptions)
  bool free_axle_rotation = true;          // nonlinear: axle-speed DOF; false: Omega = V / r0 fixed (as the curving option)
  double axle_torque_Nm = 0.0;             // applied to every axle, N m (> 0 traction)
  bool gyroscopic = true;                  // the wheelset's gyroscopic yaw moment (nonlinear: one extra equilibrium per evaluation)
  void validate() const;
};

// Forces and outputs of one wheelset at a state.
struct WheelsetDynamicsForces {
  bool ok = false;                            // contact solved (both wheels Ok, rigid equilibrium converged)
  std::string failure;                        // what failed when !ok
  double lateral_N = 0.0, yaw_moment_Nm = 0.0, axle_torque_Nm = 0.0;  // contact sums (track frame)
  double gyroscopic_moment_Nm = 0.0;          // -I_wy Omega dphi/dt
  std::array<double, 2> load_N{};             // Q [Left, Right]
  std::array<double, 2> wheel_lateral_N{};    // Y per wheel, track frame, + towards the left rail
  std::array<double, 2> y_over_q{};           // + when the rail pushes the wheel towards the track centre
  std::array<double, 2> wear_number_N{};      // T gamma per wheel: frictional power / V (linear: f11 xi^2 + f22 eta^2)
  int contact_evaluations = 0;                // contact-function calls
};

// The model: sizes, state layout and the right-hand side. Thread-safe for concurrent const calls if the contact
// function is (the counters are returned, not stored).
class VehicleDynamicsModel {
 public:
  // geometry and contact are needed (and kept by reference) for Nonlinear contact only; InputError for bad input.
  VehicleDynamicsModel(const VehicleParameters& vehicle, const WheelsetTrackGeometry* geometry, TrackInput track,
                       const DynamicsModelOptions& options, WheelContactFunction contact = {},
                       RigidPoseFunction pose = {});

  int wheelset_count() const { return W_; }
  int bogie_count() const { return B_; }
  int carbody_count() const { return C_; }
  int position_count() const { return nq_; }        // generalised coordinates
  int state_size() const { return 2 * nq_ + (spin_ ? W_ : 0); }
  bool has_axle_speed() const { return spin_; }
  // indices of the generalised coordinates (rates: + position_count(); w_j: 2 position_count() + j)
  int wheelset_index(int j) const { return 2 * j; }
  int bogie_index(int i) const { return 2 * W_ + 2 * i; }
  int carbody_index(int k) const { return 2 * W_ + 2 * B_ + 2 * k; }
  double body_position_m(int q) const { return x_[q / 2]; }  // x of the body of coordinate q, from the leading bogie
  int wheelset_of_state(int k) const;                        // wheelset whose contact depends on state k, else -1
  const DynamicsModelOptions& options() const { return options_; }
  const VehicleParameters& vehicle() const { return vehicle_; }
  const TrackInput& track() const { return track_; }
  double reference_station_m(double t) const { return options_.start_position_m + options_.speed_m_s * t; }

  // Contact forces of wheelset j at scaled state x and time t.
  WheelsetDynamicsForces WheelsetForces(const Eigen::VectorXd& x, double t, int j) const;
  // d x / dt from the state and the wheelsets' contact forces (one per wheelset).
  void Assemble(const Eigen::VectorXd& x, double t, const std::vector<WheelsetDynamicsForces>& f,
                Eigen::VectorXd* dxdt) const;
  // Both; false (and *failure set) when a wheelset's contact failed.
  bool Derivative(const Eigen::VectorXd& x, double t, Eigen::VectorXd* dxdt, std::vector<WheelsetDynamicsForces>* f,
                  std::string* failure, int* contact_evaluations) const;
  double unbalanced_acceleration(double s) const;  // a_nc(s), m/s^2

 private:
  struct Link {  // a suspension stage between a parent and a child body
    int parent = -1, child = 0;  // body indices (q / 2); parent -1: the track (carbody following it)
    double d = 0.0;              // x_child - x_parent, m
    SuspensionStage stage;
  };
  VehicleParameters vehicle_;
  const WheelsetTrackGeometry* geometry_ = nullptr;
  TrackInput track_;
  DynamicsModelOptions options_;
  WheelContactFunction contact_;
  RigidPoseFunction pose_;  // the rigid equilibrium (empty: the geometry's solve)
  int W_ = 0, B_ = 0, C_ = 0, nq_ = 0;
  bool spin_ = false;
  std::vector<double> x_, mass_, inertia_;  // per body (wheelsets, bogies, carbodies)
  std::vector<double> frame_load_mass_;     // per bogie: carbody mass share loading the frame quasi-statically
  std::vector<Link> links_;
  double r0_ = 0.46, b0_ = 0.75, Q0_ = 0.0;
};

}  // namespace conforma
