// test-links: rig
// Roller-rig kinematics (paper 000 eq. 2, docs/physics-reference.md §18.2): the free wheelset speed from the moment
// balance against eq. 2's first approximation in the linear range, the balance of the contact and spring forces,
// mirror symmetry, and the statuses.
#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/roller_rig_kinematics.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;
double Rpm(double rpm) { return rpm * 2.0 * kPi / 60.0; }

struct Rig {
  RollerRigSetup setup;
  std::unique_ptr<WheelsetTrackGeometry> geometry;
  RollerRigKinematicsOptions options;
  Rig() {
    const Profile w = MakeRollerRigWheelProfile(setup), r = MakeRollerRigRollerProfile(setup);
    geometry = std::make_unique<WheelsetTrackGeometry>(MakeRollerRigTrack(setup, {w, w}, {r, r}),
                                                       RollerRigGeometryOptions(setup));
    options.contact = RollerRigContactOptions(setup);
  }
  // roller 2 slower so that eq. 2 gives creepages +xi / -xi at equal radii
  RollerRigKinematicsInput Input(double xi, double y = 0.0) const {
    RollerRigKinematicsInput in;
    in.lateral_m = y;
    in.roller_speed_rad_s = {Rpm(500.0), Rpm(500.0) * (1.0 - xi) / (1.0 + xi)};
    in.wheel_load_N = {50.0 * 9.81, 50.0 * 9.81};
    return in;
  }
};

TEST(RigKinematics, Eq2CreepageAndFirstApproximation) {
  EXPECT_DOUBLE_EQ(RollerRigCreepage(10.0, 0.2, 20.0, 0.1), 0.0);
  EXPECT_NEAR(RollerRigCreepage(10.0, 0.2, 19.0, 0.1), 0.05, 1e-15);
  const double w3 = RollerRigEq2WheelsetSpeed({10.0, 9.0}, {0.185, 0.185}, {0.0944, 0.0944});
  const double x1 = RollerRigCreepage(10.0, 0.185, w3, 0.0944), x2 = RollerRigCreepage(9.0, 0.185, w3, 0.0944);
  EXPECT_NEAR(x1, -x2, 1e-15);
  EXPECT_GT(x1, 0.0);
  EXPECT_THROW(RollerRigCreepage(0.0, 0.185, 1.0, 0.0944), InputError);
}

// Linear range (xi = 1e-4, saturation near 5e-3): the balanced omega_3 and both creepages agree with eq. 2's first
// approximation within 1 %, centred and with a lateral shift (different rolling radii); the moment balances.
TEST(RigKinematics, LinearRangeAgreesWithEq2) {
  Rig rig;
  for (double y : {0.0, 0.4e-3, -0.8e-3}) {
    const RollerRigKinematicsResult r = SolveRollerRigKinematics(*rig.geometry, rig.setup, rig.Input(1e-4, y), rig.options);
    ASSERT_EQ(r.status, RollerRigKinematicsStatus::Converged) << r.message;
    const auto& c = r.contact;
    const double w_eq2 = r.eq2_wheelset_speed_rad_s;
    EXPECT_NEAR(r.wheelset_speed_rad_s, w_eq2, 1e-2 * w_eq2 * 1e-4) << y;  // 1 % of the creepage-sized difference
    const double w = rig.Input(1e-4, y).roller_speed_rad_s[0], w2 = rig.Input(1e-4, y).roller_speed_rad_s[1];
    const double x1_eq2 = RollerRigCreepage(w, c[0].roller_rolling_radius_m, w_eq2, c[0].wheel_rolling_radius_m);
    const double x2_eq2 = RollerRigCreepage(w2, c[1].roller_rolling_radius_m, w_eq2, c[1].wheel_rolling_radius_m);
    EXPECT_NEAR(c[0].xi, x1_eq2, 0.01 * std::abs(x1_eq2)) << y;
    EXPECT_NEAR(c[1].xi, x2_eq2, 0.01 * std::abs(x2_eq2)) << y;
    // the solver's creepage is eq. 2 at the solved omega_3 with the effective radius r - delta, up to the load
    // control's last push after the reported approach (~3 nm here: 3e-8 in creepage)
    EXPECT_NEAR(c[0].eq2_creepage, c[0].xi, 1e-7) << y;
    EXPECT_NEAR(c[1].eq2_creepage, c[1].xi, 1e-7) << y;
    if (y == 0.0) {
      EXPECT_LT(c[0].fx_N, 0.0);
    }  // roller 1 faster: xi_1 > 0, the force on the wheel opposes it
    const double scale = c[0].wheel_rolling_radius_m * std::abs(c[0].fx_N) + c[1].wheel_rolling_radius_m * std::abs(c[1].fx_N);
    EXPECT_LE(std::abs(r.axle_moment_residual_Nm), 1e-6 * scale) << y;
  }
}

// Beyond the linear range and with unequal loads the balance, not eq. 2, sets omega_3; the forces balance: the
// axle moment within 1e-6 and the springs carry the rest (force and moment about z).
TEST(RigKinematics, ForcesBalanceWithTheSprings) {
  Rig rig;
  RollerRigKinematicsInput in = rig.Input(0.02, 0.5e-3);
  in.wheel_load_N = {43.0 * 9.81, 53.0 * 9.81};
  const RollerRigKinematicsResult r = SolveRollerRigKinematics(*rig.geometry, rig.setup, in, rig.options);
  ASSERT_EQ(r.status, RollerRigKinematicsStatus::Converged) << r.message;
  const auto& c = r.contact;
  const double scale = std::abs(c[0].fx_N) + std::abs(c[1].fx_N);
  EXPECT_GT(scale, 0.1 * 9.81 * 43.0 * 0.3);
  EXPECT_LE(std::abs(r.axle_moment_residual_Nm),
            1e-6 * (c[0].wheel_rolling_radius_m * std::abs(c[0].fx_N) + c[1].wheel_rolling_radius_m * std::abs(c[1].fx_N)));
  EXPECT_LE(std::abs(c[0].fx_N + c[1].fx_N + r.spring_force_N[0] + r.spring_force_N[1]), 1e-6 * scale);
  const double bs = rig.setup.spring_half_spacing_m;
  const double mz = -c[0].contact_y_m * c[0].fx_N - c[1].contact_y_m * c[1].fx_N - bs * r.spring_force_N[0] +
                    bs * r.spring_force_N[1];
  EXPECT_LE(std::abs(mz), 1e-6 * scale * bs);
  // unequal loads: the creepages are not opposite (the lighter wheel creeps more), and omega_3 differs from eq. 2
  EXPECT_GT(std::abs(c[0].xi), std::abs(c[1].xi));
  EXPECT_NE(r.wheelset_speed_rad_s, r.eq2_wheelset_speed_rad_s);
  // the yaw deflection follows from the opposite forces and the springs: small ("high stiffness", paper 000 §3.1)
  EXPECT_LT(std::abs(r.yaw_deflection_rad), 1e-3);
}

// Swapping the roller speeds (and mirroring y) mirrors the creepages and forces.
TEST(RigKinematics, SwapRollerSpeedsMirrors) {
  Rig rig;
  for (double y : {0.0, 0.3e-3}) {
    RollerRigKinematicsInput a = rig.Input(0.01, y), b = a;
    b.roller_speed_rad_s = {a.roller_speed_rad_s[1], a.roller_speed_rad_s[0]};
    b.lateral_m = -y;
    const auto ra = SolveRollerRigKinematics(*rig.geometry, rig.setup, a, rig.options);
    const auto rb = SolveRollerRigKinematics(*rig.geometry, rig.setup, b, rig.options);
    ASSERT_EQ(ra.status, RollerRigKinematicsStatus::Converged);
    ASSERT_EQ(rb.status, RollerRigKinematicsStatus::Converged);
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(ra.contact[k].xi, rb.contact[1 - k].xi, 1e-6 * std::abs(ra.contact[k].xi)) << y;
      EXPECT_NEAR(ra.contact[k].fx_N, rb.contact[1 - k].fx_N, 1e-6 * std::abs(ra.contact[k].fx_N)) << y;
    }
    EXPECT_NEAR(ra.wheelset_speed_rad_s, rb.wheelset_speed_rad_s, 1e-9 * ra.wheelset_speed_rad_s);
  }
}

TEST(RigKinematics, StatusesAndErrors) {
  Rig rig;
  RollerRigKinematicsInput in = rig.Input(0.01);
  in.wheelset_speed_rad_s = rig.Input(0.01).roller_speed_rad_s[0] * 0.185 / 0.0944;
  const auto m = SolveRollerRigKinematics(*rig.geometry, rig.setup, in, rig.options);
  EXPECT_EQ(m.status, RollerRigKinematicsStatus::Measured);
  EXPECT_EQ(m.evaluations, 1);
  in.wheel_load_N[1] = 0.0;
  EXPECT_EQ(SolveRollerRigKinematics(*rig.geometry, rig.setup, in, rig.options).status,
            RollerRigKinematicsStatus::NoContact);
  in.roller_speed_rad_s[0] = -1.0;
  EXPECT_THROW(SolveRollerRigKinematics(*rig.geometry, rig.setup, in, rig.options), InputError);
}

// Valid input, but a contact solve rejects the patch (here: the exact model's grid exceeds its element budget; on worn
// profiles e.g. a patch turning beyond 90 degrees): a status with the solver's message, not an exception that would
// end a whole test plan.
TEST(RigKinematics, ContactSolveRejectionIsAStatus) {
  Rig rig;
  rig.options.contact.model = ContactModel::Exact;
  rig.options.contact.exact_max_elements = 4;
  const auto r = SolveRollerRigKinematics(*rig.geometry, rig.setup, rig.Input(0.01), rig.options);
  EXPECT_EQ(r.status, RollerRigKinematicsStatus::ContactError);
  EXPECT_NE(r.message.find("contact solve failed on the current profiles"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("exact_max_elements"), std::string::npos) << r.message;
  EXPECT_STREQ(to_string(r.status), "contact_error");
}

}  // namespace
}  // namespace conforma
