// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)
// Wheel on roller (TrackSetup::roller_radius_m, geometry.hpp WHEEL ON ROLLER, docs/physics-reference.md §1.7):
// the rail limit R_r -> infinity, the crossed-cylinder Hertz solution (Johnson 1985 §4.2, elliptical contact) and a
// brute-force 3-D closest-point check of the rigid search at yaw.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/hertz.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"
#include "pipeline_test_geometry.hpp"

using namespace conforma;

namespace {

double Rel(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

// ---------------------------------------------------------------------------------------------------------------
// 1. R_r -> infinity: a roller of radius 1e15 m is the rail (its drop x^2 / (2 R_r) ~ 1e-20 m at x ~ 4 mm, its
// curvature 5e-16 1/m against A ~ 1 1/m), so every result must agree with the rail's to round-off; 1e-9 relative
// is far above round-off (~1e-15) and far below any physical effect of the roller.
// ---------------------------------------------------------------------------------------------------------------

const WheelsetTrackGeometry& HugeRollers() {
  static const WheelsetTrackGeometry g([] {
    TrackSetup t = test::PipelineGeometry().setup();
    t.roller_radius_m = {1e15, 1e15};
    return t;
  }());
  return g;
}

struct PoseCase {
  double y_mm, yaw_mrad;
};
const PoseCase kPoses[] = {{0.0, 2.0}, {3.0, -3.0}, {-4.0, 5.0}, {6.0, 4.0}};

// relative difference with a floor: the quantity's scale (positions: 1 mm) so that values near 0 compare absolutely
double Diff(double roller, double rail, double floor) {
  return std::fabs(roller - rail) / std::max(std::fabs(rail), floor);
}

TEST(RollerGeometry, HugeRollerReproducesTheRailContactPoints) {
  double worst = 0.0;
  for (const PoseCase& pc : kPoses) {
    const WheelsetPose pose = test::Pose(pc.y_mm, pc.yaw_mrad);
    const WheelsetContactResult rail = test::PipelineGeometry().RigidContacts(pose);
    const WheelsetContactResult roll = HugeRollers().RigidContacts(pose);
    for (int s = 0; s < 2; ++s) {
      const auto& a = rail.wheel[s].points;
      const auto& b = roll.wheel[s].points;
      ASSERT_EQ(a.size(), b.size()) << pc.y_mm << " mm, side " << s;
      for (size_t k = 0; k < a.size(); ++k) {
        for (int i = 0; i < 3; ++i) {
          worst = std::max(worst, Diff(b[k].wheel_point_m(i), a[k].wheel_point_m(i), 1e-3));
          worst = std::max(worst, Diff(b[k].rail_point_m(i), a[k].rail_point_m(i), 1e-3));
        }
        worst = std::max(
            {worst, Diff(b[k].rolling_radius_m, a[k].rolling_radius_m, 1e-3), Diff(b[k].lead_m, a[k].lead_m, 1e-3),
             Diff(b[k].gap_m, a[k].gap_m, 1e-3), Diff(b[k].contact_angle_rad, a[k].contact_angle_rad, 1e-3),
             Diff(b[k].hertz_A_per_m, a[k].hertz_A_per_m, 1e-3), Diff(b[k].hertz_B_per_m, a[k].hertz_B_per_m, 1e-3)});
        EXPECT_EQ(a[k].roller_rolling_radius_m, 0.0);
        EXPECT_NEAR(b[k].roller_rolling_radius_m, 1e15 + b[k].rail_profile_m.y(), 1.0);
      }
    }
  }
  std::printf("R_r = 1e15 m vs rail, contact points at 4 poses (both sides): largest relative difference %.2e\n",
              worst);
  EXPECT_LT(worst, 1e-9);
}

// The rigid equilibrium (vertical position and roll) solved on each: the solver stops when the right wheel's gap is
// below EquilibriumOptions::tolerance_m = 1e-10 m, so the two solutions may differ by about that much in height and
// 1e-10 / (track half width) in roll, whatever the geometry's agreement; bounded with a margin of 10.
TEST(RollerGeometry, HugeRollerReproducesTheRailEquilibrium) {
  double dz = 0.0, droll = 0.0;
  for (const PoseCase& pc : kPoses) {
    const EquilibriumResult rail = test::PipelineGeometry().SolveRigidEquilibrium(pc.y_mm * 1e-3, pc.yaw_mrad * 1e-3);
    const EquilibriumResult roll = HugeRollers().SolveRigidEquilibrium(pc.y_mm * 1e-3, pc.yaw_mrad * 1e-3);
    ASSERT_EQ(rail.status, EquilibriumStatus::Converged);
    ASSERT_EQ(roll.status, EquilibriumStatus::Converged);
    dz = std::max(dz, std::fabs(roll.pose.vertical_m - rail.pose.vertical_m));
    droll = std::max(droll, std::fabs(roll.pose.roll_rad - rail.pose.roll_rad));
  }
  std::printf("R_r = 1e15 m vs rail, rigid equilibrium at 4 poses: vertical %.2e m, roll %.2e rad\n", dz, droll);
  EXPECT_LT(dz, 1e-9);
  EXPECT_LT(droll, 1e-9 / 0.75);
}

TEST(RollerGeometry, HugeRollerReproducesTheRailForces) {
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Conformal}) {
    double worst = 0.0;
    for (const PoseCase& pc : kPoses) {
      const WheelsetPose pose = test::Pose(pc.y_mm, pc.yaw_mrad);
      WheelContactOptions o;
      o.model = m;
      for (Side side : {Side::Left, Side::Right}) {
        const WheelContactReport a = SolveWheelContact(test::PipelineGeometry(), side, pose, test::Rolling(), o);
        const WheelContactReport b = SolveWheelContact(HugeRollers(), side, pose, test::Rolling(), o);
        ASSERT_EQ(a.status, WheelContactStatus::Ok);
        ASSERT_EQ(b.status, WheelContactStatus::Ok);
        ASSERT_EQ(a.patches.size(), b.patches.size());
        for (size_t j = 0; j < a.patches.size(); ++j) {
          const PatchReport &p = a.patches[j], &q = b.patches[j];
          const double f = std::fabs(p.fn_N);
          worst = std::max({worst, Rel(q.fn_N, p.fn_N), Rel(q.pmax_Pa, p.pmax_Pa), Diff(q.fx_N, p.fx_N, f),
                            Diff(q.fy_N, p.fy_N, f), Rel(q.area_m2, p.area_m2),
                            Diff(q.rolling_radius_m, p.rolling_radius_m, 1e-3)});
        }
      }
    }
    std::printf("R_r = 1e15 m vs rail, %s model (fn, pmax, fx, fy, area, r): largest relative difference %.2e\n",
                to_string(m), worst);
    EXPECT_LT(worst, 1e-9) << to_string(m);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Crowned profiles: circles of transverse radius R_c (wheel: radial height, rail/roller: z up), top at y = y_top.
// ---------------------------------------------------------------------------------------------------------------
double Crown(double R, double y) { return -(R - std::sqrt(R * R - y * y)); }
double CrownSlope(double R, double y) { return -y / std::sqrt(R * R - y * y); }

Profile CrownProfile(double R, double half_width, ProfileKind kind) {
  std::vector<Eigen::Vector2d> pts;
  const int n = static_cast<int>(std::lround(2 * half_width / 0.05e-3));
  for (int i = 0; i <= n; ++i) {
    const double y = -half_width + i * 0.05e-3;
    pts.emplace_back(y, Crown(R, y));
  }
  return Profile::FromPoints(pts, kind, {}, kind == ProfileKind::Wheel ? "crowned wheel" : "crowned roller");
}

// A wheelset with crowned wheels (nominal radius r0, crown R_w) on crowned rollers (R_r, crown R_rc), the gauge set so
// that both crowns' tops face each other at lateral shift 0 (the roller top at eta = wheel-profile origin).
WheelsetTrackGeometry CrownedRig(double r0, double crown_w, double roller_radius, double crown_r) {
  TrackSetup t = MakeSymmetricTrack(CrownProfile(crown_w, 0.03, ProfileKind::Wheel),
                                    CrownProfile(crown_r, 0.03, ProfileKind::Rail));
  t.nominal_radius_m = {r0, r0};
  t.roller_radius_m = {roller_radius, roller_radius};
  t.gauge_height_m = 0.2e-3;  // the crowns drop only a few mm
  const WheelsetTrackGeometry first(t);
  t.gauge_m += 2.0 * (first.wheel_origin_eta_m() - first.rail_origin_eta_m(Side::Left));
  return WheelsetTrackGeometry(t);
}

// Johnson (1985) §4.2 (the ellipsoidal pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) and its displacements; a form
// independent of hertz.cpp's, docs/physics-reference.md §1.2): an elliptical Hertz contact of h = A x^2 + B y^2
// (A <= B: the major semi-axis a along x) carries P = (2/3) pi a b p0 with
//   A = (p0 / E*) (b / (e^2 a^2)) (K(e) - E(e)),   B = (p0 / E*) (b / (e^2 a^2)) ((a/b)^2 E(e) - K(e)),
//   delta = (p0 b / E*) K(e),   e^2 = 1 - (b/a)^2,   E* = E / (2 (1 - nu^2)) for two equal bodies,
// solved here with std::comp_ellint_1/2 (modulus e): bisection of B/A in b/a, then a^3 from P.
struct AnalyticHertz {
  double a, b, p0, delta;
};
AnalyticHertz JohnsonEllipse(double A, double B, double P, const Material& mat) {
  EXPECT_LE(A, B);
  const double E_star = mat.young_modulus_Pa() / (2.0 * (1.0 - mat.poisson_ratio * mat.poisson_ratio));
  auto ratio = [](double k) {  // B/A at b/a = k
    const double e = std::sqrt(1.0 - k * k), K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    return ((1.0 / (k * k)) * E - K) / (K - E);
  };
  double lo = 1e-3, hi = 1.0 - 1e-12;  // B/A decreases from large values to 1 as k -> 1
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (ratio(mid) > B / A) lo = mid;
    else hi = mid;
  }
  const double k = 0.5 * (lo + hi), e2 = 1.0 - k * k, e = std::sqrt(e2);
  const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
  // A = (p0/E*) (k / (e^2 a)) (K - E) and P = (2/3) pi k a^2 p0  ->  a^3 = 3 P (K - E) / (2 pi A E* e^2)
  AnalyticHertz h;
  h.a = std::cbrt(3.0 * P * (K - E) / (2.0 * M_PI * A * E_star * e2));
  h.b = k * h.a;
  h.p0 = 3.0 * P / (2.0 * M_PI * h.a * h.b);
  h.delta = h.p0 * h.b / E_star * K;
  return h;
}

// ---------------------------------------------------------------------------------------------------------------
// 2. Cylinder on cylinder with crossed curvatures: wheel r0 = 0.46 m (crown 0.2 m) on a roller R_r = 0.5 m (crown
// 1.0 m), centred, no yaw: A = 1/(2 r0) + 1/(2 R_r) = 2.087 1/m (rolling radii), B = (1/0.2 + 1/1.0)/2 = 3.0 1/m.
// ---------------------------------------------------------------------------------------------------------------
TEST(RollerGeometry, CrossedCylindersGiveTheHertzSolution) {
  const double r0 = 0.46, crown_w = 0.2, R_r = 0.5, crown_r = 1.0, P = 10e3;
  const WheelsetTrackGeometry g = CrownedRig(r0, crown_w, R_r, crown_r);
  const double A = 1.0 / (2.0 * r0) + 1.0 / (2.0 * R_r), B = 0.5 * (1.0 / crown_w + 1.0 / crown_r);
  const Material mat;
  const AnalyticHertz ref = JohnsonEllipse(A, B, P, mat);

  // the rigid contact: at the crowns' tops, with the roller's rolling radius and both curvatures in A
  WheelsetPose pose;
  double gap = 0.0, y_touch = 0.0;
  ASSERT_TRUE(g.MinimumVerticalGap(Side::Left, pose, &gap, &y_touch));
  pose.vertical_m -= gap;
  const WheelContactResult rigid = g.RigidContact(Side::Left, pose);
  ASSERT_EQ(rigid.status, ContactStatus::Ok);
  const RigidContactPoint& c = rigid.points.front();
  EXPECT_NEAR(c.gap_m, 0.0, 1e-12);
  EXPECT_NEAR(c.roller_rolling_radius_m, R_r, 1e-9);
  EXPECT_NEAR(c.rolling_radius_m, r0, 1e-9);
  EXPECT_NEAR(c.hertz_A_per_m / A, 1.0, 1e-6);
  EXPECT_NEAR(c.hertz_B_per_m / B, 1.0, 1e-4);

  WheelContactOptions o;
  o.model = ContactModel::Hertz;
  o.vertical_load_N = P;
  o.solve_tangential = false;
  const WheelContactReport h = SolveWheelContact(g, Side::Left, pose, test::Rolling(), o);
  ASSERT_EQ(h.status, WheelContactStatus::Ok);
  ASSERT_EQ(h.patches.size(), 1u);
  const PatchReport& hp = h.patches.front();
  const HertzResult hz = SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, hp.fn_N, mat);
  // the push-down from first touch is the Hertz approach (contact angle 0: vertical = normal)
  const double approach = pose.vertical_m - h.pose.vertical_m;
  std::printf("crossed cylinders, Johnson: a = %.6f mm, b = %.6f mm, p0 = %.6f MPa, delta = %.6f um\n", ref.a * 1e3,
              ref.b * 1e3, ref.p0 * 1e-6, ref.delta * 1e6);
  std::printf(
      "  hertz model: fn = %.3f N, a %+.2e, b %+.2e, p_max %+.2e, approach (pose) %+.2e, approach (hertz.hpp "
      "at the geometry's A, B) %+.2e (relative errors)\n",
      hp.fn_N, hp.a_m / ref.a - 1, hp.b_m / ref.b - 1, hp.pmax_Pa / ref.p0 - 1, approach / ref.delta - 1,
      hz.approach_m / ref.delta - 1);
  EXPECT_NEAR(hp.fn_N / P, 1.0, 1e-5);
  EXPECT_NEAR(hp.roller_rolling_radius_m, R_r, 1e-9);  // exposed per patch for the rig kinematics
  EXPECT_NEAR(hp.a_m / ref.a, 1.0, 1e-3);
  EXPECT_NEAR(hp.b_m / ref.b, 1.0, 1e-3);
  EXPECT_NEAR(hp.pmax_Pa / ref.p0, 1.0, 1e-3);
  EXPECT_NEAR(approach / ref.delta, 1.0, 1e-3);
  EXPECT_NEAR(hz.approach_m / ref.delta, 1.0, 1e-3);

  // the strip models and the BEM on the same contact: KPEC reproduces a Hertzian gap closely (docs/physics-reference.md
  // §3.3); the roller's curvature is in every strip's A(s) (without it a would be (2.087/1.087)^(1/3) = 1.24 times
  // larger)
  // The same gap on a straight rail: a wheel of the equivalent radius 1 / (1/r0 + 1/R_r) (A equal at the centre, and
  // across the patch up to the O(delta^2) and O(z/r) variations of the two cos(delta)/R terms, <= 1e-5 at its edges).
  const WheelsetTrackGeometry eq = CrownedRig(1.0 / (1.0 / r0 + 1.0 / R_r), crown_w, 0.0, crown_r);
  WheelsetPose eq_pose;
  ASSERT_TRUE(eq.MinimumVerticalGap(Side::Left, eq_pose, &gap, &y_touch));
  eq_pose.vertical_m -= gap;
  for (ContactModel m : {ContactModel::Kpec, ContactModel::Conformal, ContactModel::Exact}) {
    o.model = m;
    const WheelContactReport k = SolveWheelContact(g, Side::Left, pose, test::Rolling(), o);
    const WheelContactReport e = SolveWheelContact(eq, Side::Left, eq_pose, test::Rolling(), o);
    ASSERT_EQ(k.status, WheelContactStatus::Ok) << to_string(m);
    ASSERT_EQ(e.status, WheelContactStatus::Ok) << to_string(m);
    ASSERT_EQ(k.patches.size(), 1u) << to_string(m);
    ASSERT_EQ(e.patches.size(), 1u) << to_string(m);
    const PatchReport &kp = k.patches.front(), &ep = e.patches.front();
    std::printf(
        "  %s model: fn = %.3f N, p_max %+.2e, length/2a %+.2e, width/2b %+.2e, area/(pi a b) %+.2e "
        "(relative to Johnson); against the equivalent wheel on a rail: p_max %+.2e, length %+.2e, width "
        "%+.2e\n",
        to_string(m), kp.fn_N, kp.pmax_Pa / ref.p0 - 1, kp.length_m / (2 * ref.a) - 1, kp.width_m / (2 * ref.b) - 1,
        kp.area_m2 / (M_PI * ref.a * ref.b) - 1, kp.pmax_Pa / ep.pmax_Pa - 1, kp.length_m / ep.length_m - 1,
        kp.width_m / ep.width_m - 1);
    // the roller's curvature enters the strips exactly as a smaller wheel radius would (measured: < 1e-6)
    EXPECT_NEAR(kp.pmax_Pa / ep.pmax_Pa, 1.0, 1e-5) << to_string(m);
    EXPECT_NEAR(kp.length_m / ep.length_m, 1.0, 1e-5) << to_string(m);
    EXPECT_NEAR(kp.width_m / ep.width_m, 1.0, 1e-5) << to_string(m);
    // against Johnson: KPEC's accuracy on Hertzian gaps (0.5 %, tests/test_kp_hertz.cpp); the conformal model
    // (strip collocation, docs/physics-reference.md §5.3) gives the same figures on the straight rail, so its -1.2 %
    // in the width is the model's, not the roller's: bounded at 2 % here
    if (m == ContactModel::Exact) {  // BEM on 0.2 mm elements: extents to within one element
      EXPECT_NEAR(kp.pmax_Pa / ref.p0, 1.0, 0.01);
      EXPECT_NEAR(kp.length_m, 2 * ref.a, o.exact_element_size_m);
      EXPECT_NEAR(kp.width_m, 2 * ref.b, o.exact_element_size_m);
      continue;
    }
    const double tol = m == ContactModel::Kpec ? 0.005 : 0.02;
    EXPECT_NEAR(kp.pmax_Pa / ref.p0, 1.0, tol) << to_string(m);
    EXPECT_NEAR(kp.length_m / (2 * ref.a), 1.0, tol) << to_string(m);
    EXPECT_NEAR(kp.width_m / (2 * ref.b), 1.0, tol) << to_string(m);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// 3. Brute force: the closest points of the wheel and roller surfaces, found by Newton on the 4-D squared distance
// |P(theta, y_w) - Q(phi, e)|^2 between the exact surfaces (circles of revolution, no profile tables), against the
// search's wheel point, roller point and gap, with yaw, roll and an off-centre contact (contact angle ~ 0.06 rad).
// ---------------------------------------------------------------------------------------------------------------
struct Surfaces {
  double r0, crown_w, R_r, crown_r, b, rail_eta;  // wheel-profile origin at body eta b; roller top at eta rail_eta
  Eigen::Matrix3d R;
  Eigen::Vector3d c;
  // wheel point (side frame) and its derivatives in theta and y_w
  Eigen::Vector3d P(double th, double y, Eigen::Vector3d* dth = nullptr, Eigen::Vector3d* dy = nullptr) const {
    const double r = r0 + Crown(crown_w, y), rp = CrownSlope(crown_w, y);
    if (dth) *dth = R * Eigen::Vector3d(r * std::cos(th), 0.0, r * std::sin(th));
    if (dy) *dy = R * Eigen::Vector3d(rp * std::sin(th), 1.0, -rp * std::cos(th));
    return c + R * Eigen::Vector3d(r * std::sin(th), b + y, -r * std::cos(th));
  }
  // roller point: the crown turned about the axis (x = 0, z = -R_r), at angle phi and eta = e
  Eigen::Vector3d Q(double ph, double e, Eigen::Vector3d* dph = nullptr, Eigen::Vector3d* de = nullptr) const {
    const double rho = R_r + Crown(crown_r, e - rail_eta), rhop = CrownSlope(crown_r, e - rail_eta);
    if (dph) *dph = Eigen::Vector3d(rho * std::cos(ph), 0.0, -rho * std::sin(ph));
    if (de) *de = Eigen::Vector3d(rhop * std::sin(ph), 1.0, rhop * std::cos(ph));
    return Eigen::Vector3d(rho * std::sin(ph), e, rho * std::cos(ph) - R_r);
  }
  Eigen::Vector4d Gradient(const Eigen::Vector4d& u) const {
    Eigen::Vector3d a, b_, cph, ce;
    const Eigen::Vector3d d = P(u(0), u(1), &a, &b_) - Q(u(2), u(3), &cph, &ce);
    return 2.0 * Eigen::Vector4d(d.dot(a), d.dot(b_), -d.dot(cph), -d.dot(ce));
  }
  double Distance2(const Eigen::Vector4d& u) const { return (P(u(0), u(1)) - Q(u(2), u(3))).squaredNorm(); }
};

// Newton on grad F = 0 (Hessian by central differences of the analytic gradient), with step halving on F.
Eigen::Vector4d ClosestPoints(const Surfaces& s, Eigen::Vector4d u) {
  for (int it = 0; it < 100; ++it) {
    const Eigen::Vector4d grad = s.Gradient(u);
    Eigen::Matrix4d H;
    for (int j = 0; j < 4; ++j) {
      Eigen::Vector4d du = Eigen::Vector4d::Zero();
      du(j) = 1e-6;
      H.col(j) = (s.Gradient(u + du) - s.Gradient(u - du)) / 2e-6;
    }
    H = 0.5 * (H + H.transpose()).eval();
    Eigen::Vector4d step = -H.colPivHouseholderQr().solve(grad);
    const double f0 = s.Distance2(u);
    while (s.Distance2(u + step) > f0 * (1 + 1e-14) && step.norm() > 1e-18) step *= 0.5;
    u += step;
    if (step.norm() < 1e-15) break;
  }
  return u;
}

TEST(RollerGeometry, SearchFindsTheClosestPointsOfTheSurfacesAtYaw) {
  const double r0 = 0.46, crown_w = 0.1, R_r = 0.5, crown_r = 0.08, lift = 0.1e-3;
  const WheelsetTrackGeometry g = CrownedRig(r0, crown_w, R_r, crown_r);
  TrackSetup prism_setup = g.setup();
  prism_setup.roller_radius_m = {0.0, 0.0};
  const WheelsetTrackGeometry prism(prism_setup);
  double worst_position = 0.0, worst_gap = 0.0, worst_radius = 0.0, prism_offset = 0.0, worst_touch = 0.0;
  double worst_angle = 0.0, worst_vertical = 0.0;
  struct Case {
    double y_mm, yaw_mrad, roll_mrad;
  };
  for (const Case& k : {Case{10.0, 10.0, 0.0}, Case{-8.0, -15.0, 1.0}, Case{5.0, 20.0, -2.0}}) {
    for (Side side : {Side::Left, Side::Right}) {
      WheelsetPose pose;
      pose.lateral_m = k.y_mm * 1e-3;
      pose.yaw_rad = k.yaw_mrad * 1e-3;
      pose.roll_rad = k.roll_mrad * 1e-3;
      double gap = 0.0, y_touch = 0.0;
      ASSERT_TRUE(g.MinimumVerticalGap(side, pose, &gap, &y_touch));
      pose.vertical_m -= gap - lift;  // 0.1 mm above the roller: a well-defined closest pair
      // touching after MinimumVerticalGap's lowering (the meridian gap shrinks by cos(phi) per unit of it: iterated)
      WheelsetPose touching = pose;
      touching.vertical_m -= lift;
      worst_touch = std::max(worst_touch, std::fabs(g.RigidContact(side, touching).points.front().gap_m));
      const WheelContactResult rc = g.RigidContact(side, pose);
      ASSERT_EQ(rc.status, ContactStatus::Ok);
      const RigidContactPoint& c = rc.points.front();

      const double sigma = side_sign(side);
      const WheelsetTrackGeometry::Frame f = g.SideFrame(side, pose);
      Surfaces s{r0, crown_w, R_r, crown_r, g.wheel_origin_eta_m(), g.rail_origin_eta_m(side), f.rotation, f.centre};
      // start: the crowns' tops, straight below the axle
      const Eigen::Vector4d u = ClosestPoints(s, Eigen::Vector4d(0.0, 0.0, 0.0, s.rail_eta));
      const Eigen::Vector3d Pw = s.P(u(0), u(1)), Qr = s.Q(u(2), u(3));
      const Eigen::Vector3d mirror(1.0, sigma, 1.0);
      const Eigen::Vector3d Pt = Pw.cwiseProduct(mirror), Qt = Qr.cwiseProduct(mirror);  // track frame
      worst_position = std::max(
          {worst_position, (Pt - c.wheel_point_m).cwiseAbs().maxCoeff(), (Qt - c.rail_point_m).cwiseAbs().maxCoeff()});
      worst_gap = std::max(worst_gap, std::fabs((Pw - Qr).norm() - c.gap_m));
      worst_angle = std::max(worst_angle, std::fabs(std::atan2(Qr(0), Qr(2) + R_r) - c.roller_angle_rad));
      worst_vertical = std::max(worst_vertical, std::fabs(c.vertical_gap_m - lift));
      worst_radius = std::max({worst_radius, std::fabs(r0 + Crown(crown_w, u(1)) - c.rolling_radius_m),
                               std::fabs(R_r + Crown(crown_r, u(3) - s.rail_eta) - c.roller_rolling_radius_m)});
      // the same pose on a straight rail of the roller's profile: how far the roller moves the contact
      const WheelContactResult pc = prism.RigidContact(side, pose);
      ASSERT_EQ(pc.status, ContactStatus::Ok);
      prism_offset = std::max(prism_offset, (pc.points.front().wheel_point_m - Pt).cwiseAbs().maxCoeff());
      if (side == Side::Left)
        std::printf(
            "y %+.0f mm, yaw %+.0f mrad: contact x = %+.4f mm on the wheel, %+.4f mm on the roller, "
            "delta = %.4f rad, gap %.6f um\n",
            k.y_mm, k.yaw_mrad, c.wheel_point_m(0) * 1e3, c.rail_point_m(0) * 1e3, c.contact_angle_rad, c.gap_m * 1e6);
    }
  }
  std::printf(
      "brute force vs search: positions %.2e m, gap %.2e m, rolling radii %.2e m, roller angle %.2e rad; the "
      "straight rail's contact point is %.3e m away\n",
      worst_position, worst_gap, worst_radius, worst_angle, prism_offset);
  std::printf("touching pose: gap %.2e m; vertical gap at 0.1 mm lift: %.2e m off\n", worst_touch, worst_vertical);
  // Resolution of the search: Brent to 1e-10 m in y_w, then parabolic steps along the rail until a step is below
  // 1e-9 m (converging fast, so the last error is well below the last step): positions to 1e-9 m. The gap is
  // stationary at the closest pair (error ~ curvature x (1e-9 m)^2 ~ 1e-17 m) and the 0.05 mm-sampled circles are
  // reproduced by the splines and Hermite tables to ~1e-15 m: the gap to 1e-12 m. The roller's lead effect it
  // must resolve is 3.5 mm (the straight rail's contact point) and its drop tens of um.
  EXPECT_LT(worst_position, 1e-9);
  EXPECT_LT(worst_gap, 1e-12);
  EXPECT_LT(worst_radius, 1e-9);
  EXPECT_LT(worst_angle, 1e-9 / R_r);
  EXPECT_LT(worst_touch, 1e-14);
  // RigidContactPoint::vertical_gap_m = meridian gap / cos(phi): exact to first order in the lift (measured 1.5e-12 m
  // at a 0.1 mm lift), bounded at 1e-6 of the lift
  EXPECT_LT(worst_vertical, 1e-6 * lift);
  EXPECT_GT(prism_offset, 1e-5);  // the roller matters: tens of um at these yaw angles
}

// Load control on a roller at yaw: the contact lies at phi ~ lead / R_r about the roller axis, its normal leans by phi
// along x, so the vertical load is carried by fn cos(delta) cos(phi) (not fn cos(delta): 1.3e-4 apart at phi = 16
// mrad).
TEST(RollerGeometry, LoadControlUsesTheNormalTiltedAboutTheRollerAxis) {
  const WheelsetTrackGeometry g = CrownedRig(0.46, 0.1, 0.5, 0.08);
  WheelsetPose pose;
  pose.lateral_m = 5e-3;
  pose.yaw_rad = 20e-3;
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kpec}) {
    WheelContactOptions o;
    o.model = m;
    o.solve_tangential = false;
    o.vertical_load_N = 10e3;
    const WheelContactReport r = SolveWheelContact(g, Side::Left, pose, test::Rolling(), o);
    ASSERT_EQ(r.status, WheelContactStatus::Ok) << to_string(m);
    ASSERT_EQ(r.patches.size(), 1u) << to_string(m);
    const PatchReport& p = r.patches.front();
    EXPECT_GT(std::fabs(p.roller_angle_rad), 0.01) << to_string(m);
    const double carried = p.fn_N * std::cos(p.contact_angle_rad) * std::cos(p.roller_angle_rad);
    std::printf("%s at yaw 20 mrad: phi = %.5f rad, fn cos(delta) cos(phi) / load - 1 = %+.2e\n", to_string(m),
                p.roller_angle_rad, carried / o.vertical_load_N - 1.0);
    EXPECT_NEAR(carried / o.vertical_load_N, 1.0, 1e-5) << to_string(m);
    EXPECT_NEAR(r.vertical_force_N / o.vertical_load_N, 1.0, 1e-5) << to_string(m);
  }
}

// Without yaw the wheel's silhouette lies in the plane x = 0, the roller's top line: every contact quantity equals the
// rail's except A, which gains exactly cos(delta) / (2 R_r(y)). S1002 on 60E1 1:40 rollers of 0.5 m (a full-scale rig),
// from -10 to +10 mm (tread to flange), rigid equilibrium with roll.
TEST(RollerGeometry, WithoutYawTheRollerTouchesWhereTheRailDoes) {
  TrackSetup t = test::PipelineGeometry().setup();
  t.roller_radius_m = {0.5, 0.5};
  const WheelsetTrackGeometry rig(t);
  double worst = 0.0, worst_A = 0.0;
  int flange = 0;
  for (int y_mm = -10; y_mm <= 10; y_mm += 2) {
    const EquilibriumResult a = test::PipelineGeometry().SolveRigidEquilibrium(y_mm * 1e-3, 0.0);
    const EquilibriumResult b = rig.SolveRigidEquilibrium(y_mm * 1e-3, 0.0);
    ASSERT_EQ(a.status, EquilibriumStatus::Converged);
    ASSERT_EQ(b.status, EquilibriumStatus::Converged) << y_mm << " mm";
    worst =
        std::max({worst, std::fabs(a.pose.vertical_m - b.pose.vertical_m), std::fabs(a.pose.roll_rad - b.pose.roll_rad),
                  std::fabs(a.rolling_radius_difference_m - b.rolling_radius_difference_m)});
    for (int s = 0; s < 2; ++s) {
      const RigidContactPoint &p = a.contact.wheel[s].points.front(), &q = b.contact.wheel[s].points.front();
      flange += p.contact_angle_rad > 0.5;
      worst = std::max({worst, (p.wheel_point_m - q.wheel_point_m).cwiseAbs().maxCoeff(),
                        (p.rail_point_m - q.rail_point_m).cwiseAbs().maxCoeff(), std::fabs(p.gap_m - q.gap_m)});
      EXPECT_EQ(q.roller_angle_rad, 0.0);
      const double roller_term = std::cos(q.contact_angle_rad) / (2.0 * (0.5 + q.rail_profile_m.y()));
      worst_A = std::max(worst_A, std::fabs(q.hertz_A_per_m - p.hertz_A_per_m - roller_term) / p.hertz_A_per_m);
    }
  }
  std::printf(
      "no yaw, rollers of 0.5 m vs rail, -10..10 mm (%d flange contacts): poses and points %.2e m, A - roller term "
      "%.2e relative\n",
      flange, worst, worst_A);
  EXPECT_GT(flange, 0);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_A, 1e-12);
}

// With yaw on the same rig the rigid equilibrium converges from tread to flange (Newton of the roller silhouette).
TEST(RollerGeometry, EquilibriumConvergesWithYawFromTreadToFlange) {
  TrackSetup t = test::PipelineGeometry().setup();
  t.roller_radius_m = {0.5, 0.5};
  const WheelsetTrackGeometry rig(t);
  for (double yaw : {-10e-3, 10e-3}) {
    for (int y_mm = -10; y_mm <= 10; y_mm += 2) {
      const EquilibriumResult b = rig.SolveRigidEquilibrium(y_mm * 1e-3, yaw);
      ASSERT_EQ(b.status, EquilibriumStatus::Converged) << y_mm << " mm, yaw " << yaw;
      for (int s = 0; s < 2; ++s) {
        const RigidContactPoint& q = b.contact.wheel[s].points.front();
        EXPECT_NEAR(q.gap_m, 0.0, 1e-9) << y_mm << " mm, yaw " << yaw;
        EXPECT_NEAR(std::hypot(q.rail_point_m.x(), q.rail_point_m.z() + 0.5), q.roller_rolling_radius_m, 1e-12);
      }
    }
  }
}

TEST(RollerGeometry, RollerSmallerThanItsProfileDepthIsAnInputError) {
  TrackSetup t = test::PipelineGeometry().setup();
  t.roller_radius_m = {0.5, 0.01};  // 60E1: the tabulated head reaches deeper than 10 mm
  try {
    WheelsetTrackGeometry g(t);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("roller_radius_m[right]"), std::string::npos) << e.what();
  }
}

}  // namespace
