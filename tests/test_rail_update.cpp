// Rail update by averaging virtual rail profiles (paper 003 §6, Fig. 11).
// test-links: wear  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "conforma/error.hpp"
#include "conforma/rail_update.hpp"
#include "conforma/standard_profiles.hpp"

using namespace conforma;

namespace {

constexpr double kR = 0.3;  // crown radius of the test rail (centre (0, -R))

Profile crown(double half_angle = 0.15) {
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i <= 2000; ++i) {
    const double t = -half_angle + 2 * half_angle * i / 2000.0;
    pts.emplace_back(kR * std::sin(t), kR * std::cos(t) - kR);
  }
  ProfileFitOptions fit;
  fit.function_of_y = false;
  return Profile::FromPoints(pts, ProfileKind::Rail, fit, "crown");
}

double gauss(double x, double c, double sigma) { return std::exp(-0.5 * std::pow((x - c) / sigma, 2)); }

WearDistribution band(const Profile& rail, double y_centre, double sigma, double amplitude) {
  WearDistribution d = WearDistribution::ForProfile(rail, 0.1e-3);
  for (size_t i = 0; i < d.size(); ++i) d.depth_m[i] = amplitude * gauss(rail.position(d.s(i)).x(), y_centre, sigma);
  return d;
}

// Radius of a crown-like profile along the ray at polar angle theta from the crown centre (bisection in s).
double radius_at(const Profile& p, double theta) {
  auto angle = [&](double s) {
    const Eigen::Vector2d q = p.position(s);
    return std::atan2(q.x(), q.y() + kR);
  };
  double lo = 0.0, hi = p.length();
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    (angle(mid) < theta ? lo : hi) = mid;
  }
  return (p.position(0.5 * (lo + hi)) - Eigen::Vector2d(0, -kR)).norm();
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

}  // namespace

TEST(RailUpdate, ZeroWheelWearLeavesTheRailUnchanged) {
  const Profile rail = MakeRail(RailSection::R60E1, rail_inclination_1in40());
  const WearDistribution zero = WearDistribution::ForProfile(rail, 0.1e-3);
  const RailStepResult r = UpdateRail(rail, {zero, zero, zero}, {}, 1.0);
  EXPECT_EQ(r.status, ProfileUpdateStatus::NoWear) << r.message;
  const auto a = rail.samples(), b = r.rail.samples();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ((a[i] - b[i]).norm(), 0.0);
  // keeping the rail fixed ignores any wear
  RailStepOptions fixed;
  fixed.keep_rail_fixed = true;
  const RailStepResult f = UpdateRail(rail, {band(rail, 0.0, 5e-3, 1e-9)}, {}, 1.0, fixed);
  EXPECT_EQ(f.rail.length(), rail.length());
  EXPECT_TRUE(f.virtual_rails.empty());
}

TEST(RailUpdate, AverageAlongNormalsOfUniformOffsets) {
  const Profile base = crown();
  std::vector<Profile> shifted;
  const double offsets[3] = {0.05e-3, 0.2e-3, 0.11e-3}, weights[3] = {0.5, 0.3, 0.2};
  for (double d : offsets) {
    WearDistribution u = WearDistribution::ForProfile(base, 0.1e-3);
    std::fill(u.depth_m.begin(), u.depth_m.end(), d);
    shifted.push_back(RemoveAlongNormal(base, u));
  }
  const NormalAverageResult avg = AverageAlongNormals(base, shifted, {0.5, 0.3, 0.2});
  const double expected = weights[0] * offsets[0] + weights[1] * offsets[1] + weights[2] * offsets[2];
  double worst = 0.0;
  for (double v : avg.mean_depth.depth_m) worst = std::max(worst, std::abs(v - expected));
  RecordProperty("uniform_offset_mean_error_m", sci(worst));
  EXPECT_LT(worst, 1e-6);
  for (int i = 0; i <= 200; ++i) {
    const double theta = -0.14 + 0.28 * i / 200.0;
    EXPECT_NEAR(radius_at(avg.profile, theta), kR - expected, 1e-7);
  }
  EXPECT_THROW(AverageAlongNormals(base, shifted, {0.5, 0.5, 0.5}), InputError);
}

TEST(RailUpdate, RemovedAreaOfAUniformOffsetIsDepthTimesLength) {
  // a crown worn by a uniform depth d along its normals is the concentric circle of radius R - d: the depth along
  // the old normals is d everywhere, the first-order area d L (the exact area between the arcs is (d - d^2/(2R)) L)
  const Profile base = crown();
  const double d = 0.1e-3;
  WearDistribution u = WearDistribution::ForProfile(base, 0.1e-3);
  std::fill(u.depth_m.begin(), u.depth_m.end(), d);
  const RemovedAlongNormals m = MeasureRemovedAlongNormals(base, RemoveAlongNormal(base, u));
  EXPECT_NEAR(m.max_depth_m, d, 1e-10);
  for (double t : m.depth.depth_m) EXPECT_NEAR(t, d, 1e-10);
  EXPECT_NEAR(m.area_m2, d * base.length(), 1e-9 * d * base.length());
  // nothing removed: zero area; the base against itself
  const RemovedAlongNormals z = MeasureRemovedAlongNormals(base, base);
  EXPECT_LT(std::abs(z.area_m2), 1e-18);
  EXPECT_LT(z.max_depth_m, 1e-12);
}

TEST(RailUpdate, AveragedRailIsTheMeanOfTheVirtualRails) {
  const Profile rail = crown();
  // three wheel profiles give three different rail wear bands (per passage)
  const std::vector<WearDistribution> wear = {band(rail, 0.0, 6e-3, 2e-9), band(rail, -15e-3, 4e-3, 1e-9),
                                              band(rail, 10e-3, 8e-3, 0.5e-9)};
  const std::vector<double> w = {0.5, 0.3, 0.2};
  RailStepOptions o;
  o.step_index = 2;
  const RailStepResult r = UpdateRail(rail, wear, w, 1.0, o);
  ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
  ASSERT_EQ(r.virtual_rails.size(), 3u);
  // the mean removed depth reaches the rail cap (0.1 mm) and the passages follow from the scale factor
  EXPECT_NEAR(r.mean_removed_depth.max_depth_m(), o.max_depth_per_step_m, 0.01 * o.max_depth_per_step_m);
  EXPECT_NEAR(r.passages_step, r.scale_factor, 1e-9 * r.scale_factor);
  // independent check on rays from the crown centre: radius of the averaged rail = weighted mean of the
  // radii of the virtual rails (the crown normals are these rays)
  double worst = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double theta = -0.145 + 0.29 * i / 400.0;
    double mean = 0.0;
    for (size_t j = 0; j < 3; ++j) mean += w[j] * radius_at(r.virtual_rails[j], theta);
    worst = std::max(worst, std::abs(radius_at(r.rail, theta) - mean));
  }
  RecordProperty("averaged_vs_mean_virtual_m", sci(worst));
  EXPECT_LT(worst, 1e-7);
}

TEST(RailUpdate, Real60E1RailWithGaugeCornerWearStaysValid) {
  Profile rail = MakeRail(RailSection::R60E1, rail_inclination_1in40());
  // five wheel profiles moving the contact from the crown towards the gauge corner (gauge side is -y)
  for (int step = 1; step <= 5; ++step) {
    std::vector<WearDistribution> wear;
    for (int j = 0; j < 5; ++j)
      wear.push_back(band(rail, -5e-3 - 5e-3 * j, 3e-3, 1e-9 * (1 + j)));
    RailStepOptions o;
    o.step_index = step;
    const RailStepResult r = UpdateRail(rail, wear, {}, 1.0, o);
    ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
    EXPECT_NEAR(r.mean_removed_depth.max_depth_m(), o.max_depth_per_step_m, 0.01 * o.max_depth_per_step_m);
    EXPECT_EQ(r.validity.y_folds_after, r.validity.y_folds_before);
    rail = r.rail;
  }
}
