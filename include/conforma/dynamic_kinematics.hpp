#pragma once
// Kinematics provider `dynamic` of the wear loop (docs/physics-reference.md §16.6): every track class is run in the
// time domain (vehicle_dynamics.hpp) and the wear is accumulated over the contact samples of the run (paper 001
// §6, paper 003 §5: the multibody code's contact samples), so that the lateral spread of the contact comes from the
// vehicle's response to the track (curve, cant, irregularity), not from a chosen sinusoid.
//
// ONE CLASS (radius R, cant h, speed V, friction mu of a TrackClass):
//   track      a steady curve from s = 0 (MakeCurveTrack without tangent and transitions; tangent track for R = 0)
//              plus, unless `irregularity: none`, the seeded irregularity of the scenario's kinematics.dynamic
//              (SynthesizeTrackIrregularity over the whole run, SetTrackIrregularity: alignment and cross-level);
//              the vehicle starts with its rearmost wheelset 2 m past s = 0, so every body is on the curve.
//   model      VehicleDynamicsModel of the scenario's vehicle with nonlinear contact: the curving contact model
//              (CurvingContactModel: kinematics.contact_model, else the wear model), the scenario's material,
//              elastic flange, load tolerance, cant base, free axle rotation and axle torque (as the quasi-static
//              provider, ScenarioQuasiStaticOptions), the class's friction.
//   start      in a curve, the quasi-static curving solution (SolveQuasiStaticCurving) when the provider would
//              accept it (QuasiStaticRejection empty), else the kinematic curving estimate; the carbodies on the
//              chord through their bogie centres, shifted by the secondary deflection m_c a_nc / k_s,y; all rates
//              zero. On tangent track: centred. With an irregularity every body is then moved onto the actual
//              centre line at its station (y + y_irr, psi + y_irr', dy/dt = V y_irr'). The first settle_s seconds
//              are discarded.
//   samples    every history sample at t = settle_s, settle_s + sample_interval_s, ... up to settle_s + duration_s:
//              per wheelset j at its station s = s0 + V t + x_j the pose RELATIVE TO THE ACTUAL (IRREGULAR) TRACK
//              as the contact saw it, y - y_irr(s) and psi - y_irr'(s), vertical position and roll of the rigid
//              two-rail equilibrium there (elastic flange rule of the contact; the rigid solve warm-started from the
//              previous sample, from the neutral start when that fails; with a table, the table's equilibrium that
//              the run used, EvaluateLutRigidPose); velocity V, dy/dt - V y_irr'(s),
//              dpsi/dt + V c(s), axle V / r0 (1 + w_j); loads Q0 -/+ m a_nc(s) h / (2 b0) with the cross-level in
//              a_nc (the model's own loads); weight 1 / (number of samples); curvature c(s).
// CONTACT: kinematics.dynamic.contact `direct` (default) as above, `lut` a contact look-up table of the wheel step's
//              geometry for the contact forces and the rigid equilibrium of the dynamics (dynamic_kinematics_lut.hpp).
// STIFFNESS: the run has a running budget of steps_per_s_max steps per simulated second (StepLimit as soon as
//              the step attempts exceed steps_per_s_max (t + 1 s), DynamicsOptions::max_steps_per_s); a dopri5 run
//              that reaches it (stiff creep forces at a flange bound the explicit step: a conformal R 400 m run of
//              65 s took 2,000,000 steps, 1,666 s, before it stopped) is run again with rosenbrock4 on the same
//              budget, which the series' source then names (the failure, if that run fails too). A class that
//              stops at the budget on a hertz table with both steppers (the multi-Hertz contact on a worn flange
//              root with many gap minima, docs/physics-reference.md §16.7 session 22) is run again on a table of
//              the `auto` contact model built for it, unless kinematics.dynamic.stall_model is `none`.
// FAILURES are never silent: an integration that stops early (DynamicsResult status), a sample without rigid
// equilibrium or an unloaded wheel makes the class fall back like a rejected quasi-static solve (wear_simulation.hpp
// MakeScenarioKinematics): to the last accepted series of the class, else the kinematic curving estimate, with the
// reason in the fallback log (steps.csv kinematics_fallbacks).
// Deterministic: the integration is single-threaded and the irregularity seeded.
#include <memory>
#include <string>

#include "conforma/kinematics.hpp"
#include "conforma/scenario.hpp"
#include "conforma/vehicle_dynamics.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {

// One class run by the dynamic provider.
struct DynamicClassKinematics {
  KinematicsSeries series;        // the samples (empty when failure is set)
  std::string failure;            // why the run gives no samples ("" when it does), e.g. "dynamics contact_failed: ..."
  bool quasistatic_start = false; // the run started from the accepted quasi-static solution (curves)
  DynamicsStatus status = DynamicsStatus::Completed;  // of the integration
  double simulated_time_s = 0.0;  // reached
  long steps = 0, contact_evaluations = 0;            // of the integration (DynamicsResult)
};

// Runs one class with the scenario's kinematics.dynamic settings; `model` is the curving contact model, `contact`
// the wheel contact function and `pose` the rigid equilibrium of the dynamics (empty: the geometry's solve; the
// samples' vertical position and roll are always the geometry's). InputError for bad input; failures are in
// `failure`. With `contact: lut` the provider calls SimulateClassKinematicsWithLut (dynamic_kinematics_lut.hpp).
DynamicClassKinematics SimulateClassKinematics(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                               const TrackClass& track_class, ContactModel model,
                                               const WheelContactFunction& contact, const RigidPoseFunction& pose = {});

// The `dynamic` provider as a KinematicsFunction, with the fallback described above (per-class memory: one function
// per run; `fallbacks` optional). With kinematics.dynamic.contact: lut, `contact` is not used: each wheel step's
// table is built once for all classes (DynamicKinematicsLutCache) and the classes run on it; a table that cannot be
// built or a query it refuses is a failure of the class like the others (dynamic_kinematics_lut.hpp).
KinematicsFunction MakeDynamicKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                         std::shared_ptr<KinematicsFallbackLog> fallbacks = nullptr);

// The scenario's provider, every one of them: MakeDynamicKinematics for `dynamic`, else MakeScenarioKinematics.
// Has the signature of WearSimulationOptions::kinematics_factory.
KinematicsFunction MakeWearKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                      std::shared_ptr<KinematicsFallbackLog> fallbacks);

}  // namespace conforma
