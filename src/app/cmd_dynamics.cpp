// conforma dynamics --scenario F [--speed-kmh V] [--radius R ...] [--out CSV] [--eig]: the time-domain lateral
// vehicle model (vehicle_dynamics*.hpp) of a scenario's vehicle and profiles over a tangent or a curve with
// clothoid transitions; writes the time history and prints a summary. --eig: the eigenvalues of the linear model
// (linear contact from the profiles: equivalent conicity, contact-angle parameter, Kalker coefficients of the
// centred Hertz contact) and its critical speed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "conforma/contact_lut.hpp"
#include "conforma/contact_plausibility.hpp"
#include "conforma/contact_lut_io.hpp"
#include "exit_status.hpp"
#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/scenario.hpp"
#include "conforma/vehicle_dynamics.hpp"
#include "conforma/vehicle_dynamics_eigen.hpp"
#include "conforma/vehicle_dynamics_output.hpp"
#include "conforma/wear_simulation.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

namespace {
constexpr double kYqLimitEn14363 = 0.8;             // EN 14363 flange-climbing limit (R >= 250 m)
constexpr double kNadalFlangeAngle_rad = 70.0 * M_PI / 180.0;  // S1002 flange angle
// Nadal's limit of Y/Q for flange angle delta and friction mu: (tan delta - mu) / (1 + mu tan delta)
double NadalLimit(double delta_rad, double mu) { return (std::tan(delta_rad) - mu) / (1.0 + mu * std::tan(delta_rad)); }
}  // namespace

namespace {

// Linear contact of the profile pair: lambda = -Delta r(-A) / (2 A) of the rigid equilibrium (as the curving
// model's tangent samples), epsilon = b0 (tan delta_L - tan delta_R) / (2 A) and dphi/dy = phi / A at y = A, and
// Kalker's f11, f22 of the centred Hertz ellipse under the static wheel load.
LinearWheelsetContact ProfileLinearContact(const WheelsetTrackGeometry& g, const VehicleParameters& v,
                                           const Material& material, double amplitude_m, double gravity) {
  const EquilibriumResult centred = g.SolveRigidEquilibrium(0.0, 0.0);
  const EquilibriumResult left = g.SolveRigidEquilibrium(amplitude_m, 0.0);
  const EquilibriumResult right = g.SolveRigidEquilibrium(-amplitude_m, 0.0);
  if (centred.status != EquilibriumStatus::Converged || left.status != EquilibriumStatus::Converged ||
      right.status != EquilibriumStatus::Converged || centred.contact.wheel[0].points.empty() ||
      left.contact.wheel[0].points.empty() || left.contact.wheel[1].points.empty())
    throw InputError("dynamics --linear: no rigid equilibrium of the profile pair at 0 / +/- the amplitude");
  const RigidContactPoint& p = centred.contact.wheel[0].points.front();
  const HertzResult h = SolveHertzForLoad(p.hertz_A_per_m, p.hertz_B_per_m, v.static_wheel_load_N(gravity), material);
  if (h.status != HertzStatus::Ok) throw InputError("dynamics --linear: no Hertz ellipse at the centred contact");
  LinearWheelsetContact k = LinearContactFromEllipse(h.a_m, h.b_m, material);
  k.conicity = std::max(-right.rolling_radius_difference_m / (2.0 * amplitude_m), 1e-3);
  const double dtan = std::tan(left.contact.wheel[0].points.front().contact_angle_rad) -
                      std::tan(left.contact.wheel[1].points.front().contact_angle_rad);
  k.contact_angle_parameter = std::max(0.0, v.contact_half_distance_m * dtan / (2.0 * amplitude_m));
  k.roll_coefficient_per_m = std::fabs(left.pose.roll_rad / amplitude_m);
  return k;
}

}  // namespace

void RegisterDynamicsCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("dynamics", "time-domain lateral vehicle dynamics over a tangent or a curve");
  struct Args {
    std::vector<std::string> scenario_overrides;  // --set
    std::string scenario, model, out, stepper = "rosenbrock4", irregularity, lut, lut_creep = "fastsim";
    int bogies = 0, jacobian_reuse = 1;
    double max_steps_per_s = 0.0;
    double speed_kmh = 60.0, duration = 5.0, interval = 0.01, radius = 0.0, tangent = 50.0, transition = 50.0,
           curve = 100.0, cant_mm = 0.0, start = 0.0, friction = 0.3, offset_mm = 1.0, amplitude_mm = 3.0, atol = 1e-3, rtol = 1e-4;
    bool linear = false, eig = false;
    double v_max_kmh = 400.0;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file (vehicle, profiles, material, contact model)")->required();
  sub->add_option("--model", a->model, WearModelHelp("contact model") + "; default: the scenario's");
  AddScenarioOverrides(sub, &a->scenario_overrides);
  sub->add_option("--bogies", a->bogies, "number of bogies of the vehicle (default: the scenario's; 1: one bogie, "
                                         "secondary stage against a carbody following the track)");
  sub->add_option("--speed-kmh", a->speed_kmh, "speed, km/h");
  sub->add_option("--duration", a->duration, "simulated time, s");
  sub->add_option("--output-interval", a->interval, "time between CSV rows, s");
  sub->add_option("--radius", a->radius, "curve radius, m (0: tangent track; > 0 turns left)");
  sub->add_option("--tangent", a->tangent, "tangent before the entry transition, m");
  sub->add_option("--transition", a->transition, "clothoid transition length (with the cant ramp), m");
  sub->add_option("--curve-length", a->curve, "length of the circular arc, m");
  sub->add_option("--cant-mm", a->cant_mm, "cant of the arc, mm");
  sub->add_option("--friction", a->friction, "friction coefficient");
  sub->add_option("--irregularity", a->irregularity,
                  "track irregularity CSV (track_irregularity.hpp: s_m, alignment_m[, alignment_slope, vertical_level_m, "
                  "cross_level_rad]; `conforma track irregularity` writes one); it must cover the run");
  sub->add_option("--lut", a->lut, "contact look-up table (HDF5, `conforma lut build` with the same profiles and model) "
                                   "instead of the direct contact solver");
  sub->add_option("--lut-creep", a->lut_creep, "--lut: each patch's creep forces by fastsim (as the direct solver) or "
                  "polach (closed form on the patch's ellipse, docs/physics-reference.md §17.3: for speed)")
      ->check(CLI::IsMember({"fastsim", "polach"}));
  sub->add_option("--start-m", a->start, "station s of the leading bogie centre at t = 0, m (the curve begins at s = 0 "
                                         "with its tangent; an irregularity file must cover the whole vehicle)");
  sub->add_option("--offset-mm", a->offset_mm, "initial lateral offset of every wheelset, mm (the disturbance)");
  sub->add_option("--stepper", a->stepper, "rosenbrock4 (implicit, default) or dopri5 (explicit)");
  sub->add_option("--jacobian-reuse", a->jacobian_reuse, "rosenbrock4: steps a Jacobian serves (1: every step)");
  sub->add_option("--max-steps-per-s", a->max_steps_per_s,
                  "running step budget: stop (step_limit) as soon as the step attempts exceed this x (t + 1 s) at the "
                  "simulated time t, so a run that stalls stops early (0: only the limit of 2,000,000 steps)");
  sub->add_option("--atol", a->atol, "absolute tolerance of the scaled state (mm, mrad, mm/s, ...)");
  sub->add_option("--rtol", a->rtol, "relative tolerance");
  sub->add_flag("--linear", a->linear, "linear contact from the profile pair instead of the contact model");
  sub->add_option("--amplitude-mm", a->amplitude_mm, "--linear / --eig: amplitude of the equivalent conicity, mm");
  sub->add_flag("--eig", a->eig, "print the eigenvalues of the linear model at the speed and its critical speed (no run)");
  sub->add_option("--vmax-kmh", a->v_max_kmh, "--eig: upper end of the critical-speed search, km/h");
  sub->add_option("--out", a->out, "time-history CSV file");
  sub->callback([a, sub]() {
    Scenario sc = LoadScenario(a->scenario, a->scenario_overrides);
    const ContactModel model = a->model.empty() ? sc.model : ParseWearModel(a->model, "--model");
    if (!IsWearContactModel(model))
      throw InputError(std::string("contact model '") + to_string(model) + "' has no creep forces; usable: " +
                       WearContactModelNames());
    VehicleParameters vehicle = sc.vehicle;
    if (a->bogies < 0) throw InputError("--bogies must be >= 1 (or omitted: the scenario's), got " +
                                        std::to_string(a->bogies));
    if (a->bogies > 0) vehicle.bogie_count = a->bogies;
    vehicle.validate();
    const WheelsetTrackGeometry g(sc.MakeTrackSetup());
    const QuasiStaticOptions qo = ScenarioQuasiStaticOptions(sc, model);
    DynamicsOptions o;
    o.model.speed_m_s = a->speed_kmh / 3.6;
    o.model.start_position_m = a->start;
    o.model.contact = qo.contact;
    o.model.friction_coefficient = a->friction;
    if (!IsPlausibleFriction(a->friction))  // (as contact's warning, §13)
      std::fprintf(stderr, "warning: --friction %g is outside the plausible range %g to %g of wheel-rail contact\n",
                   a->friction, kMinPlausibleFriction, kMaxPlausibleFriction);
    o.model.gravity_m_s2 = qo.gravity_m_s2;
    o.model.cant_base_m = qo.cant_base_m;
    o.model.axle_torque_Nm = qo.axle_torque_Nm;
    if (a->linear || a->eig) {
      require_positive(a->amplitude_mm, "--amplitude-mm");
      o.model.contact_kind = DynamicsContactKind::Linear;
      o.model.linear = ProfileLinearContact(g, vehicle, sc.material, 1e-3 * a->amplitude_mm, qo.gravity_m_s2);
      std::printf("linear contact: conicity %.4f, contact-angle parameter %.3f, roll coefficient %.4f /m, f11 %.3e N, "
                  "f22 %.3e N\n", o.model.linear.conicity, o.model.linear.contact_angle_parameter,
                  o.model.linear.roll_coefficient_per_m, o.model.linear.f11_N, o.model.linear.f22_N);
    }
    if (a->eig) {
      const LinearStabilityResult r = AnalyseLinearStability(vehicle, o.model);
      std::printf("eigenvalues at %.1f km/h (%d states): max real part %+.4f 1/s\n", a->speed_kmh,
                  static_cast<int>(r.state_matrix.rows()), r.max_real_part);
      for (const DynamicsMode& m : r.modes)
        std::printf("  s = %+10.4f %+10.4f i   f %7.3f Hz   damping %+.4f\n", m.eigenvalue.real(), m.eigenvalue.imag(),
                    m.frequency_Hz, m.damping_ratio);
      CriticalSpeedOptions co;
      co.min_speed_m_s = 1.0;
      co.max_speed_m_s = a->v_max_kmh / 3.6;
      const CriticalSpeedResult c = FindCriticalSpeed(vehicle, o.model, co);
      if (c.unstable_at_min_speed) std::printf("critical speed: unstable already at %.1f km/h\n", 3.6 * co.min_speed_m_s);
      else if (!c.found) std::printf("critical speed: stable up to %.1f km/h\n", a->v_max_kmh);
      else
        std::printf("critical speed %.2f km/h (%.3f m/s), hunting frequency %.3f Hz (%d analyses)\n",
                    3.6 * c.critical_speed_m_s, c.critical_speed_m_s, c.frequency_Hz, c.evaluations);
      return;
    }
    CurveTrackSpec spec;
    spec.radius_m = a->radius;
    spec.tangent_length_m = a->tangent;
    spec.transition_length_m = a->transition;
    spec.curve_length_m = a->curve;
    spec.cant_m = 1e-3 * a->cant_mm;
    TrackInput track = MakeCurveTrack(spec);
    if (!a->irregularity.empty()) {
      const TrackIrregularity irr = ReadTrackIrregularityCsv(a->irregularity);
      // every wheelset's station over the run, with the integrator's look-ahead (1 m either side)
      const double front = 0.5 * vehicle.wheelbase_m + 1.0;
      const double rear = -(vehicle.bogie_count - 1) * vehicle.bogie_centre_distance_m - 0.5 * vehicle.wheelbase_m - 1.0;
      const double s_end = a->start + o.model.speed_m_s * a->duration + front;
      if (irr.s_begin() > a->start + rear || irr.s_end() < s_end)
        throw InputError("--irregularity '" + a->irregularity + "': covers s = " + MessageNumber(irr.s_begin(), 9) +
                         " .. " + MessageNumber(irr.s_end(), 9) + " m, the run needs " +
                         MessageNumber(a->start + rear, 9) + " .. " + MessageNumber(s_end, 9) + " m");
      SetTrackIrregularity(track, irr, o.model.cant_base_m);
    }
    WheelContactFunction contact = &SolveWheelContact;
    RigidPoseFunction pose;  // empty: the geometry's rigid solve
    if (!a->lut.empty()) {  // the table checks profiles, model and material against the query at each evaluation
      const auto table = std::make_shared<const ContactLut>(LoadContactLut(a->lut));
      CheckContactLutGeometry(*table, g);
      LutEvaluationOptions evaluation;
      evaluation.creep_force = ParseLutCreepForce(a->lut_creep);
      contact = MakeLutContactFunction(table, evaluation);
      pose = MakeLutPoseFunction(table);  // the rigid equilibrium from the table too
    }
    const VehicleDynamicsModel m(vehicle, &g, track, o.model, contact, pose);
    o.duration_s = a->duration;
    o.output_interval_s = a->interval;
    o.absolute_tolerance = a->atol;
    o.relative_tolerance = a->rtol;
    o.jacobian_reuse_steps = a->jacobian_reuse;
    require_non_negative(a->max_steps_per_s, "--max-steps-per-s");
    o.max_steps_per_s = a->max_steps_per_s;
    if (a->stepper == "rosenbrock4") o.stepper = DynamicsStepper::Rosenbrock4;
    else if (a->stepper == "dopri5") o.stepper = DynamicsStepper::Dopri5;
    else throw InputError("--stepper: unknown stepper '" + a->stepper + "' (rosenbrock4, dopri5)");
    o.initial_positions.assign(m.position_count(), 0.0);
    for (int j = 0; j < m.wheelset_count(); ++j) o.initial_positions[m.wheelset_index(j)] = 1e-3 * a->offset_mm;
    // progress in simulated seconds: a line per 0.1 s, or per 2 % of a run longer than 5 s
    ProgressReporter progress("dynamics", o.duration_s, "s", ProgressModeOf(sub), std::cerr);
    progress.SetDecimals(2);
    progress.SetLineStep(std::max(0.1, o.duration_s / 50.0));
    o.on_progress = progress.Function();
    const auto start = std::chrono::steady_clock::now();
    const DynamicsResult r = SimulateVehicleDynamics(m, o);
    progress.Finish();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!a->out.empty()) {
      std::ofstream f(a->out);
      if (!f) throw InputError("--out: cannot write '" + a->out + "'");
      WriteDynamicsHistoryCsv(f, m, r);
    }
    const std::string source = a->lut.empty() ? ", direct" : ", look-up table, " + a->lut_creep + " creep forces";
    std::printf("dynamics: %s, %s contact (%s%s), stepper %s, V %.1f km/h, %d bogies\n", to_string(r.status),
                to_string(o.model.contact_kind), to_string(model), source.c_str(),
                to_string(o.stepper), a->speed_kmh, vehicle.bogie_count);
    std::printf("  simulated %.3f s (%.1f m) in %.2f s wall: %.3f simulated s per wall s\n", r.simulated_time_s,
                r.simulated_time_s * o.model.speed_m_s, wall, r.simulated_time_s / wall);
    std::printf("  steps %ld (rejected %ld, contact-failure retries %ld), derivatives %ld, Jacobians %ld, contact solves %ld\n",
                r.steps, r.rejected_steps, r.contact_failure_retries, r.derivative_evaluations, r.jacobian_evaluations,
                r.contact_evaluations);
    // flange climbing (fuzzing, session 24: --offset-mm 50 reported "completed" with Y/Q 3.1 and nothing else)
    const double nadal = NadalLimit(kNadalFlangeAngle_rad, o.model.friction_coefficient);
    std::printf("  max Y/Q %.3f (flange-climbing limits: %.2f EN 14363, %.2f Nadal at 70 deg and mu %.2f)\n",
                r.max_y_over_q, kYqLimitEn14363, nadal, o.model.friction_coefficient);
    if (r.max_y_over_q > kYqLimitEn14363)
      std::fprintf(stderr, "warning: max Y/Q %.3f exceeds the flange-climbing limit %.2f (EN 14363)%s: derailment "
                   "risk (check the initial --offset-mm against the flangeway clearance)\n", r.max_y_over_q,
                   kYqLimitEn14363, r.max_y_over_q > nadal ? " and Nadal's" : "");
    if (r.status != DynamicsStatus::Completed)
      throw IncompleteResult(ExitCode::NotConverged, std::string("dynamics ") + to_string(r.status) + ": " + r.message);
  });
}

}  // namespace conforma::cli
