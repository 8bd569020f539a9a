// Arc-length parametrisation, normals and curvature of the Profile curve against a circle (exact geometry).
// test-links: profiles  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/profile.hpp"

using conforma::Profile;
using conforma::ProfileKind;

namespace {
// Upper arc of a circle radius R centred at (0, -R): a convex rail crown, z up, y from -w to w.
Profile crown(double R, double half_angle, int n) {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < n; ++i) {
    const double th = -half_angle + 2 * half_angle * i / (n - 1);
    p.emplace_back(R * std::sin(th), -R + R * std::cos(th));
  }
  return Profile::FromPoints(p, ProfileKind::Rail);
}
}  // namespace

TEST(ProfileBasic, CircleArcLengthCurvatureNormal) {
  const double R = 0.3, half = 0.1;
  Profile prof = crown(R, half, 400);
  EXPECT_NEAR(prof.length(), 2 * R * half, 1e-7);
  for (double f : {0.1, 0.37, 0.5, 0.8}) {
    const double s = f * prof.length();
    EXPECT_NEAR(prof.curvature(s), 1.0 / R, 1e-3 / R);  // convex crown: positive curvature
    const Eigen::Vector2d q = prof.position(s);
    const Eigen::Vector2d radial = (q - Eigen::Vector2d(0, -R)).normalized();
    EXPECT_NEAR(prof.normal(s).dot(radial), 1.0, 1e-9);  // outward normal
    EXPECT_NEAR((q - Eigen::Vector2d(0, -R)).norm(), R, 1e-9);
  }
  EXPECT_NEAR(*prof.height_at(0.0), 0.0, 1e-10);
  EXPECT_FALSE(prof.height_at(0.5).has_value());
}

TEST(ProfileBasic, RefusesTooFewAndNonFinitePoints) {
  EXPECT_THROW(Profile::FromPoints({{0, 0}, {1, 0}}, ProfileKind::Rail), conforma::InputError);
  EXPECT_THROW(Profile::FromPoints({{0, 0}, {1, 0}, {2, NAN}, {3, 0}, {4, 1}}, ProfileKind::Rail), conforma::InputError);
}
