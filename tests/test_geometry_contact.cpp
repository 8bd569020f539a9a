// Wheel-rail contact geometry (geometry.hpp, contact_candidates.hpp, creepage.hpp): analytic shapes, a
// brute-force check of the silhouette search with yaw, mirror symmetry of the two sides, two-point contact
// candidates at the flange root, creepage limits and a randomized robustness sweep on S1002 / 60E1.
// test-links: geometry  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "conforma/contact_candidates.hpp"
#include "conforma/creepage.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"

using namespace conforma;

namespace {

// Wheel: cone z_w = -k y (radius decreasing towards the field side), y in [-60, 60] mm.
Profile cone_wheel(double k) {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 240; ++i) {
    const double y = -0.06 + 0.12 * i / 240.0;
    p.emplace_back(y, -k * y);
  }
  return Profile::FromPoints(p, ProfileKind::Wheel);
}
// Rail: circular crown of radius R (z up, top at the origin), half-width 35 mm, with steep flanks so that a
// gauge point 14 mm below the top exists.
Profile crown_rail(double R) {
  std::vector<Eigen::Vector2d> p;
  const double w = 0.035;
  for (int i = 0; i <= 20; ++i) p.emplace_back(-w - 0.001 + 0.001 * i / 20.0, -0.03 + (0.03 - (R - std::sqrt(R * R - w * w))) * i / 20.0);
  for (int i = 1; i <= 700; ++i) {
    const double y = -w + 2 * w * i / 700.0;
    p.emplace_back(y, std::sqrt(R * R - y * y) - R);
  }
  for (int i = 1; i <= 20; ++i) p.emplace_back(w + 0.001 * i / 20.0, (R - std::sqrt(R * R - w * w)) * -1.0 - (0.03 - (R - std::sqrt(R * R - w * w))) * i / 20.0);
  ProfileFitOptions o;
  o.function_of_y = false;
  return Profile::FromPoints(p, ProfileKind::Rail, o);
}

WheelsetTrackGeometry standard_track() {
  // uninclined 60E1, canted 1:40 by the track (tests the mounting)
  return WheelsetTrackGeometry(MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40()));
}

}  // namespace

TEST(GeometryContact, ConeOnCrownAnalytic) {
  const double k = 0.05, R = 0.3;
  const WheelsetTrackGeometry g(MakeSymmetricTrack(cone_wheel(k), crown_rail(R), 0.0));
  WheelsetPose p;
  const WheelContactResult c = g.RigidContact(Side::Left, p);
  ASSERT_EQ(c.status, ContactStatus::Ok);
  const RigidContactPoint& q = c.points.front();
  // rail slope equals the cone slope: normal angle atan(k) towards the gauge side, at y_r = -R sin(atan k)
  EXPECT_NEAR(q.contact_angle_rad, std::atan(k), 1e-6);
  EXPECT_NEAR(q.rail_profile_m.x(), -R * std::sin(std::atan(k)), 2e-6);
  EXPECT_NEAR(q.rolling_radius_m, 0.46 - k * q.wheel_profile_m.x(), 1e-9);
  EXPECT_NEAR(q.hertz_A_per_m, std::cos(std::atan(k)) / (2 * q.rolling_radius_m), 1e-9);
  EXPECT_NEAR(q.hertz_B_per_m, 0.5 / R, 1e-3 / R);  // flat cone generator, R300 crown
  EXPECT_NEAR(q.lead_m, 0.0, 1e-12);
  // the vertical position: lift by 1 mm opens the gap by 1 mm vertically, cos(delta) mm along the normal
  WheelsetPose up = p;
  up.vertical_m += 1e-3;
  const RigidContactPoint q2 = g.RigidContact(Side::Left, up).points.front();
  EXPECT_NEAR(q2.vertical_gap_m - q.vertical_gap_m, 1e-3, 1e-9);
  EXPECT_NEAR(q2.gap_m - q.gap_m, 1e-3 * std::cos(std::atan(k)), 2e-7);
}

TEST(GeometryContact, YawLeadOfTheConeContact) {
  // yaw alone: sin(theta) = -tan(psi) r' (paper 001 eq. 6); the lead is r sin(theta)
  const double k = 0.05;
  const WheelsetTrackGeometry g(MakeSymmetricTrack(cone_wheel(k), crown_rail(0.3), 0.0));
  WheelsetPose p;
  p.yaw_rad = 0.02;
  for (Side s : {Side::Left, Side::Right}) {
    const RigidContactPoint q = g.RigidContact(s, p).points.front();
    const double r_slope = -k;  // dr/dy_w of the cone
    const double sigma = side_sign(s);
    const double expected_sin = -std::tan(sigma * p.yaw_rad) * r_slope;
    EXPECT_NEAR(std::sin(q.wheel_theta_rad), expected_sin, 1e-9) << to_string(s);
    // lead in the track frame: rotate the wheel point (r sin theta, b + y_w, .) by the yaw
    const double psi = sigma * p.yaw_rad;
    EXPECT_NEAR(q.lead_m, std::cos(psi) * q.rolling_radius_m * expected_sin, 1e-9) << to_string(s);
  }
}

TEST(GeometryContact, SilhouetteGivesTheSmallestGapOfTheWholeWheelSurface) {
  // brute force over the wheel surface (y_w, theta) against the rail prism, S1002 / 60E1 with yaw and roll
  const WheelsetTrackGeometry g = standard_track();
  const WheelsetPose poses[] = {{0.0, 0.0, 0.0, 0.0}, {0.008, 0.0, 0.002, 0.025}, {-0.009, -0.0005, -0.003, -0.02}};
  for (const WheelsetPose& p : poses) {
    for (Side s : {Side::Left, Side::Right}) {
      double gap, y;
      ASSERT_TRUE(g.MinimumVerticalGap(s, p, &gap, &y));
      const auto f = g.SideFrame(s, p);
      double brute = std::numeric_limits<double>::infinity();
      for (double yw = g.WheelTableBegin(s); yw <= g.WheelTableEnd(s); yw += 0.05e-3) {
        double zw, slope;
        if (!g.WheelProfileAt(s, yw, &zw, &slope, nullptr)) continue;
        const double r = g.setup().nominal_radius_m[side_index(s)] + zw;
        for (double th = -0.12; th <= 0.12; th += 0.0005) {
          const Eigen::Vector3d q(r * std::sin(th), g.wheel_origin_eta_m() + yw, -r * std::cos(th));
          const Eigen::Vector3d pt = f.centre + f.rotation * q;
          double zr;
          if (g.RailHeight(s, pt(1), &zr, nullptr)) brute = std::min(brute, pt(2) - zr);
        }
      }
      EXPECT_LE(gap, brute + 1e-9) << to_string(s);     // the silhouette never misses a lower point
      EXPECT_NEAR(gap, brute, 2e-6) << to_string(s);   // and the grid gets close to it
    }
  }
}

TEST(GeometryContact, MirrorSymmetryOfTheTwoSides) {
  const WheelsetTrackGeometry g = standard_track();
  const WheelsetPose p{0.004, -0.0002, 0.0015, 0.012};
  const WheelsetPose m{-p.lateral_m, p.vertical_m, -p.roll_rad, -p.yaw_rad};
  const WheelContactResult a = g.RigidContact(Side::Left, p), b = g.RigidContact(Side::Right, m);
  ASSERT_FALSE(a.points.empty());
  ASSERT_EQ(a.points.size(), b.points.size());
  const RigidContactPoint &qa = a.points.front(), &qb = b.points.front();
  EXPECT_NEAR(qa.gap_m, qb.gap_m, 1e-12);
  EXPECT_NEAR(qa.rail_profile_m.x(), qb.rail_profile_m.x(), 1e-12);
  EXPECT_NEAR(qa.contact_angle_rad, qb.contact_angle_rad, 1e-12);
  EXPECT_NEAR(qa.lead_m, qb.lead_m, 1e-12);
  EXPECT_NEAR(qa.wheel_point_m.y(), -qb.wheel_point_m.y(), 1e-12);
  // rolling-radius difference is odd in y for a symmetric track; roll raises the wheel on the larger radius
  const EquilibriumResult e1 = g.SolveRigidEquilibrium(0.003, 0.0), e2 = g.SolveRigidEquilibrium(-0.003, 0.0);
  ASSERT_EQ(e1.status, EquilibriumStatus::Converged);
  ASSERT_EQ(e2.status, EquilibriumStatus::Converged);
  EXPECT_GT(e1.rolling_radius_difference_m, 0.0);
  EXPECT_NEAR(e1.rolling_radius_difference_m, -e2.rolling_radius_difference_m, 1e-9);
  EXPECT_GT(e1.pose.roll_rad, 0.0);
  EXPECT_NEAR(e1.pose.roll_rad, -e2.pose.roll_rad, 1e-9);
}

TEST(GeometryContact, FlangeRootTwoPointContactGivesSeparatePatches) {
  const WheelsetTrackGeometry g = standard_track();
  // lateral shift of the two-point contact of the left wheel (tread and flange root touch), yaw 20 mrad:
  // scan, then bisection on which of the two is the smallest-gap contact
  const double yaw = 0.02;
  WheelsetPose guess;
  auto flange_touches = [&](double y) {
    const EquilibriumResult e = g.SolveRigidEquilibrium(y, yaw, guess);
    return e.contact.wheel[0].points.front().contact_angle_rad > 0.5;
  };
  double lo = 0.0, hi = 0.0;
  for (double y = 0.0; y < 0.012; y += 0.1e-3) {
    guess = g.SolveRigidEquilibrium(y, yaw, guess).pose;
    if (flange_touches(y)) { hi = y; break; }
    lo = y;
  }
  ASSERT_GT(hi, 0.004);
  for (int it = 0; it < 30; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (flange_touches(mid)) hi = mid; else lo = mid;
  }
  const EquilibriumResult e = g.SolveRigidEquilibrium(lo, yaw, guess);
  WheelsetPose p = e.pose;
  p.vertical_m -= 0.1e-3;  // push 0.1 mm into the rail
  // patch grouping (issue 15): by default the two regions, a few mm apart along the rail profile, are one merged
  // curved patch; combine distance 0 keeps them separate (the behaviour examined below)
  const CandidateResult merged = FindContactCandidates(g, Side::Left, p);
  ASSERT_EQ(merged.status, CandidateStatus::Ok);
  EXPECT_EQ(merged.candidates.size(), 1u);
  CandidateOptions separate;
  separate.combine_distance_m = 0.0;
  const CandidateResult r = FindContactCandidates(g, Side::Left, p, separate);
  ASSERT_EQ(r.status, CandidateStatus::Ok);
  ASSERT_GE(r.candidates.size(), 2u);
  // the merged patch spans both regions; its reference point lies between the regions' middles
  EXPECT_NEAR(merged.candidates[0].region_start_s_m, r.candidates.front().region_start_s_m, 1e-12);
  EXPECT_NEAR(merged.candidates[0].region_end_s_m, r.candidates.back().region_end_s_m, 1e-12);
  const double s_ref = merged.candidates[0].patch.reference_s_on_rail_m;
  EXPECT_GT(s_ref, r.candidates.front().patch.reference_s_on_rail_m);
  EXPECT_LT(s_ref, r.candidates.back().patch.reference_s_on_rail_m);
  for (const auto& c : r.candidates)
    std::printf("region s [%.2f, %.2f] mm: delta %.3f rad, lead %.2f mm, approach %.4f mm, %zu strips\n",
                c.region_start_s_m * 1e3, c.region_end_s_m * 1e3, c.patch.contact_angle_rad, c.reference.lead_m * 1e3,
                c.patch.rigid_approach_m * 1e3, c.patch.strips());
  const ContactCandidate &flange = r.candidates.front(), &root = r.candidates.back();  // gauge side first
  EXPECT_GT(flange.patch.contact_angle_rad, 1.0);
  EXPECT_LT(root.patch.contact_angle_rad, flange.patch.contact_angle_rad - 0.3);
  // yaw 20 mrad: both contacts lead the wheel's diametral plane, the steep flange contact by far the most
  // (paper 004); sin(theta) = -tan(psi) r' with r' = -tan(delta) for the left wheel
  for (const ContactCandidate* c : {&flange, &root}) {
    const double expected = c->reference.rolling_radius_m * std::tan(yaw) * std::tan(c->reference.contact_angle_rad);
    EXPECT_NEAR(c->reference.lead_m, expected, 0.1 * expected);
  }
  EXPECT_GT(flange.reference.lead_m, 15e-3);
  EXPECT_GT(flange.reference.lead_m, 2 * root.reference.lead_m);
  const ContactCandidate& tread = root;
  for (const ContactCandidate& c : r.candidates) {
    const PatchGeometry& pg = c.patch;
    ASSERT_GT(pg.strips(), 4u);
    double gmin = 1e9;
    for (size_t j = 0; j < pg.strips(); ++j) {
      gmin = std::min(gmin, pg.gap_m[j]);
      EXPECT_GE(pg.gap_m[j], 0.0);
      EXPECT_GT(pg.longitudinal_curvature_per_m[j], 0.0);
      EXPECT_GT(pg.wheel_radius_m[j], 0.4);
      if (j) {
        EXPECT_NEAR(pg.s_m[j] - pg.s_m[j - 1], pg.ds_m, 1e-12);
      }
    }
    EXPECT_NEAR(gmin, 0.0, 1e-15);
    EXPECT_GT(pg.rigid_approach_m, 0.0);
    // the reference point is the centre of the region: the gap at s = 0 lies inside it
    EXPECT_NEAR(c.reference.rail_s_m, 0.5 * (c.region_start_s_m + c.region_end_s_m), 1e-6);
    // alpha(0) = 0 and, on the convex rail head, alpha grows with s
    for (size_t j = 0; j + 1 < pg.strips(); ++j) EXPECT_GT(pg.alpha_rad[j + 1], pg.alpha_rad[j]);
    EXPECT_NEAR(std::abs(pg.reference_normal.norm()), 1.0, 1e-12);
  }
  // the flange region is narrow and strongly curved: its alpha spread exceeds the tread's
  const auto spread = [](const PatchGeometry& pg) { return pg.alpha_rad.back() - pg.alpha_rad.front(); };
  EXPECT_GT(spread(flange.patch) / (flange.patch.strips() * flange.patch.ds_m),
            spread(tread.patch) / (tread.patch.strips() * tread.patch.ds_m));
}

TEST(GeometryContact, LoadGivenCandidateCarriesTheLoadInHertz) {
  const WheelsetTrackGeometry g = standard_track();
  WheelsetPose p;
  p.lateral_m = 0.002;
  const CandidateResult r = FindContactCandidatesForLoad(g, Side::Left, p, 50e3, Material{});
  ASSERT_EQ(r.status, CandidateStatus::Ok);
  ASSERT_EQ(r.candidates.size(), 1u);
  const ContactCandidate& c = r.candidates.front();
  // Hertz approach for that load, from SolveHertzForLoad at the rigid point, equals the interpenetration
  WheelsetPose touching = p;
  double gap, y;
  ASSERT_TRUE(g.MinimumVerticalGap(Side::Left, touching, &gap, &y));
  touching.vertical_m -= gap;
  const RigidContactPoint rigid = g.RigidContact(Side::Left, touching).points.front();
  const double cos_delta = std::cos(rigid.contact_angle_rad);
  EXPECT_NEAR(c.normal_force_estimate_N * cos_delta, 50e3, 1.0);
  const HertzResult h = SolveHertzForLoad(rigid.hertz_A_per_m, rigid.hertz_B_per_m, 50e3 / cos_delta, Material{});
  ASSERT_EQ(h.status, HertzStatus::Ok);
  EXPECT_NEAR(c.patch.rigid_approach_m, h.approach_m, 0.02 * h.approach_m);
  EXPECT_THROW(FindContactCandidatesForLoad(g, Side::Left, p, -1.0, Material{}), InputError);
}

// CandidateOptions::strip_geometry = false (the multi-Hertz model's candidate search): the same regions, reference
// points, Hertz estimates and patch count as the full search, bit for bit, with a patch's strips cut after the
// second (and its rigid approach NaN, not a wrong number), over poses from the tread to the flange on both wheels.
TEST(GeometryContact, CandidatesWithoutStripGeometryKeepTheRegions) {
  const WheelsetTrackGeometry g = standard_track();
  CandidateOptions regions_only;
  regions_only.strip_geometry = false;
  int poses = 0, flange_poses = 0;
  for (double y_mm = -9.0; y_mm <= 9.0; y_mm += 1.5) {
    for (double yaw : {-4e-3, 0.0, 3e-3}) {
      for (Side side : {Side::Left, Side::Right}) {
        WheelsetPose p;
        p.lateral_m = y_mm * 1e-3;
        p.yaw_rad = yaw;
        const CandidateResult full = FindContactCandidatesForLoad(g, side, p, 60e3, Material{});
        const CandidateResult cut = FindContactCandidatesForLoad(g, side, p, 60e3, Material{}, regions_only);
        ASSERT_EQ(full.status, cut.status);
        ASSERT_EQ(full.candidates.size(), cut.candidates.size());
        EXPECT_EQ(full.pose.vertical_m, cut.pose.vertical_m);
        ++poses;
        for (size_t k = 0; k < full.candidates.size(); ++k) {
          const ContactCandidate &a = full.candidates[k], &b = cut.candidates[k];
          EXPECT_EQ(a.region_start_s_m, b.region_start_s_m);
          EXPECT_EQ(a.region_end_s_m, b.region_end_s_m);
          EXPECT_EQ(a.reference.rail_s_m, b.reference.rail_s_m);
          EXPECT_EQ(a.reference.gap_m, b.reference.gap_m);
          EXPECT_EQ(a.reference.contact_angle_rad, b.reference.contact_angle_rad);
          EXPECT_EQ(a.normal_force_estimate_N, b.normal_force_estimate_N);
          EXPECT_GT(a.patch.strips(), 4u);
          EXPECT_EQ(b.patch.strips(), 2u);
          EXPECT_TRUE(std::isfinite(a.patch.rigid_approach_m));
          EXPECT_TRUE(std::isnan(b.patch.rigid_approach_m));
          flange_poses += a.reference.contact_angle_rad > 0.8 ? 1 : 0;
        }
      }
    }
  }
  EXPECT_EQ(poses, 78);
  EXPECT_GT(flange_poses, 0);  // the flange is among the regions compared
}

TEST(GeometryContact, CreepageLimits) {
  const WheelsetTrackGeometry g = standard_track();
  WheelsetPose p;
  const RigidContactPoint q = g.RigidContact(Side::Right, p).points.front();
  WheelsetVelocity v;
  v.forward_speed_m_s = 20.0;
  v.axle_angular_velocity_rad_s = 20.0 / 0.46;
  const Creepages c = ComputeCreepages(g, Side::Right, p, v, q.wheel_point_m, q.contact_angle_rad);
  EXPECT_NEAR(c.longitudinal, 1.0 - q.rolling_radius_m / 0.46, 1e-9);
  EXPECT_NEAR(c.lateral, 0.0, 1e-12);
  EXPECT_NEAR(c.spin_per_m, -std::sin(q.contact_angle_rad) * (20.0 / 0.46) / 20.0, 1e-9);
  // lateral velocity gives eta = vy / V (in the side frame: towards the field side of that wheel)
  v.lateral_velocity_m_s = 0.2;
  const Creepages cl = ComputeCreepages(g, Side::Left, p, v, g.RigidContact(Side::Left, p).points.front().wheel_point_m, 0.0);
  EXPECT_NEAR(cl.lateral, 0.01, 1e-9);
  v.forward_speed_m_s = 0.0;
  EXPECT_THROW(ComputeCreepages(g, Side::Left, p, v, q.wheel_point_m, 0.0), InputError);
}

TEST(GeometryContact, RandomPosesNeverGiveNaN) {
  const WheelsetTrackGeometry g = standard_track();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> y(-0.012, 0.012), yaw(-0.025, 0.025), roll(-0.01, 0.01), z(-0.002, 0.002);
  int no_contact = 0, solved = 0;
  for (int i = 0; i < 3000; ++i) {
    const WheelsetPose p{y(rng), z(rng), roll(rng), yaw(rng)};
    const WheelsetContactResult r = g.RigidContacts(p);
    for (const auto& w : r.wheel) {
      if (w.status != ContactStatus::Ok) { ++no_contact; continue; }
      for (const auto& q : w.points) {
        ASSERT_TRUE(std::isfinite(q.gap_m) && std::isfinite(q.lead_m) && std::isfinite(q.contact_angle_rad) &&
                    std::isfinite(q.rolling_radius_m) && std::isfinite(q.hertz_A_per_m) && std::isfinite(q.hertz_B_per_m))
            << "pose " << i;
      }
    }
    if (i % 10 == 0) {
      const EquilibriumResult e = g.SolveRigidEquilibrium(p.lateral_m, p.yaw_rad);
      ASSERT_TRUE(std::isfinite(e.pose.vertical_m) && std::isfinite(e.pose.roll_rad) &&
                  std::isfinite(e.rolling_radius_difference_m));
      solved += e.status == EquilibriumStatus::Converged;
      const CandidateResult c = FindContactCandidates(g, Side::Left, p);
      for (const auto& k : c.candidates)
        for (size_t j = 0; j < k.patch.strips(); ++j)
          ASSERT_TRUE(std::isfinite(k.patch.gap_m[j]) && std::isfinite(k.patch.alpha_rad[j]) &&
                      std::isfinite(k.patch.x_offset_m[j]));
    }
  }
  EXPECT_GE(solved, 290);  // the equilibrium converges for (almost) all shifts within +-12 mm
  // far away from the rails (wheelset lifted sideways off the head): a status, not an exception
  const WheelsetPose off{0.2, 0.0, 0.0, 0.0};
  EXPECT_EQ(g.RigidContact(Side::Left, off).status, ContactStatus::NoOverlap);
  EXPECT_EQ(FindContactCandidates(g, Side::Left, off).status, CandidateStatus::NoOverlap);
  WheelsetPose lifted;
  lifted.vertical_m = 0.01;
  EXPECT_EQ(FindContactCandidates(g, Side::Left, lifted).status, CandidateStatus::NoContact);
}
