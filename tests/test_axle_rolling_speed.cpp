// Axle rolling speed from the torque balance (axle_rolling_speed.hpp, docs/physics-reference.md §12.3): free
// rolling carries no net axle torque (the tangent-track samples of the wear kinematics no longer brake every wheel,
// issue 13 item 3), mirror symmetry of the centred wheelset, an applied traction torque is carried by the contact,
// a torque beyond adhesion is reported as not converged, and bad options name the field.
// S1002 on 50E4 at 1:20 (the paper-003 metro track), Hertz + FASTSIM.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/axle_rolling_speed.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"
#include "metro_test_track.hpp"

namespace conforma {
namespace {

constexpr double kRadius = test::kMetroWheelRadius;  // metro wheel (paper 003 Table 1)
constexpr double kSpeed = 70.0 / 3.6;
constexpr double kLoad = 45e3;

const WheelsetTrackGeometry& Geometry() { return test::MetroTrackGeometry(); }

struct Wheelset {
  WheelsetPose pose;
  WheelsetVelocity velocity;
};

Wheelset At(double y_m) {
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(y_m, 0.0);
  EXPECT_EQ(eq.status, EquilibriumStatus::Converged);
  Wheelset w;
  w.pose = eq.pose;
  w.velocity.forward_speed_m_s = kSpeed;
  w.velocity.axle_angular_velocity_rad_s = kSpeed / kRadius;  // the start: the nominal radius
  return w;
}

WheelContactOptions Contact() {
  WheelContactOptions o;
  o.model = ContactModel::Hertz;
  o.friction_coefficient = 0.3;
  return o;
}

double Torque(const std::array<WheelContactReport, 2>& reports) {
  double t = 0.0;
  for (const WheelContactReport& r : reports)
    for (const PatchReport& p : r.patches) t += p.fx_N * p.rolling_radius_m;
  return t;
}

double WheelFx(const WheelContactReport& r) {
  double f = 0.0;
  for (const PatchReport& p : r.patches) f += p.fx_N;
  return f;
}

TEST(AxleRollingSpeed, CentredFreeRollingHasNoLongitudinalForces) {
  const Wheelset w = At(0.0);
  AxleRollingSpeedOptions o;
  const AxleRollingSpeedResult r =
      SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
  ASSERT_EQ(r.status, AxleRollingSpeedStatus::Converged) << to_string(r.status);
  EXPECT_LE(std::fabs(r.residual_Nm), o.torque_tolerance_Nm);
  EXPECT_NEAR(Torque(r.reports), 0.0, o.torque_tolerance_Nm);
  // mirror symmetry: both wheels roll alike, so each carries no longitudinal force (< 0.1 % of mu Q)
  EXPECT_NEAR(WheelFx(r.reports[0]), 0.0, 1e-3 * 0.3 * kLoad);
  EXPECT_NEAR(WheelFx(r.reports[1]), 0.0, 1e-3 * 0.3 * kLoad);
  // the contact rolls on a radius below the nominal one (S1002 on 50E4 1:20), so the axle turns faster than V/r0;
  // at V/r0 the same pose brakes both wheels by > 1 kN (the spurious braking of the fixed axle speed)
  EXPECT_GT(r.axle_angular_velocity_rad_s, kSpeed / kRadius);
  std::array<WheelContactReport, 2> fixed;
  for (Side s : {Side::Left, Side::Right}) {
    WheelContactOptions c = Contact();
    c.vertical_load_N = kLoad;
    fixed[side_index(s)] = SolveWheelContact(Geometry(), s, w.pose, w.velocity, c);
  }
  EXPECT_LT(WheelFx(fixed[0]), -1e3);
  EXPECT_LT(WheelFx(fixed[1]), -1e3);
}

TEST(AxleRollingSpeed, OffCentreFreeRollingBalancesTheTwoWheels) {
  // shifted towards the left rail: the left wheel rolls on a larger radius, so at the common axle speed its surface
  // runs faster than the track and the rail pushes it forward; the right wheel is held back
  const Wheelset w = At(2e-3);
  AxleRollingSpeedOptions o;
  const AxleRollingSpeedResult r =
      SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
  ASSERT_EQ(r.status, AxleRollingSpeedStatus::Converged);
  EXPECT_NEAR(Torque(r.reports), 0.0, o.torque_tolerance_Nm);
  const double fl = WheelFx(r.reports[0]), fr = WheelFx(r.reports[1]);
  EXPECT_GT(fl, 10.0);
  EXPECT_LT(fr, -10.0);
  EXPECT_NEAR(fl, -fr, 0.02 * std::fabs(fl));  // equal and opposite up to the ratio of the rolling radii
}

TEST(AxleRollingSpeed, AppliedTractionTorqueIsCarriedByTheContact) {
  const Wheelset w = At(0.0);
  AxleRollingSpeedOptions o;
  o.applied_torque_Nm = 2000.0;  // ~ 5.6 kN per wheel of 13.5 kN adhesion
  const AxleRollingSpeedResult r =
      SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
  ASSERT_EQ(r.status, AxleRollingSpeedStatus::Converged);
  EXPECT_NEAR(Torque(r.reports), 2000.0, o.torque_tolerance_Nm);
  EXPECT_GT(WheelFx(r.reports[0]), 2e3);  // traction: the rail pushes both wheels forward
  EXPECT_GT(WheelFx(r.reports[1]), 2e3);
  // braking by the same torque: the mirror image in F_x
  o.applied_torque_Nm = -2000.0;
  const AxleRollingSpeedResult b =
      SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
  ASSERT_EQ(b.status, AxleRollingSpeedStatus::Converged);
  EXPECT_NEAR(Torque(b.reports), -2000.0, o.torque_tolerance_Nm);
  EXPECT_LT(b.axle_angular_velocity_rad_s, r.axle_angular_velocity_rad_s);
}

TEST(AxleRollingSpeed, TorqueBeyondAdhesionIsNotConverged) {
  const Wheelset w = At(0.0);
  AxleRollingSpeedOptions o;
  o.applied_torque_Nm = 1.2 * 0.3 * 2.0 * kLoad * kRadius;  // 20 % above full slip on both wheels
  const AxleRollingSpeedResult r =
      SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
  EXPECT_EQ(r.status, AxleRollingSpeedStatus::NotConverged);
  EXPECT_LT(r.contact_torque_Nm, o.applied_torque_Nm);
  EXPECT_TRUE(std::isfinite(r.axle_angular_velocity_rad_s));
}

TEST(AxleRollingSpeed, TangentTrackSamplesCarryNoNetAxleTorque) {
  // the wear kinematics on tangent track (kinematics_quasistatic.hpp): every sample of the Klingel oscillation
  // re-evaluated at its axle speed carries no net torque; with the old fixed V/r0 it was about -3.6 kN m
  const VehicleParameters v = MetroVehicle();
  QuasiStaticOptions o;
  o.contact = Contact();
  TrackClass t;
  t.name = "tangent";
  t.speed_m_s = kSpeed;
  t.friction_coefficient = 0.3;
  const QuasiStaticResult r = SolveQuasiStaticCurving(v, Geometry(), t, o);
  ASSERT_EQ(r.status, QuasiStaticStatus::Converged);
  EXPECT_EQ(r.tangent_rolling_failures, 0);
  ASSERT_FALSE(r.series.samples.empty());
  const double tolerance = o.residual_tolerance * v.static_wheel_load_N(o.gravity_m_s2) * kRadius;
  for (const KinematicsSample& s : r.series.samples) {
    std::array<WheelContactReport, 2> reports;
    for (Side side : {Side::Left, Side::Right}) {
      WheelContactOptions c = o.contact;
      c.vertical_load_N = s.vertical_load_N[side_index(side)];
      reports[side_index(side)] = SolveWheelContact(Geometry(), side, s.pose, s.velocity, c);
    }
    EXPECT_NEAR(Torque(reports), 0.0, tolerance) << "sample at t = " << s.time_s << " s";
  }
  // fixed axle speed (free_axle_rotation = false): the old rule, still available, keeps V / r0
  o.free_axle_rotation = false;
  const QuasiStaticResult fixed = SolveQuasiStaticCurving(v, Geometry(), t, o);
  for (const KinematicsSample& s : fixed.series.samples) {
    EXPECT_DOUBLE_EQ(s.velocity.axle_angular_velocity_rad_s, kSpeed / kRadius);
    // ... and brakes the wheelset: the torque check above is what the old samples failed
    std::array<WheelContactReport, 2> reports;
    for (Side side : {Side::Left, Side::Right}) {
      WheelContactOptions c = o.contact;
      c.vertical_load_N = s.vertical_load_N[side_index(side)];
      reports[side_index(side)] = SolveWheelContact(Geometry(), side, s.pose, s.velocity, c);
    }
    EXPECT_LT(Torque(reports), -1e3) << "sample at t = " << s.time_s << " s";
  }
}

TEST(AxleRollingSpeed, ClassDriveTorqueIsCarriedByEverySample) {
  // TrackClass::axle_torque_Nm (a traction or braking class of a metro line, scenario acceleration_m_s2): each
  // sample's contact torque equals the class's torque, on tangent track and in a curve; on tangent track it is the
  // same as applying the torque to every class (QuasiStaticOptions::axle_torque_Nm).
  const VehicleParameters v = MetroVehicle();
  QuasiStaticOptions o;
  o.contact = Contact();
  const double tolerance = o.residual_tolerance * v.static_wheel_load_N(o.gravity_m_s2) * kRadius;
  auto check = [&](const QuasiStaticResult& r, double torque, const char* what) {
    ASSERT_FALSE(r.series.samples.empty()) << what;
    for (const KinematicsSample& s : r.series.samples) {
      std::array<WheelContactReport, 2> reports;
      for (Side side : {Side::Left, Side::Right}) {
        WheelContactOptions c = o.contact;
        c.vertical_load_N = s.vertical_load_N[side_index(side)];
        reports[side_index(side)] = SolveWheelContact(Geometry(), side, s.pose, s.velocity, c);
      }
      // a quasi-static curve sample is re-evaluated at its equilibrium: the torque residual is within
      // residual_tolerance (scaled by Q0 r0) there; the tangent samples at their own axle speed
      EXPECT_NEAR(Torque(reports), torque, 10.0 * tolerance) << what << ", sample at t = " << s.time_s << " s";
    }
  };
  for (const double a : {1.0, -1.0}) {  // traction, braking at 1 m/s^2
    const double torque = v.carried_mass_per_wheelset_kg() * a * kRadius;
    TrackClass t;
    t.name = "tangent";
    t.speed_m_s = kSpeed;
    t.friction_coefficient = 0.3;
    t.axle_torque_Nm = torque;
    const QuasiStaticResult r = SolveQuasiStaticCurving(v, Geometry(), t, o);
    ASSERT_EQ(r.status, QuasiStaticStatus::Converged);
    EXPECT_EQ(r.tangent_rolling_failures, 0);
    check(r, torque, a > 0 ? "tangent, traction" : "tangent, braking");
    QuasiStaticOptions everywhere = o;
    everywhere.axle_torque_Nm = torque;
    t.axle_torque_Nm = 0.0;
    const QuasiStaticResult same = SolveQuasiStaticCurving(v, Geometry(), t, everywhere);
    ASSERT_EQ(same.series.samples.size(), r.series.samples.size());
    for (size_t i = 0; i < r.series.samples.size(); ++i)
      EXPECT_EQ(same.series.samples[i].velocity.axle_angular_velocity_rad_s,
                r.series.samples[i].velocity.axle_angular_velocity_rad_s);
    TrackClass curve = t;
    curve.name = "R800";
    curve.curve_radius_m = 800.0;
    curve.cant_m = 0.06;
    curve.speed_m_s = 65.0 / 3.6;
    curve.axle_torque_Nm = torque;
    const QuasiStaticResult rc = SolveQuasiStaticCurving(v, Geometry(), curve, o);
    ASSERT_EQ(rc.status, QuasiStaticStatus::Converged);
    check(rc, torque, a > 0 ? "R800, traction" : "R800, braking");
  }
  TrackClass bad;
  bad.speed_m_s = kSpeed;
  bad.axle_torque_Nm = std::nan("");
  EXPECT_THROW(SolveQuasiStaticCurving(v, Geometry(), bad, o), InputError);
}

TEST(AxleRollingSpeed, BadOptionsNameTheField) {
  const Wheelset w = At(0.0);
  AxleRollingSpeedOptions o;
  o.applied_torque_Nm = std::nan("");
  try {
    SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact, kRadius, o);
    FAIL() << "NaN torque accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("applied_torque_Nm"), std::string::npos) << e.what();
  }
  o = AxleRollingSpeedOptions{};
  o.max_excursion = 0.5 * o.first_step;
  EXPECT_THROW(SolveAxleRollingSpeed(Geometry(), w.pose, w.velocity, {kLoad, kLoad}, Contact(), &SolveWheelContact,
                                     kRadius, o),
               InputError);
  QuasiStaticOptions q;
  q.axle_torque_Nm = std::nan("");
  EXPECT_THROW(q.validate(), InputError);
}

}  // namespace
}  // namespace conforma
