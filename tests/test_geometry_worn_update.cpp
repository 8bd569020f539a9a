// test-links: rig
// The worn-profile geometry update of the real-time rig (WheelsetTrackGeometry's update constructor, geometry.hpp;
// docs/physics-reference.md §18.3): over a wearing sequence with the profiles in contact updated every 20 ms sample,
// the incrementally updated geometry (table nodes solved again only where the wear moved the profiles, the roller
// mounted by an exact translation) gives the tables and the contact results of a full rebuild on the same profiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "conforma/roller_rig_sample.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct TableDifference {
  double z = 0.0, dz = 0.0, kappa = 0.0, s = 0.0;
};

void Compare(const WheelsetTrackGeometry::GraphTable& a, const WheelsetTrackGeometry::GraphTable& b,
             TableDifference* d, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(a.h, b.h) << what;
  EXPECT_EQ(a.y0, b.y0) << what;
  for (size_t k = 0; k < a.size(); ++k) {
    d->z = std::max(d->z, std::abs(a.z[k] - b.z[k]));
    d->dz = std::max(d->dz, std::abs(a.dz[k] - b.dz[k]));
    d->kappa = std::max(d->kappa, std::abs(a.kappa[k] - b.kappa[k]) / std::max(1.0, std::abs(b.kappa[k])));
    d->s = std::max(d->s, std::abs(a.s[k] - b.s[k]));
  }
}

TEST(GeometryWornUpdate, EqualsAFullRebuildOverAWearingSequence) {
  const RollerRigSetup setup;
  RollerRigSampleOptions o = RollerRigSampleOptions::Defaults(setup);
  o.kinematics.eq2_wheelset_speed = true;
  ASSERT_EQ(o.profile_update_every_steps, 1);  // every sample, as paper 000 §3.5
  ASSERT_EQ(o.filter_every_steps, 10);
  RollerRigState state = MakeRollerRigState(o);
  const double w1 = 500.0 * 2.0 * kPi / 60.0, xi = 0.05;
  RollerRigSample s;
  s.duration_s = 0.02;
  s.roller_speed_rad_s = {w1, w1 * (1.0 - xi) / (1.0 + xi)};
  s.wheel_load_N = {50.0 * 9.81, 50.0 * 9.81};
  TableDifference wheel, rail;
  double mounted = 0.0, force = 0.0, creepage = 0.0, position = 0.0, speed = 0.0;
  for (int i = 0; i < 30; ++i) {
    s.time_s = 0.02 * i;
    s.lateral_m = 0.2e-3 * std::sin(2.0 * kPi * s.time_s);
    const RollerRigSampleResult r = ProcessRigSample(o, &state, s);
    ASSERT_EQ(r.status, RollerRigSampleStatus::Ok) << r.message;
    ASSERT_TRUE(r.profiles_updated);
    GeometryOptions g = RollerRigGeometryOptions(setup);
    g.refit_uninclined_rail = false;  // real time: the rollers are mounted by translation (roller_rig_sample.cpp)
    const WheelsetTrackGeometry full(MakeRollerRigTrack(setup, state.wheel, state.roller), g);
    const WheelsetTrackGeometry& inc = *state.geometry;
    for (Side side : {Side::Left, Side::Right}) {
      Compare(inc.WheelTable(side), full.WheelTable(side), &wheel, "wheel table");
      Compare(inc.RailTable(side), full.RailTable(side), &rail, "rail table");
      EXPECT_EQ(inc.rail_origin_eta_m(side), full.rail_origin_eta_m(side));
      const Profile &a = inc.mounted_rail(side), &b = full.mounted_rail(side);
      for (double y = -4e-3; y <= 4e-3; y += 0.05e-3) {
        const auto za = a.height_at(y), zb = b.height_at(y);
        ASSERT_TRUE(za && zb);
        mounted = std::max(mounted, std::abs(*za - *zb));
      }
    }
    // the next sample's contacts on both geometries
    RollerRigKinematicsInput in;
    in.lateral_m = 0.2e-3 * std::sin(2.0 * kPi * (s.time_s + 0.02));
    in.roller_speed_rad_s = s.roller_speed_rad_s;
    in.wheel_load_N = s.wheel_load_N;
    RollerRigKinematicsOptions ko = o.kinematics;
    const RollerRigKinematicsResult ki = SolveRollerRigKinematics(inc, setup, in, ko);
    const RollerRigKinematicsResult kf = SolveRollerRigKinematics(full, setup, in, ko);
    ASSERT_EQ(ki.status, kf.status);
    speed = std::max(speed, std::abs(ki.wheelset_speed_rad_s - kf.wheelset_speed_rad_s) / kf.wheelset_speed_rad_s);
    for (int k = 0; k < 2; ++k) {
      const RollerRigContactResult &a = ki.contact[k], &b = kf.contact[k];
      for (auto [x, y] : {std::pair{a.fn_N, b.fn_N}, std::pair{a.fx_N, b.fx_N}, std::pair{a.fy_N, b.fy_N}})
        force = std::max(force, std::abs(x - y) / b.fn_N);
      for (auto [x, y] : {std::pair{a.xi, b.xi}, std::pair{a.eta, b.eta}})
        creepage = std::max(creepage, std::abs(x - y));
      position = std::max(position, std::abs(a.contact_y_m - b.contact_y_m));
    }
  }
  // bit for bit: the update solves the changed nodes as the full constructor does, from the same start on the same
  // curve (Profile::WithMovedSamples keeps the spline outside its window exactly)
  for (double d : {wheel.z, wheel.dz, wheel.kappa, wheel.s, rail.z, rail.dz, rail.kappa, rail.s, mounted, force,
                   creepage, position, speed})
    EXPECT_EQ(d, 0.0);
}

// A roller worn at its highest point must be mounted anew (mount_rail refits it with its new top at z = 0): the
// update builds that side as the full constructor does, and keeps the unchanged side.
TEST(GeometryWornUpdate, RollerWornAtItsTop) {
  const RollerRigSetup setup;
  const Profile wheel = MakeRollerRigWheelProfile(setup), roller = MakeRollerRigRollerProfile(setup);
  const WheelsetTrackGeometry before(MakeRollerRigTrack(setup, {wheel, wheel}, {roller, roller}),
                                     RollerRigGeometryOptions(setup));
  ASSERT_TRUE(before.mounted_rail(Side::Left).source() == roller.source());  // unworn: mounted as it is
  // 2 um of wear, a cosine bell 1 mm wide around the highest sample, along the normals
  size_t top = 0;
  for (size_t i = 1; i < roller.sample_count(); ++i)
    if (roller.sample_at(i).y() > roller.sample_at(top).y()) top = i;
  const double h = roller.spacing(), half_width = 0.5e-3;
  const size_t n = static_cast<size_t>(half_width / h);
  std::vector<Eigen::Vector2d> moved;
  for (size_t i = top - n; i <= top + n; ++i) {
    const double u = (static_cast<double>(i) - static_cast<double>(top)) * h / half_width;
    moved.push_back(roller.sample_at(i) - 1e-6 * (1.0 + std::cos(kPi * u)) * roller.normal(i * h));
  }
  const Profile worn = roller.WithMovedSamples(top - n, moved);
  LateralInterval changed;
  for (size_t i = top - n - Profile::kMovedSplineMargin - 1; i <= top + n + Profile::kMovedSplineMargin + 1; ++i)
    for (const double y : {roller.sample_at(i).x(), worn.sample_at(i).x()}) {
      changed.lo_m = changed.empty() ? y : std::min(changed.lo_m, y);
      changed.hi_m = changed.empty() ? y : std::max(changed.hi_m, y);
    }
  changed.lo_m -= h;
  changed.hi_m += h;
  const WheelsetTrackGeometry update(before, MakeRollerRigTrack(setup, {wheel, wheel}, {worn, roller}),
                                     {LateralInterval{}, LateralInterval{}}, {changed, LateralInterval{}});
  const WheelsetTrackGeometry full(MakeRollerRigTrack(setup, {wheel, wheel}, {worn, roller}),
                                   RollerRigGeometryOptions(setup));
  // the right side did not change: bit for bit
  TableDifference right;
  Compare(update.RailTable(Side::Right), full.RailTable(Side::Right), &right, "right rail table");
  EXPECT_EQ(right.z + right.dz + right.kappa + right.s, 0.0);
  // left: the top moved down by the 2 um, mounted at z = 0 again
  TableDifference left;
  Compare(update.RailTable(Side::Left), full.RailTable(Side::Left), &left, "left rail table");
  EXPECT_EQ(left.z + left.dz + left.kappa + left.s, 0.0);
  EXPECT_EQ(update.rail_origin_eta_m(Side::Left), full.rail_origin_eta_m(Side::Left));
  EXPECT_NE(update.mounted_rail(Side::Left).source(), roller.source());  // refitted: "... (mounted)"
  const double top_z = *std::max_element(update.RailTable(Side::Left).z.begin(), update.RailTable(Side::Left).z.end());
  EXPECT_NEAR(top_z, 0.0, 1e-9);
  const double top_before =
      *std::max_element(before.RailTable(Side::Left).z.begin(), before.RailTable(Side::Left).z.end());
  EXPECT_NEAR(top_before, 0.0, 1e-9);
}

}  // namespace
}  // namespace conforma
