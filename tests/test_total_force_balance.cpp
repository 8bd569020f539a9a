// Total-force load control (issue 15, docs/physics-reference.md §3.6.1): the wheel's total vertical force, pressure
// and creep forces of all patches, carries the load. Nadal's flange-climbing limit and Manchester.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/validation/validation_manchester.hpp"
#include "conforma/wheel_contact.hpp"

using namespace conforma;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// S1002 on 60E1 at 1:40 with the wheel profile's lateral coordinate scaled by k about the taping line (k = 1: the
// standard track): the flange flank's 70 deg steepens to atan(tan 70 deg / k), so that k = 0.7 reaches 75 deg.
WheelsetTrackGeometry MakeTrack(double k) {
  const Profile s1002 = MakeS1002();
  std::vector<Eigen::Vector2d> points = s1002.sample(0.1e-3);
  for (Eigen::Vector2d& p : points) p.x() *= k;
  const Profile wheel = k == 1.0 ? s1002 : Profile::FromPoints(points, ProfileKind::Wheel);
  TrackSetup setup = MakeSymmetricTrack(wheel, MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40());
  setup.flange_back_position_m *= k;
  return WheelsetTrackGeometry(std::move(setup));
}
const WheelsetTrackGeometry& Track(int which) {
  static const WheelsetTrackGeometry standard = MakeTrack(1.0), steep = MakeTrack(0.7);
  return which == 0 ? standard : steep;
}

WheelsetVelocity Rolling(double yaw_rate = 0.0) { return {20.0, 0.0, yaw_rate, 20.0 / 0.46}; }

// The left wheel pressed against its flange: the wheelset shifted by y towards the left rail, at the rigid
// equilibrium's roll (both wheels touching; roll_rad NaN) or at the given roll (the straight flange flank then
// touches the rail's gauge corner at its own angle minus the roll), with a yaw (angle of attack); the load control
// lowers the wheel onto the rail.
WheelsetPose FlangePose(const WheelsetTrackGeometry& track, double y_m, double roll_rad, double yaw_rad) {
  if (std::isnan(roll_rad)) {
    const EquilibriumResult e = track.SolveRigidEquilibrium(y_m, yaw_rad);
    EXPECT_EQ(e.status, EquilibriumStatus::Converged);
    return e.pose;
  }
  WheelsetPose pose;
  pose.lateral_m = y_m;
  pose.roll_rad = roll_rad;
  pose.yaw_rad = yaw_rad;
  return pose;
}

struct FlangeContact {
  int track = 0;
  double y_m = 0.0, roll_rad = 0.0, delta_rad = 0.0;
  WheelsetPose pose(double yaw_rad) const { return FlangePose(Track(track), y_m, roll_rad, yaw_rad); }
};

// Poses of the left wheel with one patch only, on the flange: for each target angle, the pose whose (Hertz) contact
// angle is nearest to it, from shifts on the standard track at equilibrium (57 to 70 deg) and on the steep one at
// roll 0 (62 to 75.7 deg).
std::vector<FlangeContact> FlangeContacts(const std::vector<double>& targets_deg) {
  std::vector<FlangeContact> scan;
  WheelContactOptions o;
  o.solve_tangential = false;
  const double nan = std::nan("");
  for (const auto& [track, roll, y_min, y_max] : {std::tuple<int, double, double, double>{0, nan, 6.0e-3, 8.0e-3},
                                                  {1, 0.0, 16e-3, 20e-3}}) {
    for (double y = y_min; y <= y_max; y += 0.05e-3) {
      const FlangeContact c{track, y, roll, 0.0};
      const WheelContactReport r = SolveWheelContact(Track(track), Side::Left, c.pose(0.0), Rolling(), o);
      if (std::getenv("NADAL_SCAN"))
        std::printf("scan track %d roll %.0f mrad y %.2f mm: %s %zu patches %.2f deg\n", track, roll * 1e3, y * 1e3,
                    to_string(r.status), r.patches.size(), r.patches.empty() ? 0.0 : r.patches[0].contact_angle_rad / kDeg);
      if (r.status == WheelContactStatus::Ok && r.patches.size() == 1)
        scan.push_back({track, y, roll, r.patches[0].contact_angle_rad});
    }
  }
  std::vector<FlangeContact> out;
  for (double target : targets_deg) {
    const FlangeContact* best = nullptr;
    for (const FlangeContact& c : scan)
      if (!best || std::fabs(c.delta_rad - target * kDeg) < std::fabs(best->delta_rad - target * kDeg)) best = &c;
    if (!best || std::fabs(best->delta_rad - target * kDeg) >= 1.0 * kDeg) continue;
    // a plateau of one angle over a range of shifts is a straight flank riding on the gauge corner: its middle
    // keeps the patch away from the flank's ends (where the flange curves)
    std::vector<const FlangeContact*> plateau;
    for (const FlangeContact& c : scan)
      if (c.track == best->track && std::fabs(c.delta_rad - best->delta_rad) < 0.01 * kDeg) plateau.push_back(&c);
    out.push_back(*plateau[plateau.size() / 2]);
  }
  return out;
}

}  // namespace

// Nadal (1908): a wheel on its flange at contact angle delta, in full slip along the flange with the creep force
// on the wheel pointing up the flange (the wheel slides down relative to the rail: a positive angle of attack),
// Y = N sin(delta) - mu N cos(delta), Q = N cos(delta) + mu N sin(delta), so Y/Q = (tan delta - mu)/(1 + mu tan delta).
// With the total-force balance Q is the load; with the pressure balance the wheel would carry Q = N cos(delta).
TEST(TotalForceBalance, NadalLimitOfAWheelSlidingOnItsFlange) {
  // 75.7 deg: the steep track's straight flank (its first pose, well inside the flank: a patch reaching into the
  // flange root is curved, and Nadal's formula is for one contact angle)
  const std::vector<FlangeContact> contacts = FlangeContacts({60.0, 62.5, 65.0, 67.5, 70.0, 72.5, 75.7});
  ASSERT_EQ(contacts.size(), 7u);
  EXPECT_LE(contacts.front().delta_rad, 60.5 * kDeg);
  EXPECT_GE(contacts.back().delta_rad, 75.0 * kDeg);
  // the sign of the lateral creepage of a positive angle of attack at the flange, from the wheelset kinematics
  const FlangeContact& first = contacts.front();
  WheelContactOptions kinematic;
  kinematic.solve_tangential = false;
  const WheelContactReport yawed = SolveWheelContact(Track(first.track), Side::Left,
                                                     first.pose(5e-3), Rolling(), kinematic);
  ASSERT_EQ(yawed.patches.size(), 1u);
  WheelContactOptions with_creep = kinematic;
  with_creep.solve_tangential = true;
  const WheelContactReport yawed_creep = SolveWheelContact(
      Track(first.track), Side::Left, first.pose(5e-3), Rolling(), with_creep);
  ASSERT_EQ(yawed_creep.patches.size(), 1u);
  const double eta_sign = yawed_creep.patches[0].eta < 0.0 ? -1.0 : 1.0;
  // the creep force of a positive angle of attack points up the flange (+t0) on the wheel
  EXPECT_GT(yawed_creep.patches[0].fy_N, 0.0);
  std::printf("positive angle of attack (yaw 5 mrad): eta %.4f, fy %.0f N along +t0\n", yawed_creep.patches[0].eta,
              yawed_creep.patches[0].fy_N);

  std::printf(" model      track delta_deg  mu   Y/Q      Nadal    error_%%  Fz/load-1   Fn_N\n");
  for (ContactModel model : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal,
                             ContactModel::Exact, ContactModel::Auto}) {
    for (const FlangeContact& c : contacts) {
      for (double mu : {0.2, 0.3, 0.4, 0.5}) {
        WheelContactOptions o;
        o.model = model;
        o.friction_coefficient = mu;
        o.vertical_load_N = 20e3;
        o.creepages_given = true;
        o.creepages = {0.0, eta_sign * 0.5, 0.0};  // full lateral slip: 50 % of the rolling speed
        const WheelContactReport r =
            SolveWheelContact(Track(c.track), Side::Left, c.pose(0.0), Rolling(), o);
        ASSERT_EQ(r.status, WheelContactStatus::Ok) << to_string(model) << " y " << c.y_m;
        ASSERT_EQ(r.patches.size(), 1u);
        const PatchReport& p = r.patches[0];
        EXPECT_GT(p.fy_N, 0.99 * mu * p.fn_N) << "full slip up the flange";
        // delta: the direction of the patch's pressure resultant (Nadal's normal force). The report gives the
        // wheel's force as fn n0 + (fs + fy) t0 at the reference angle delta0 (n0 = (-sin, cos), t0 = (cos, sin) in
        // (eta, z)); the KP models' pressure part fs along t0 turns the resultant by -atan(fs / fn) (0 for hertz).
        const double d0 = p.contact_angle_rad;
        const double along_t0 = p.lateral_force_N * std::cos(d0) + p.vertical_force_N * std::sin(d0);
        const double delta = d0 - std::atan((along_t0 - p.fy_N) / p.fn_N);
        // Y on the wheel towards the track centre, Q the load (Y / F_z alone would not depend on the balance for one
        // patch in full slip: the test is that the load is carried by F_z = N cos(delta) + mu N sin(delta))
        const double y_over_q = -r.lateral_force_N / o.vertical_load_N;
        const double nadal = (std::tan(delta) - mu) / (1.0 + mu * std::tan(delta));
        const double error = y_over_q / nadal - 1.0;
        std::printf(" %-10s %d     %7.2f  %.1f  %.5f  %.5f  %+7.3f  %+.1e  %.0f\n", to_string(model), c.track,
                    delta / kDeg, mu, y_over_q, nadal, 100.0 * error, r.vertical_force_N / o.vertical_load_N - 1.0,
                    p.fn_N);
        EXPECT_NEAR(r.vertical_force_N, o.vertical_load_N, 1e-5 * o.vertical_load_N);
        EXPECT_LT(std::fabs(error), 0.01) << to_string(model) << " delta " << delta / kDeg << " mu " << mu;
        if (model == ContactModel::Hertz && mu == 0.3) {  // the pressure balance carries Q = N cos(delta) instead
          WheelContactOptions pressure = o;
          pressure.load_balance = LoadBalance::Pressure;
          const WheelContactReport rp = SolveWheelContact(Track(c.track), Side::Left, c.pose(0.0), Rolling(), pressure);
          const double y_over_q_pressure = -rp.lateral_force_N / o.vertical_load_N;
          EXPECT_NEAR(y_over_q_pressure, std::tan(delta) - mu, 1e-3 * std::tan(delta));
          EXPECT_GT(y_over_q_pressure / nadal - 1.0, 0.5);
        }
      }
    }
  }
}

// Manchester A-2.2 (left wheel, 21 cases, the file's creepages): the wheel's total vertical force carries the
// 10 kN to 0.1 % with every model, and the pressure part alone differs from it by the creep forces' vertical part.
TEST(TotalForceBalance, ManchesterA22TotalVerticalForceIsTheLoadForEveryModel) {
  std::printf(" model      worst |Fz/Q - 1|  worst |Pz/Q - 1|  load iterations (mean)\n");
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal,
                         ContactModel::Exact, ContactModel::Auto}) {
    ManchesterOptions o;
    o.model = m;
    const std::vector<ManchesterComparison> rows = RunManchesterA22(CONFORMA_SHARED_DATA, o);
    ASSERT_EQ(rows.size(), 21u);
    double worst_total = 0.0, worst_pressure = 0.0, iterations = 0.0;
    for (const ManchesterComparison& r : rows) {
      ASSERT_EQ(r.report.status, WheelContactStatus::Ok) << to_string(m) << " case " << r.reference.id;
      EXPECT_NEAR(r.report.vertical_force_N, 10e3, 1e-3 * 10e3) << to_string(m) << " case " << r.reference.id;
      worst_total = std::max(worst_total, std::fabs(r.report.vertical_force_N / 10e3 - 1.0));
      worst_pressure = std::max(worst_pressure, std::fabs(r.report.pressure_vertical_force_N / 10e3 - 1.0));
      iterations += r.report.load_iterations / 21.0;
    }
    std::printf(" %-10s %.2e          %.2e          %.1f\n", to_string(m), worst_total, worst_pressure, iterations);
  }
}

// The flange family of issue 15: Manchester A-2.2's poses for y = 5…10 mm (yaw 2.4 y mrad, the file's roll) seen
// from the RIGHT wheel, which the shift pushes into flange-root and flange-flank contact; creepages from the
// wheelset kinematics, mu 0.3. The wheel's total vertical force carries the 10 kN to 0.1 % with every model, and the
// flank is reached (a patch above 60 deg), where the creep forces' vertical part is a large part of the load.
TEST(TotalForceBalance, RightWheelFlangeCasesTotalVerticalForceIsTheLoadForEveryModel) {
  const std::string examples = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/examples/";
  ProfileReadOptions wheel_read, rail_read;
  wheel_read.kind = ProfileKind::Wheel;
  rail_read.kind = ProfileKind::Rail;
  const WheelsetTrackGeometry geometry(MakeSymmetricTrack(LoadProfile(examples + "MBench_S1002_v3.prw", wheel_read),
                                                          LoadProfile(examples + "MBench_UIC60_v3.prr", rail_read), 0.0));
  std::vector<ManchesterReferenceCase> cases;
  for (const ManchesterReferenceCase& c :
       ReadManchesterReference(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_mbench_a22_left.csv"))
    if (c.y_ws_mm >= 5.0) cases.push_back(c);
  ASSERT_EQ(cases.size(), 11u);
  std::printf(" model      worst |Fz/Q - 1|  worst |Pz/Q - 1|  steepest patch deg  load iterations (mean)\n");
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal,
                         ContactModel::Exact, ContactModel::Auto}) {
    double worst_total = 0.0, worst_pressure = 0.0, steepest = 0.0, iterations = 0.0;
    for (const ManchesterReferenceCase& c : cases) {
      WheelsetPose pose;
      pose.lateral_m = -c.y_ws_mm * 1e-3;  // CONTACT's track y points to the right (as RunManchesterA22)
      pose.yaw_rad = -c.yaw_mrad * 1e-3;
      pose.roll_rad = c.roll_rad;
      WheelContactOptions o;
      o.model = m;
      o.material.shear_modulus_Pa = 82e9;
      o.material.poisson_ratio = 0.28;
      o.friction_coefficient = 0.3;
      o.vertical_load_N = 10e3;
      const WheelContactReport r = SolveWheelContact(geometry, Side::Right, pose, {2.0, 0.0, 0.0, 2.0 / 0.46}, o);
      ASSERT_EQ(r.status, WheelContactStatus::Ok) << to_string(m) << " y " << c.y_ws_mm;
      EXPECT_NEAR(r.vertical_force_N, 10e3, 1e-3 * 10e3) << to_string(m) << " y " << c.y_ws_mm;
      worst_total = std::max(worst_total, std::fabs(r.vertical_force_N / 10e3 - 1.0));
      worst_pressure = std::max(worst_pressure, std::fabs(r.pressure_vertical_force_N / 10e3 - 1.0));
      for (const PatchReport& p : r.patches) steepest = std::max(steepest, std::fabs(p.contact_angle_rad) / kDeg);
      iterations += r.load_iterations / static_cast<double>(cases.size());
    }
    std::printf(" %-10s %.2e          %.2e          %5.1f               %.1f\n", to_string(m), worst_total,
                worst_pressure, steepest, iterations);
    EXPECT_GT(steepest, 60.0) << to_string(m) << ": the flange flank is not reached";
    EXPECT_GT(worst_pressure, 0.05) << to_string(m) << ": the creep forces carry part of the load at the flange";
  }
}
