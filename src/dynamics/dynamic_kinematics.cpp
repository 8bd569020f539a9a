// Kinematics provider `dynamic` of the wear loop (dynamic_kinematics.hpp): each track class run in the time domain.
#include "conforma/dynamic_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>

#include "conforma/dynamic_kinematics_lut.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/track_irregularity.hpp"
#include "conforma/vehicle_dynamics_track.hpp"

namespace conforma {

namespace {

// Initial positions (SI, VehicleDynamicsModel layout) and axle speed deviations of a steady curve: the quasi-static
// solution when accepted, else the kinematic estimate (one bogie's two wheelsets, repeated per bogie).
void CurveStart(const Scenario& sc, const WheelsetTrackGeometry& g, const TrackClass& tc, const QuasiStaticOptions& qo,
                const WheelContactFunction& contact, const VehicleDynamicsModel& m, DynamicsOptions* o, bool* quasistatic) {
  const VehicleParameters& v = sc.vehicle;
  const double c = TrackClassCurvature(tc), V = tc.speed_m_s, r0 = v.nominal_wheel_radius_m;
  o->initial_positions.assign(m.position_count(), 0.0);
  o->initial_axle_speed_deviation.assign(m.has_axle_speed() ? m.wheelset_count() : 0, 0.0);
  const QuasiStaticResult r = SolveQuasiStaticCurving(v, g, tc, qo, contact);
  *quasistatic = QuasiStaticRejection(r).empty() && static_cast<int>(r.wheelsets.size()) == m.wheelset_count() &&
                 static_cast<int>(r.bogies.size()) == m.bogie_count();
  std::vector<double> frame_y(m.bogie_count(), 0.0);
  if (*quasistatic) {
    for (int j = 0; j < m.wheelset_count(); ++j) {
      o->initial_positions[m.wheelset_index(j)] = r.wheelsets[j].pose.lateral_m;
      o->initial_positions[m.wheelset_index(j) + 1] = r.wheelsets[j].pose.yaw_rad;
      if (m.has_axle_speed()) o->initial_axle_speed_deviation[j] = r.wheelsets[j].velocity.axle_angular_velocity_rad_s * r0 / V - 1.0;
    }
    for (int i = 0; i < m.bogie_count(); ++i) {
      frame_y[i] = r.bogies[i].lateral_m;
      o->initial_positions[m.bogie_index(i)] = r.bogies[i].lateral_m;
      o->initial_positions[m.bogie_index(i) + 1] = r.bogies[i].yaw_rad;
    }
  } else {
    const KinematicsSeries e = KinematicCurvingEstimate(sc, g, tc);  // wheelsets 0 (leading) and 1 of one bogie
    for (int j = 0; j < m.wheelset_count(); ++j)
      for (const KinematicsSample& k : e.samples)
        if (k.wheelset == j % 2) {
          o->initial_positions[m.wheelset_index(j)] = k.pose.lateral_m;
          o->initial_positions[m.wheelset_index(j) + 1] = k.pose.yaw_rad;
        }
    for (int i = 0; i < m.bogie_count(); ++i) {  // frame on the chord of its wheelsets
      frame_y[i] = 0.5 * (o->initial_positions[m.wheelset_index(2 * i)] + o->initial_positions[m.wheelset_index(2 * i + 1)]);
      o->initial_positions[m.bogie_index(i)] = frame_y[i];
    }
  }
  // carbody k on the chord between bogies k and k+1 (at d = +/- L/2: Delta y = y_b + c d^2 / 2 - y_c - psi_c d = 0,
  // vehicle_dynamics_suspension.hpp), shifted by the secondary deflection m_c a_nc / k_s,y that carries its load
  const double L = v.bogie_centre_distance_m;
  const double a_nc = V * V * c - qo.gravity_m_s2 * (c > 0 ? tc.cant_m : -tc.cant_m) / qo.cant_base_m;
  const double deflection = v.secondary_lateral_stiffness_N_m > 0.0
                                ? v.carbody_mass_per_bogie_kg * a_nc / v.secondary_lateral_stiffness_N_m : 0.0;
  for (int k = 0; k < m.carbody_count(); ++k) {
    o->initial_positions[m.carbody_index(k)] = 0.5 * (frame_y[k] + frame_y[k + 1]) + c * L * L / 8.0 - deflection;
    o->initial_positions[m.carbody_index(k) + 1] = (frame_y[k] - frame_y[k + 1]) / L;
  }
}

}  // namespace

DynamicClassKinematics SimulateClassKinematics(const Scenario& sc, const WheelsetTrackGeometry& g, const TrackClass& tc,
                                               ContactModel model, const WheelContactFunction& contact,
                                               const RigidPoseFunction& pose) {
  const ScenarioDynamicKinematics& d = sc.kinematics.dynamic;
  const VehicleParameters& v = sc.vehicle;
  const QuasiStaticOptions qo = ScenarioQuasiStaticOptions(sc, model);
  const double c = TrackClassCurvature(tc);
  const double V = tc.speed_m_s;
  const double run_s = d.settle_s + d.duration_s;
  // stations: every wheelset from 2 m past s = 0 to the end of the run, with 5 m to spare (integrator look-ahead)
  const double a = 0.5 * v.wheelbase_m;
  const double rear = (v.bogie_count - 1) * v.bogie_centre_distance_m + a;
  const double s0 = rear + 2.0;
  const double s_end = s0 + V * run_s + a + 5.0;

  DynamicsOptions o;
  o.model.speed_m_s = V;
  o.model.start_position_m = s0;
  o.model.contact = qo.contact;
  o.model.friction_coefficient = tc.friction_coefficient;
  o.model.gravity_m_s2 = qo.gravity_m_s2;
  o.model.cant_base_m = qo.cant_base_m;
  o.model.free_axle_rotation = qo.free_axle_rotation;
  o.model.axle_torque_Nm = qo.axle_torque_Nm + tc.axle_torque_Nm;
  o.duration_s = run_s;
  o.output_interval_s = d.sample_interval_s;
  o.stepper = d.stepper == "dopri5" ? DynamicsStepper::Dopri5 : DynamicsStepper::Rosenbrock4;
  // the running step budget (a stiff run with dopri5: MakeDynamicKinematics runs it again with rosenbrock4)
  o.max_steps_per_s = d.steps_per_s_max;
  o.record_wheels = false;

  TrackInput track;
  if (c != 0.0) {
    CurveTrackSpec spec;
    spec.tangent_length_m = 0.0;
    spec.transition_length_m = 0.0;
    spec.radius_m = 1.0 / c;
    spec.cant_m = tc.cant_m;
    spec.curve_length_m = s_end + 10.0;
    track = MakeCurveTrack(spec);
  }
  if (d.irregularity) {
    TrackIrregularityOptions io;
    io.spectrum = d.spectrum;
    io.seed = d.seed;
    io.wavelength_min_m = d.wavelength_min_m;
    io.wavelength_max_m = d.wavelength_max_m;
    io.spacing_m = std::min(0.25, 0.25 * d.wavelength_min_m);
    io.length_m = std::max(s_end + 10.0, d.wavelength_max_m);
    SetTrackIrregularity(track, SynthesizeTrackIrregularity(io), qo.cant_base_m);
  }
  const VehicleDynamicsModel m(v, &g, track, o.model, contact, pose);
  DynamicClassKinematics out;
  if (c != 0.0) CurveStart(sc, g, tc, qo, contact, m, &o, &out.quasistatic_start);
  if (d.irregularity) {
    // every body starts on the actual (irregular) centre line at its station, moving along it: the transient of
    // a vehicle put down beside the track is not in the samples' start
    const int nq = m.position_count();
    o.initial_positions.resize(nq, 0.0);
    o.initial_velocities.assign(nq, 0.0);
    for (int q = 0; q < nq; q += 2) {
      const double s = s0 + m.body_position_m(q);
      o.initial_positions[q] += track.alignment(s);
      o.initial_positions[q + 1] += track.alignment_derivative(s);
      o.initial_velocities[q] = V * track.alignment_derivative(s);
    }
  }

  const DynamicsResult r = SimulateVehicleDynamics(m, o);
  out.status = r.status;
  out.simulated_time_s = r.simulated_time_s;
  out.steps = r.steps;
  out.contact_evaluations = r.contact_evaluations;
  if (r.status != DynamicsStatus::Completed) {
    out.failure = std::string("dynamics ") + to_string(r.status) + " at t = " + std::to_string(r.simulated_time_s) +
                  " s: " + r.message;
    return out;
  }
  const int W = m.wheelset_count(), nq = m.position_count();
  const double r0 = v.nominal_wheel_radius_m, b0 = v.contact_half_distance_m;
  const double Q0 = v.static_wheel_load_N(qo.gravity_m_s2);
  EquilibriumOptions eo;  // the touching rule of the contact (wheelset_forces.cpp)
  eo.max_touching_contact_angle_rad = qo.contact.max_touching_contact_angle_rad;
  const double t_first = d.settle_s - 1e-9 * d.sample_interval_s, t_last = run_s + 1e-9 * d.sample_interval_s;
  std::vector<WheelsetPose> guess(W);
  KinematicsSeries& series = out.series;
  for (const DynamicsSample& h : r.history) {
    if (h.time_s < t_first || h.time_s > t_last) continue;
    for (int j = 0; j < W; ++j) {
      const int q = m.wheelset_index(j);
      const double s = m.reference_station_m(h.time_s) + m.body_position_m(q);
      const double y = 1e-3 * h.state[q], psi = 1e-3 * h.state[q + 1];
      const double yd = 1e-3 * h.state[nq + q], psid = 1e-3 * h.state[nq + q + 1];
      const double w = m.has_axle_speed() ? 1e-3 * h.state[2 * nq + j] : 0.0;
      const double slope = track.alignment_derivative(s);
      KinematicsSample k;
      k.wheelset = j;
      k.time_s = h.time_s;
      // the rigid equilibrium the run's contact saw: the given pose function's (a table's), else the rigid solve
      // warm-started from the previous sample; that start can put the roll search on the wrong side of a contact
      // jump: from the neutral start then, as the run's own contact evaluation does (wheelset_forces.cpp)
      EquilibriumResult eq = SolveRigidPose(g, pose, y - track.alignment(s), psi - slope, eo, guess[j]);
      if (!pose && eq.status != EquilibriumStatus::Converged)
        eq = SolveRigidPose(g, pose, y - track.alignment(s), psi - slope, eo);
      if (eq.status != EquilibriumStatus::Converged) {
        out.failure = "no rigid equilibrium of wheelset " + std::to_string(j) + " at t = " + std::to_string(h.time_s) + " s";
        out.series.samples.clear();
        return out;
      }
      guess[j] = eq.pose;
      k.pose = eq.pose;
      k.velocity.forward_speed_m_s = V;
      k.velocity.lateral_velocity_m_s = yd - V * slope;
      k.velocity.yaw_rate_rad_s = psid + V * track.curvature(s);
      k.velocity.axle_angular_velocity_rad_s = V / r0 * (1.0 + w);
      // quasi-static load transfer as the model (vehicle_dynamics_model.cpp WheelsetForces)
      const double dQ = v.carried_mass_per_wheelset_kg() * m.unbalanced_acceleration(s) * v.load_transfer_height_m / (2.0 * b0);
      k.vertical_load_N[0] = Q0 - dQ;
      k.vertical_load_N[1] = Q0 + dQ;
      if (k.vertical_load_N[0] <= 0.0 || k.vertical_load_N[1] <= 0.0) {
        out.failure = "wheelset " + std::to_string(j) + " unloaded at t = " + std::to_string(h.time_s) + " s";
        out.series.samples.clear();
        return out;
      }
      k.track_curvature_per_m = track.curvature(s);
      series.samples.push_back(k);
    }
  }
  if (series.samples.empty()) {
    out.failure = "no history samples after settle_s";
    return out;
  }
  const double weight = static_cast<double>(W) / static_cast<double>(series.samples.size());
  for (KinematicsSample& k : series.samples) k.weight = weight;
  char b[200];
  std::snprintf(b, sizeof b, "dynamic %s (%zu samples per wheelset, %.2f-%.2f s)", tc.name.c_str(),
                series.samples.size() / static_cast<size_t>(W), d.settle_s, run_s);
  series.source = b;
  return out;
}

KinematicsFunction MakeDynamicKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                         std::shared_ptr<KinematicsFallbackLog> fallbacks) {
  struct AcceptedSolutions {  // last accepted series per class index (as MakeScenarioKinematics)
    std::mutex mutex;
    std::map<int, KinematicsSeries> series;
  };
  auto accepted = std::make_shared<AcceptedSolutions>();
  // contact: lut: one table per wheel step, shared by the classes
  auto tables = scenario.kinematics.dynamic.lut_contact ? std::make_shared<DynamicKinematicsLutCache>() : nullptr;
  return [scenario, model, contact, fallbacks, accepted, tables](const WheelsetTrackGeometry& g, const TrackClass& tc,
                                                                 int class_index) {
    DynamicClassKinematics r;
    std::shared_ptr<const ContactLut> table;
    if (tables) {
      try {
        table = tables->get(scenario, g, model);
      } catch (const std::exception& e) {
        r.failure = std::string("contact look-up table not built: ") + e.what();
      }
    }
    // (a rerun starts from the table the last run ended on: a widening is not built twice)
    auto run = [&](const Scenario& sc, ContactModel m) {
      return table ? SimulateClassKinematicsCoveringLut(sc, g, tc, m, table, &table)
                   : SimulateClassKinematics(sc, g, tc, m, contact);
    };
    auto run_with_rerun = [&](ContactModel m) {
      DynamicClassKinematics out = run(scenario, m);
      if (out.status == DynamicsStatus::StepLimit && scenario.kinematics.dynamic.stepper == "dopri5") {
        // the explicit stepper stopped at its budget (stiff contact): the class again with the implicit one
        char b[200];
        std::snprintf(b, sizeof b, "dopri5 reached the step budget (%g per s) at t = %.3f s; run again with rosenbrock4",
                      scenario.kinematics.dynamic.steps_per_s_max, out.simulated_time_s);
        Scenario implicit = scenario;
        implicit.kinematics.dynamic.stepper = "rosenbrock4";
        out = run(implicit, m);
        if (out.failure.empty())
          out.series.source += std::string("; ") + b;
        else
          out.failure += std::string(" (") + b + ")";
      }
      return out;
    };
    if (table || !tables) r = run_with_rerun(model);  // (else the table was not built: r holds that failure)
    if (r.status == DynamicsStatus::StepLimit && table && model == ContactModel::Hertz &&
        scenario.kinematics.dynamic.stall_model == "auto") {
      // Stalled on the hertz table, with either stepper: the multi-Hertz contact (one ellipse per rigid gap minimum)
      // on a worn flange root with many minima (docs/physics-reference.md §16.7, session 22). The class again on a
      // table of the auto contact model, which solves such a region as one curved patch; built for this class.
      const std::string stalled = r.failure;
      try {
        table = BuildDynamicKinematicsLut(scenario, g, ContactModel::Auto);
        char b[160];
        std::snprintf(b, sizeof b, "run again on a table of the auto contact model (built in %.1f s)",
                      table->header.generation_s);
        r = run_with_rerun(ContactModel::Auto);
        const std::string note = "the hertz table's run stopped at the step budget: " + stalled + "; " + b;
        if (r.failure.empty())
          r.series.source += "; " + note;
        else
          r.failure = note + ": " + r.failure;
      } catch (const std::exception& e) {
        r.failure = stalled + "; the auto table for the rerun was not built: " + e.what();
      }
    }
    std::lock_guard<std::mutex> lock(accepted->mutex);
    if (r.failure.empty()) {
      accepted->series[class_index] = r.series;
      return r.series;
    }
    const auto previous = accepted->series.find(class_index);
    const bool has_previous = previous != accepted->series.end();
    if (fallbacks) fallbacks->add({class_index, tc.name, r.failure, has_previous ? "previous solution" : "kinematic estimate"});
    if (has_previous) return previous->second;
    return KinematicCurvingEstimate(scenario, g, tc);
  };
}

KinematicsFunction MakeWearKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                      std::shared_ptr<KinematicsFallbackLog> fallbacks) {
  if (scenario.kinematics.provider == KinematicsProvider::Dynamic)
    return MakeDynamicKinematics(scenario, model, contact, std::move(fallbacks));
  return MakeScenarioKinematics(scenario, model, contact, std::move(fallbacks));
}

}  // namespace conforma
