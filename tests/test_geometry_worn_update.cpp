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

// A cosine bell of wear (depth at its centre, 41 samples wide) along the normals around sample `centre`, and the
// lateral interval to pass to the update (the re-solved window, one sample and a spacing more, as the rig's removal).
Profile WearBell(const Profile& p, size_t centre, double depth, LateralInterval* changed) {
  const double h = p.spacing();
  std::vector<Eigen::Vector2d> moved;
  for (size_t i = centre - 20; i <= centre + 20; ++i) {
    const double u = (static_cast<double>(i) - static_cast<double>(centre)) / 20.0;
    moved.push_back(p.sample_at(i) - 0.5 * depth * (1.0 + std::cos(kPi * u)) * p.normal(i * h));
  }
  const Profile worn = p.WithMovedSamples(centre - 20, moved);
  *changed = LateralInterval{};
  const size_t margin = Profile::kMovedSplineMargin + 1;
  for (size_t i = centre - 20 - margin; i <= centre + 20 + margin; ++i)
    for (const double y : {p.sample_at(i).x(), worn.sample_at(i).x()}) {
      changed->lo_m = changed->empty() ? y : std::min(changed->lo_m, y);
      changed->hi_m = changed->empty() ? y : std::max(changed->hi_m, y);
    }
  changed->lo_m -= h;
  changed->hi_m += h;
  return worn;
}

void ExpectSameTables(const WheelsetTrackGeometry& a, const WheelsetTrackGeometry& b) {
  for (Side side : {Side::Left, Side::Right}) {
    TableDifference rail, wheel;
    Compare(a.RailTable(side), b.RailTable(side), &rail, "rail table");
    Compare(a.WheelTable(side), b.WheelTable(side), &wheel, "wheel table");
    EXPECT_EQ(rail.z + rail.dz + rail.kappa + rail.s, 0.0);
    EXPECT_EQ(wheel.z + wheel.dz + wheel.kappa + wheel.s, 0.0);
    EXPECT_EQ(a.rail_origin_eta_m(side), b.rail_origin_eta_m(side));
  }
}

// A roller worn at its highest point is mounted anew (refitted, or, in real time, translated to its new top: the
// update solves that rail table anew), then worn beside its top (translated by the same shift: the update solves
// only the worn nodes). Bit for bit a full rebuild at both steps, with both mountings.
TEST(GeometryWornUpdate, RollerWornAtItsTopThenBeside) {
  const RollerRigSetup setup;
  const Profile wheel = MakeRollerRigWheelProfile(setup), roller = MakeRollerRigRollerProfile(setup);
  size_t top = 0;
  for (size_t i = 1; i < roller.sample_count(); ++i)
    if (roller.sample_at(i).y() > roller.sample_at(top).y()) top = i;
  LateralInterval at_top, beside;
  const Profile worn = WearBell(roller, top, 2e-6, &at_top);
  const Profile worn2 = WearBell(worn, top + 150, 1e-6, &beside);
  const LateralInterval none;
  for (bool refit : {true, false}) {
    GeometryOptions g = RollerRigGeometryOptions(setup);
    g.refit_uninclined_rail = refit;
    const WheelsetTrackGeometry before(MakeRollerRigTrack(setup, {wheel, wheel}, {roller, roller}), g);
    EXPECT_EQ(before.mounted_rail(Side::Left).source(), roller.source());  // unworn: top at z = 0, as it is
    const WheelsetTrackGeometry update(before, MakeRollerRigTrack(setup, {wheel, wheel}, {worn, roller}), {none, none},
                                       {at_top, none});
    const WheelsetTrackGeometry full(MakeRollerRigTrack(setup, {wheel, wheel}, {worn, roller}), g);
    ExpectSameTables(update, full);
    EXPECT_NE(update.mounted_rail(Side::Left).source(), roller.source());  // mounted anew: "... (mounted)"
    const double top_z = *std::max_element(update.RailTable(Side::Left).z.begin(), update.RailTable(Side::Left).z.end());
    EXPECT_NEAR(top_z, 0.0, 1e-9);
    const WheelsetTrackGeometry update2(update, MakeRollerRigTrack(setup, {wheel, wheel}, {worn2, roller}),
                                        {none, none}, {beside, none});
    const WheelsetTrackGeometry full2(MakeRollerRigTrack(setup, {wheel, wheel}, {worn2, roller}), g);
    ExpectSameTables(update2, full2);
  }
}

}  // namespace
}  // namespace conforma
