// test-links: profiles
// Profile::s_at (profile.hpp): the arc length of a lateral position is found by a binary search per monotonic run of
// the samples; it must return exactly what the plain scan over all segments returns (the first segment in s that
// holds y, then 40 bisections), on monotonic profiles and on profiles that turn back in y (overhangs), including y
// equal to a sample's y (where two segments meet) and y on a segment of constant y.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "conforma/profile.hpp"
#include "conforma/standard_profiles.hpp"

using namespace conforma;

namespace {

// the scan s_at used before the runs: every segment in order, the first one that holds y
std::optional<double> ScanArcLength(const Profile& p, double y) {
  const std::vector<Eigen::Vector2d> pts = p.samples();
  double y_min = pts[0].x(), y_max = pts[0].x();
  for (const auto& q : pts) y_min = std::min(y_min, q.x()), y_max = std::max(y_max, q.x());
  if (y < y_min || y > y_max) return std::nullopt;
  const double h = p.spacing();
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double y0 = pts[i].x(), y1 = pts[i + 1].x();
    if ((y0 <= y && y <= y1 && y1 > y0) || (y1 <= y && y <= y0 && y0 > y1)) {
      double lo = static_cast<double>(i) * h, hi = static_cast<double>(i + 1) * h;
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        if ((p.position(mid).x() < y) == (y1 > y0)) lo = mid; else hi = mid;
      }
      return 0.5 * (lo + hi);
    }
  }
  return std::nullopt;
}

void ExpectSameAsScan(const Profile& p) {
  const std::vector<Eigen::Vector2d> pts = p.samples();
  std::vector<double> ys;
  for (const auto& q : pts) ys.push_back(q.x());  // sample values: where two segments meet
  double y_min = ys[0], y_max = ys[0];
  for (double y : ys) y_min = std::min(y_min, y), y_max = std::max(y_max, y);
  for (int k = -5; k <= 2005; ++k) ys.push_back(y_min + (y_max - y_min) * k / 2000.0);  // and outside the range
  int found = 0;
  for (double y : ys) {
    const std::optional<double> fast = p.s_at(y), scan = ScanArcLength(p, y);
    ASSERT_EQ(fast.has_value(), scan.has_value()) << p.source() << " y = " << y;
    if (fast) {
      ++found;
      ASSERT_EQ(*fast, *scan) << p.source() << " y = " << y;  // bit for bit
    }
  }
  EXPECT_GT(found, 2000);
}

}  // namespace

TEST(ProfileArcLengthOfY, EqualsTheScanOnStandardProfiles) {
  ExpectSameAsScan(MakeS1002());
  ExpectSameAsScan(MakeRail(RailSection::R60E1, 1.0 / 40.0));
}

TEST(ProfileArcLengthOfY, EqualsTheScanOnAProfileThatTurnsBackAndHasAFlatStep) {
  // an S-shaped curve: y(t) = t - 1.5 sin t turns back twice over [0, 4 pi] (runs +, -, +, -, +), scaled to mm
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i <= 400; ++i) {
    const double t = 4.0 * 3.14159265358979323846 * i / 400.0;
    pts.emplace_back(1e-3 * (t - 1.5 * std::sin(t)), 1e-3 * 0.5 * t);
  }
  ProfileFitOptions fit;
  fit.function_of_y = false;
  fit.sample_spacing_m = 0.05e-3;
  const Profile curve = Profile::FromPoints(pts, ProfileKind::Rail, fit, "s-curve");
  ExpectSameAsScan(curve);
  // samples with a segment of constant y (a vertical step) between two increasing runs
  std::vector<Eigen::Vector2d> step;
  for (int i = 0; i < 10; ++i) step.emplace_back(1e-3 * i, 0.0);
  step.emplace_back(9e-3, 1e-3);
  for (int i = 0; i < 10; ++i) step.emplace_back(1e-3 * (9 + i) + 1e-3, 1e-3);
  ExpectSameAsScan(Profile::FromArcLengthSamples(step, ProfileKind::Rail, "step"));
}
