#pragma once
// Time integration of the lateral vehicle model (vehicle_dynamics_model.hpp) with Boost.Odeint: Options in, Result
// out, deterministic (single thread; the result does not depend on the machine's load).
//
// STIFFNESS: the creep forces damp the wheelset's lateral and yaw motion with time constants m V / (2 f22) and
// I_z V / (2 f11 b0^2) (~1 ms at 20 m/s, ~0.1 ms at 2 m/s) and the axle speed with I_wy V / (2 f11 r0^2), while
// the motion of interest (kinematic oscillation, body modes, the track) lives at 0.5-10 Hz. Default stepper: the
// linearly implicit rosenbrock4 (Kaps-Rentrop, 4th order, L-stable; odeint's rosenbrock4_controller) with a
// finite-difference Jacobian that uses the model's structure: the contact forces of a wheelset depend on its own
// five states only, so a Jacobian costs 5 wheelset contact evaluations per wheelset plus one for d f / d t,
// about six right-hand sides. Its step is set by accuracy, not by the creep time constant. The explicit
// controlled dopri5 is the alternative (Stepper::Dopri5): its step is bounded by stability, ~3 m V / (2 f22).
// Measured step counts of both: docs/physics-reference.md §16.5.
//
// FAILURES are never silent: a contact failure during a step attempt rejects the step and halves it (the trial
// state may lie off the trajectory); when the step falls below min_step_s, or the step count exceeds max_steps,
// or the state becomes non-finite, the integration stops with a status and a message naming the wheelset, the
// station and the state, and the result holds the history up to there.
#include <string>
#include <vector>

#include "conforma/progress.hpp"
#include "conforma/vehicle_dynamics_model.hpp"

namespace conforma {

// Rosenbrock4: linearly implicit, finite-difference Jacobian (default); Dopri5: explicit Dormand-Prince 5(4).
enum class DynamicsStepper { Rosenbrock4, Dopri5 };
const char* to_string(DynamicsStepper stepper);  // "rosenbrock4", "dopri5"

// The most history rows a run may ask for (duration_s / output_interval_s), kept in memory.
constexpr double kMaxHistoryRows = 1e7;

// validate() throws InputError naming the option.
struct DynamicsOptions {
  DynamicsModelOptions model;            // speed, contact, gravity, ...
  double duration_s = 5.0;               // simulated time, s, > 0
  double output_interval_s = 0.01;       // time between history samples, s, > 0, duration / it <= kMaxHistoryRows
  DynamicsStepper stepper = DynamicsStepper::Rosenbrock4;  // see DynamicsStepper and the header comment
  // Error tolerances of the scaled state (mm, mrad, mm/s, mrad/s, per mille): absolute and relative.
  double absolute_tolerance = 1e-3;      // > 0
  double relative_tolerance = 1e-4;      // > 0
  double initial_step_s = 1e-4;          // > 0
  double max_step_s = 0.01;              // > 0 (0.01 s at 20 m/s is 0.2 m of track)
  double min_step_s = 1e-9;              // > 0: below this the integration stops (status StepTooSmall)
  long max_steps = 2000000;              // >= 1
  // > 0: a running step budget as well, StepLimit as soon as the step attempts (accepted and rejected) exceed
  // max_steps_per_s (t + step_budget_grace_s) at the simulated time t: a run that stalls (the step collapsing at a
  // force discontinuity or a flange) stops within about a second of simulated time of it, not only at the end of
  // the run's whole budget. 0: max_steps alone.
  double max_steps_per_s = 0.0;          // >= 0
  double step_budget_grace_s = 1.0;      // >= 0: the start's allowance (a settling transient), in simulated seconds
  // Jacobian difference steps of the scaled states (rosenbrock4), > 0.
  double jacobian_step = 1e-4;
  // rosenbrock4: a Jacobian serves this many step attempts at new states (1: a fresh one every step, the
  // Rosenbrock method as designed; more: fewer contact solves, the error control absorbs the older Jacobian)
  int jacobian_reuse_steps = 1;
  // Initial state in SI (m, rad, m/s, rad/s; axle speeds as w = Omega r0 / V - 1): empty, or one value per
  // generalised coordinate for initial_positions / initial_velocities (VehicleDynamicsModel index layout) and
  // one per wheelset for initial_axle_speed_deviation. Empty: 0.
  std::vector<double> initial_positions, initial_velocities, initial_axle_speed_deviation;
  bool record_wheels = true;             // evaluate the wheel forces (Y, Q, Y/Q, T gamma) at every output sample
  // progress (progress.hpp) at every output sample: done = simulated time, total = duration_s (s), no name; empty:
  // none
  ProgressFunction on_progress;
  void validate() const;
};

// Completed: duration reached. ContactFailed: a wheelset's contact failed and halving the step did not help
// (message). StepTooSmall: the error control pushed the step below min_step_s. StepLimit: max_steps reached, or the
// running budget max_steps_per_s.
// NonFinite: a state or derivative became NaN / inf.
enum class DynamicsStatus { Completed, ContactFailed, StepTooSmall, StepLimit, NonFinite };
const char* to_string(DynamicsStatus status);  // "completed", "contact_failed", "step_too_small", "step_limit", "non_finite"

// One wheel at an output sample.
struct WheelDynamicsSample {
  double lateral_force_N = 0.0;   // Y, track frame (+ towards the left rail)
  double vertical_load_N = 0.0;   // Q (quasi-static, with the load transfer)
  double y_over_q = 0.0;          // + when the rail pushes the wheel towards the track centre (flange climbing)
  double wear_number_N = 0.0;     // T gamma: frictional power / V (linear contact: f11 xi^2 + f22 eta^2)
};

struct DynamicsSample {
  double time_s = 0.0;
  double station_m = 0.0;         // s of the leading bogie centre
  std::vector<double> state;      // scaled state (vehicle_dynamics_model.hpp): q in mm/mrad, rates, w in 1e-3
  std::vector<std::array<WheelDynamicsSample, 2>> wheels;  // per wheelset [Left, Right] (record_wheels)
};

struct DynamicsResult {
  DynamicsStatus status = DynamicsStatus::Completed;  // see DynamicsStatus
  std::string message;                                // why it stopped (empty when Completed)
  double simulated_time_s = 0.0;                      // reached
  std::vector<DynamicsSample> history;                // at t = 0, output_interval_s, ... (and where it stopped)
  long steps = 0;                                     // accepted steps
  long rejected_steps = 0;                            // error-control rejections
  long contact_failure_retries = 0;                   // step attempts rejected for a contact failure
  long derivative_evaluations = 0;                    // right-hand sides (Jacobian columns not included)
  long jacobian_evaluations = 0;                      // rosenbrock4 Jacobians
  long contact_evaluations = 0;                       // wheel contact solves (contact-function calls), all purposes
  double max_y_over_q = 0.0;                          // over the history's wheels
};

// InputError for bad input; failures of the integration are statuses.
DynamicsResult SimulateVehicleDynamics(const VehicleDynamicsModel& model, const DynamicsOptions& options);

}  // namespace conforma
