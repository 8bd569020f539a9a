// test-links: profiles
// Profile::WithMovedSamples (profile.hpp): samples moved on the same arc-length grid, the splines re-solved around
// them. The new curve passes through the moved samples, equals the natural spline through all samples (a global
// solve) to rounding, and is the old curve bit for bit outside its window.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/profile.hpp"

namespace conforma {
namespace {

Profile Arc() {  // a circular arc of radius 20 mm, 0.02 mm samples
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 400; ++i) {
    const double a = -0.4 + 0.8 * i / 400.0;
    p.emplace_back(0.02 * std::sin(a), 0.02 * (std::cos(a) - 1.0));
  }
  ProfileFitOptions fit;
  fit.sample_spacing_m = 0.02e-3;
  return Profile::FromPoints(p, ProfileKind::Rail, fit, "arc");
}

TEST(ProfileMovedSamples, LocalResolveIsTheNaturalSplineThroughTheSamples) {
  const Profile arc = Arc();
  const double h = arc.spacing();
  const size_t n = arc.sample_count(), first = n / 2 - 20;
  // unmoved: the same curve to rounding (the window's second derivatives are solved again)
  std::vector<Eigen::Vector2d> same;
  for (size_t i = first; i < first + 41; ++i) same.push_back(arc.sample_at(i));
  const Profile unmoved = arc.WithMovedSamples(first, same);
  double unmoved_largest = 0.0;
  for (double s = 0.0; s <= arc.length(); s += 0.37 * h)
    unmoved_largest = std::max(unmoved_largest, (unmoved.position(s) - arc.position(s)).norm());
  EXPECT_LT(unmoved_largest, 1e-17);
  // 1 um of wear, a cosine bell over 41 samples, along the normals
  std::vector<Eigen::Vector2d> moved;
  for (size_t i = first; i < first + 41; ++i) {
    const double u = (static_cast<double>(i - first) - 20.0) / 20.0;
    moved.push_back(arc.sample_at(i) - 0.5e-6 * (1.0 + std::cos(3.14159265358979 * u)) * arc.normal(i * h));
  }
  const Profile worn = arc.WithMovedSamples(first, moved);
  EXPECT_EQ(worn.spacing(), arc.spacing());
  EXPECT_EQ(worn.length(), arc.length());
  // the same samples through the global solve: nodes at i h (FromArcLengthSamples takes h from the polyline, so the
  // comparison is at the nodes and mid-segment, after scaling its parameter to this h; Profile::curvature takes the
  // parameter as arc length, so its value scales with 1 / scale^2)
  std::vector<Eigen::Vector2d> all;
  for (size_t i = 0; i < n; ++i) all.push_back(worn.sample_at(i));
  const Profile global = Profile::FromArcLengthSamples(all, ProfileKind::Rail, "global");
  const double scale = global.spacing() / h;
  double largest = 0.0, largest_curvature = 0.0;
  for (size_t i = 0; i + 1 < n; ++i) {
    for (double t : {0.0, 0.5}) {
      const double s = (static_cast<double>(i) + t) * h;
      largest = std::max(largest, (worn.position(s) - global.position(s * scale)).norm());
      largest_curvature =
          std::max(largest_curvature, std::abs(worn.curvature(s) - global.curvature(s * scale) * scale * scale) / 50.0);
    }
  }
  std::printf("local - global solve: position %.3g m, curvature %.3g (relative); unmoved %.3g m\n", largest,
              largest_curvature, unmoved_largest);
  EXPECT_LT(largest, 1e-17);            // m: rounding of coordinates of ~0.02 m
  // relative to the arc's 50 1/m; the rounding of second differences is ulp(0.02 m) / h^2 ~ 1e-8 1/m = 2e-10
  EXPECT_LT(largest_curvature, 2e-10);
  for (size_t i = 0; i < n; ++i) EXPECT_LT((worn.position(i * h) - worn.sample_at(i)).norm(), 1e-17) << i;
  // outside the window of re-solved samples the old curve, bit for bit
  const size_t margin = Profile::kMovedSplineMargin;
  for (size_t i = 0; i + 1 < first - margin; ++i) EXPECT_EQ(worn.position((i + 0.5) * h), arc.position((i + 0.5) * h));
  for (size_t i = first + 41 + margin; i + 1 < n; ++i)
    EXPECT_EQ(worn.position((i + 0.5) * h), arc.position((i + 0.5) * h));
  EXPECT_THROW(arc.WithMovedSamples(n - 2, moved), InputError);
}

}  // namespace
}  // namespace conforma
