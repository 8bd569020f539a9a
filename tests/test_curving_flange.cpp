// Flange contact in the curving solve: the Hertz wheel forces stay continuous as the flange comes into contact
// (multi-Hertz, wheel_normal_stage.cpp), and the quasi-static solve of a stiff bogie in a sharp curve finds the
// flange-contact equilibrium (multi-start, derailed attempts rejected; kinematics_quasistatic.hpp).
// Set-up: the Aosta scenario (ALn 501, S1002 on 60E1 at 1:20, r0 = 430 mm, its friction, elastic flange at 60 deg
// in the curving solve; the first test's wheel forces use a rigid or an elastic flange as stated).
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {
namespace {

const Scenario& Aosta() {
  static const Scenario sc = LoadScenario(CONFORMA_SOURCE_DIR "/scenarios/aosta_aln501.yaml");
  return sc;
}

const WheelsetTrackGeometry& Geometry() {
  static const WheelsetTrackGeometry g(Aosta().MakeTrackSetup());
  return g;
}

// Lateral force (track frame, + towards the left rail) of both wheels at the rigid equilibrium of (y, psi),
// static wheel loads, curve R 150 m at 55 km/h. elastic_flange_rad: WheelContactOptions::max_touching_contact_
// angle_rad (and the same rule for the equilibrium); right_tread_N: vertical force of the right wheel's patches
// below 0.5 rad.
double WheelsetLateralForce(double y_m, double psi_rad, double* max_right_angle_rad, double elastic_flange_rad = 1e300,
                            double* right_tread_N = nullptr, double* right_vertical_N = nullptr) {
  EquilibriumOptions eo;
  eo.max_touching_contact_angle_rad = elastic_flange_rad;
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(y_m, psi_rad, WheelsetPose{}, eo);
  EXPECT_EQ(eq.status, EquilibriumStatus::Converged) << "y = " << y_m * 1e3 << " mm";
  WheelContactOptions o;
  o.max_touching_contact_angle_rad = elastic_flange_rad;
  o.model = ContactModel::Hertz;
  o.material = Aosta().material;
  o.friction_coefficient = Aosta().friction_coefficient;
  o.vertical_load_N = Aosta().vehicle.static_wheel_load_N(9.81);
  WheelsetVelocity v;
  v.forward_speed_m_s = 55.0 / 3.6;
  v.yaw_rate_rad_s = v.forward_speed_m_s / 150.0;
  v.axle_angular_velocity_rad_s = v.forward_speed_m_s / Aosta().vehicle.nominal_wheel_radius_m;
  double Y = 0.0;
  *max_right_angle_rad = 0.0;
  for (Side side : {Side::Left, Side::Right}) {
    const WheelContactReport r = SolveWheelContact(Geometry(), side, eq.pose, v, o);
    EXPECT_EQ(r.status, WheelContactStatus::Ok);
    Y += side_sign(side) * r.lateral_force_N;
    if (side != Side::Right) continue;
    if (right_tread_N) *right_tread_N = 0.0;
    if (right_vertical_N) *right_vertical_N = r.vertical_force_N;  // what load control balances (total, issue 15)
    for (const PatchReport& p : r.patches) {
      *max_right_angle_rad = std::max(*max_right_angle_rad, p.contact_angle_rad);
      if (right_tread_N && p.contact_angle_rad < 0.5) *right_tread_N += p.vertical_force_N;
    }
  }
  return Y;
}

// Nadal's limit Y/Q = (tan delta - mu) / (1 + mu tan delta) at the flange face (70 deg) with the scenario's friction:
// the wheel on its flange with (nearly) full slip up the flange carries its load there (total-force balance, issue 15;
// with the pressure balance of before, Y/Q0 was ~2.1, about tan(70 deg) minus the creep forces).
double NadalAtTheFlangeFace() {
  const double t = std::tan(70.0 * M_PI / 180.0), mu = Aosta().friction_coefficient;
  return (t - mu) / (1.0 + mu * t);
}

TEST(CurvingFlange, HertzLateralForceRisesMonotonicallyIntoFlangeContact) {
  // Leading wheelset at an angle of attack of -8.7 mrad moved towards the right (outer) rail through the flange
  // root (~25 deg) onto the flange face (70 deg, lead ~10 mm). The rigid contact moves continuously; the wheel
  // forces must follow. One Hertz point per interpenetration region made Y drop by 0.85 Q0 within 5 um here
  // (the flange point was lost when its region merged with the flange root's, or when its pushed point had
  // B <= 0) and stalled the curving solve.
  const double Q0 = Aosta().vehicle.static_wheel_load_N(9.81);
  double previous = 0.0, angle = 0.0, max_angle = 0.0;
  for (int k = 0; k <= 50; ++k) {
    const double y = -6.20e-3 - 5e-6 * k;
    const double Y = WheelsetLateralForce(y, -8.7e-3, &angle) / Q0;
    max_angle = std::max(max_angle, angle);
    if (k > 0) {
      EXPECT_GE(Y, previous - 0.02) << "y = " << y * 1e3 << " mm";  // pushed harder towards the flange
    }
    previous = Y;
  }
  EXPECT_GT(max_angle, 69.0 * M_PI / 180.0);  // the flange face was reached
  EXPECT_GT(previous, 0.95 * NadalAtTheFlangeFace());  // and carries the load at about Nadal's limit
}

TEST(CurvingFlange, ElasticFlangeCarriesLateralForceWhileTheTreadStillCarriesLoad) {
  // 0.05 mm past flange contact (y = -6.40 mm, angle of attack -8.7 mrad): with the rigid flange the wheel has
  // already lifted onto its flange (all load at 70 deg, Y/Q0 at its plateau, Nadal's limit), with the elastic flange the
  // flange is pressed into the gauge corner and the tread still carries part of the load; both carry exactly
  // the wheel load (load control) and the elastic forces rise monotonically into the flange.
  const double Q0 = Aosta().vehicle.static_wheel_load_N(9.81);
  const double elastic = 60.0 * M_PI / 180.0;
  double angle = 0.0, tread = 0.0, vertical = 0.0;
  const double rigid_Y = WheelsetLateralForce(-6.40e-3, -8.7e-3, &angle, 1e300, &tread, &vertical) / Q0;
  EXPECT_EQ(tread, 0.0);
  EXPECT_NEAR(vertical, Q0, 1e-5 * Q0);
  EXPECT_GT(rigid_Y, 0.95 * NadalAtTheFlangeFace());
  const double elastic_Y = WheelsetLateralForce(-6.40e-3, -8.7e-3, &angle, elastic, &tread, &vertical) / Q0;
  EXPECT_GT(angle, 69.0 * M_PI / 180.0);  // the flange face carries
  EXPECT_GT(tread, 0.05 * Q0);            // and so does the tread
  EXPECT_NEAR(vertical, Q0, 1e-5 * Q0);
  EXPECT_GT(elastic_Y, 0.3);
  EXPECT_LT(elastic_Y, rigid_Y);
  double previous = 0.0;
  for (int k = 0; k <= 40; ++k) {
    const double y = -6.20e-3 - 1e-5 * k;
    const double Y = WheelsetLateralForce(y, -8.7e-3, &angle, elastic) / Q0;
    if (k > 0) {
      EXPECT_GE(Y, previous - 0.02) << "y = " << y * 1e3 << " mm";
    }
    previous = Y;
  }
  EXPECT_GT(previous, 0.95 * NadalAtTheFlangeFace());  // 0.4 mm past contact: the flange carries the whole load
}

TEST(CurvingFlange, StiffBogieInSharpCurvesConvergesAtTheFlange) {
  // R 150 m and R 200 m (classes 1 and 8, 21 % of the line): the direct and continuation starts stalled here
  // (residual 0.2-0.4 Q0) before the multi-start; an attempt beyond the flange (|y| 17-65 mm) must never win.
  const QuasiStaticOptions o = ScenarioQuasiStaticOptions(Aosta(), ContactModel::Hertz);
  const double flange = std::fabs(FlangeContactShift(Geometry(), 1.0));
  for (int index : {1, 8}) {
    const TrackClass& tc = Aosta().classes[index];
    const QuasiStaticResult r = SolveQuasiStaticCurving(Aosta().vehicle, Geometry(), tc, o);
    ASSERT_EQ(r.status, QuasiStaticStatus::Converged) << tc.name;
    for (const BogieQuasiStaticReport& b : r.bogies) {
      EXPECT_FALSE(b.derailed) << tc.name;
      for (double res : b.residuals) EXPECT_LE(std::fabs(res), o.residual_tolerance) << tc.name;
    }
    for (const WheelsetQuasiStaticReport& w : r.wheelsets)
      EXPECT_LE(std::fabs(w.pose.lateral_m), flange + o.derailment_margin_m) << tc.name << " wheelset " << w.wheelset;
    // The leading wheelset of each bogie runs on the outer (right) flange, below Nadal's climbing limit
    // (tan 70 deg - mu) / (1 + mu tan 70 deg) (1.34 at mu = 0.3).
    const double mu = tc.friction_coefficient, t70 = std::tan(70.0 * M_PI / 180.0);
    const double nadal = (t70 - mu) / (1.0 + mu * t70);
    for (int j : {0, 2}) {
      const WheelQuasiStaticReport& outer = r.wheelsets[j].wheel[side_index(Side::Right)];
      EXPECT_TRUE(outer.flange_contact) << tc.name << " wheelset " << j;
      EXPECT_GT(outer.y_over_q, 0.0) << tc.name;
      EXPECT_LT(outer.y_over_q, nadal) << tc.name;
    }
  }
}

}  // namespace
}  // namespace conforma
