// Time-domain vehicle model against the quasi-static curving model (vehicle_dynamics*.hpp,
// kinematics_quasistatic.hpp): on a constant-radius curve without irregularities, with the same vehicle, class
// and nonlinear contact (SolveWheelContact, Hertz + FASTSIM, the default scenario's S1002 / 50E4 1:20 pair), the
// simulation must settle to the quasi-static equilibrium: every wheelset within 0.2 mm and 0.2 mrad.
// test-links: dynamics

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/vehicle_dynamics.hpp"
#include "conforma/wheel_contact.hpp"
#include "metro_test_track.hpp"

namespace conforma {
namespace {

// The paper-003 metro vehicle's bogies and masses, as a two-bogie vehicle (one carbody).
VehicleParameters TwoBogieMetro() {
  VehicleParameters v = MetroVehicle();
  v.bogie_count = 2;
  return v;
}

struct Comparison {
  double max_dy_mm = 0.0, max_dpsi_mrad = 0.0, max_rate = 0.0;
};

Comparison Compare(const VehicleParameters& v, double R, double V, double cant, double duration) {
  const WheelsetTrackGeometry& g = test::MetroTrackGeometry();
  TrackClass tc;
  tc.name = "R" + std::to_string(R);
  tc.curve_radius_m = R;
  tc.cant_m = cant;
  tc.speed_m_s = V;
  tc.friction_coefficient = 0.3;
  QuasiStaticOptions qo;
  const QuasiStaticResult qs = SolveQuasiStaticCurving(v, g, tc, qo);
  EXPECT_EQ(qs.status, QuasiStaticStatus::Converged);

  DynamicsOptions o;
  o.model.speed_m_s = V;
  o.model.contact = qo.contact;
  o.model.friction_coefficient = tc.friction_coefficient;
  o.model.gravity_m_s2 = qo.gravity_m_s2;
  o.model.cant_base_m = qo.cant_base_m;
  o.duration_s = duration;
  o.output_interval_s = 0.05;
  o.record_wheels = false;
  TrackInput track;
  const double c = 1.0 / R;
  const double signed_cant = R > 0.0 ? cant : -cant;
  track.curvature_per_m = [c](double) { return c; };
  track.cant_m = [signed_cant](double) { return signed_cant; };
  const VehicleDynamicsModel model(v, &g, track, o.model, &SolveWheelContact);
  // start: wheelsets and frames centred, carbodies at the secondary stage's static deflection (shortens the
  // slow carbody transient; the wheelsets start 2-5 mm from their equilibrium)
  o.initial_positions.assign(model.position_count(), 0.0);
  const double a_nc = V * V * c - o.model.gravity_m_s2 * signed_cant / o.model.cant_base_m;
  for (int k = 0; k < model.carbody_count(); ++k)
    o.initial_positions[model.carbody_index(k)] =
        -v.carbody_mass_per_bogie_kg * a_nc / v.secondary_lateral_stiffness_N_m;
  const DynamicsResult r = SimulateVehicleDynamics(model, o);
  EXPECT_EQ(r.status, DynamicsStatus::Completed) << r.message;
  Comparison out;
  const DynamicsSample& last = r.history.back();
  for (int j = 0; j < model.wheelset_count(); ++j) {
    const double dy = last.state[model.wheelset_index(j)] - 1e3 * qs.wheelsets[j].pose.lateral_m;
    const double dpsi = last.state[model.wheelset_index(j) + 1] - 1e3 * qs.wheelsets[j].pose.yaw_rad;
    std::printf("  R %.0f ws %d: dynamics y %+8.4f mm psi %+8.4f mrad | quasi-static %+8.4f mm %+8.4f mrad | diff %+.4f mm %+.4f mrad\n",
                R, j, last.state[model.wheelset_index(j)], last.state[model.wheelset_index(j) + 1],
                1e3 * qs.wheelsets[j].pose.lateral_m, 1e3 * qs.wheelsets[j].pose.yaw_rad, dy, dpsi);
    out.max_dy_mm = std::max(out.max_dy_mm, std::fabs(dy));
    out.max_dpsi_mrad = std::max(out.max_dpsi_mrad, std::fabs(dpsi));
  }
  for (int k = model.position_count(); k < 2 * model.position_count(); ++k)
    out.max_rate = std::max(out.max_rate, std::fabs(last.state[k]));
  for (int i = 0; i < model.bogie_count(); ++i)
    std::printf("  R %.0f bogie %d: dynamics y %+8.4f mm psi %+8.4f mrad | quasi-static %+8.4f mm %+8.4f mrad\n", R, i,
                last.state[model.bogie_index(i)], last.state[model.bogie_index(i) + 1], 1e3 * qs.bogies[i].lateral_m,
                1e3 * qs.bogies[i].yaw_rad);
  std::printf("  R %.0f: %ld steps, %ld rejected, %ld contact retries, %ld f, %ld J, %ld contact solves; max rate %.2e mm/s\n",
              R, r.steps, r.rejected_steps, r.contact_failure_retries, r.derivative_evaluations, r.jacobian_evaluations,
              r.contact_evaluations, out.max_rate);
  return out;
}

TEST(VehicleDynamicsCurving, SettlesToTheQuasiStaticEquilibrium) {
  for (const double R : {600.0}) {
    const Comparison c = Compare(TwoBogieMetro(), R, 15.0, 0.04, 5.0);
    EXPECT_LT(c.max_dy_mm, 0.2) << "R " << R;
    EXPECT_LT(c.max_dpsi_mrad, 0.2) << "R " << R;
    EXPECT_LT(c.max_rate, 0.5) << "R " << R << ": not settled";
  }
}

// A contact function that fails beyond 2 mm towards the outer rail (a stand-in for a look-up table's range or a
// load control that does not converge): the run must stop with ContactFailed, name the wheelset and keep the
// history up to there, not step over the failure.
TEST(VehicleDynamicsCurving, ContactFailureStopsTheRunWithItsReason) {
  const WheelsetTrackGeometry& g = test::MetroTrackGeometry();
  const WheelContactFunction failing = [](const WheelsetTrackGeometry& gg, Side side, const WheelsetPose& pose,
                                          const WheelsetVelocity& velocity, const WheelContactOptions& o) {
    if (pose.lateral_m < -2e-3) {
      WheelContactReport r;
      r.status = WheelContactStatus::NotConverged;
      return r;
    }
    return SolveWheelContact(gg, side, pose, velocity, o);
  };
  DynamicsOptions o;
  o.model.speed_m_s = 15.0;
  o.duration_s = 2.0;
  o.output_interval_s = 0.05;
  TrackInput track;
  track.curvature_per_m = [](double) { return 1.0 / 300.0; };
  VehicleParameters v = TwoBogieMetro();
  v.bogie_count = 1;
  const VehicleDynamicsModel model(v, &g, track, o.model, failing);
  const DynamicsResult r = SimulateVehicleDynamics(model, o);
  EXPECT_EQ(r.status, DynamicsStatus::ContactFailed);
  EXPECT_NE(r.message.find("wheelset"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("not_converged"), std::string::npos) << r.message;
  EXPECT_GT(r.contact_failure_retries, 0);
  EXPECT_LT(r.simulated_time_s, o.duration_s);
  ASSERT_GE(r.history.size(), 2u);
  // the last state reached is still inside the contact function's range (within the step that failed)
  double y_min = 0.0;
  for (int j = 0; j < model.wheelset_count(); ++j) y_min = std::min(y_min, r.history.back().state[model.wheelset_index(j)]);
  EXPECT_GT(y_min, -2.0);
  EXPECT_LT(y_min, -1.5);
  std::printf("  contact failure stopped the run at t = %.4f s: %s\n", r.simulated_time_s, r.message.c_str());
}

}  // namespace
}  // namespace conforma
