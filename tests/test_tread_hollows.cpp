// Separate hollows of a worn tread (WheelWearDepths::tread_hollows, MeasureWheelWear): one smooth hollow counts 1,
// two grooves count 2, a groove shallower than the prominence threshold does not count.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conforma/standard_profiles.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {
namespace {

struct Groove {
  double y_m, depth_m, half_width_m;  // Gaussian depth across y
};

// The S1002 with material removed along its inward normal: the sum of the grooves' Gaussian depths at each node's y.
Profile Worn(const Profile& initial, const std::vector<Groove>& grooves) {
  std::vector<Eigen::Vector2d> p = initial.samples();
  for (size_t i = 0; i < p.size(); ++i) {
    double d = 0.0;
    for (const Groove& g : grooves) d += g.depth_m * std::exp(-std::pow((p[i].x() - g.y_m) / g.half_width_m, 2));
    p[i] -= d * initial.normal(initial.spacing() * i);
  }
  return Profile::FromPoints(p, ProfileKind::Wheel);
}

TEST(TreadHollows, OneHollowTwoGroovesAndAShallowRipple) {
  const Profile s1002 = MakeS1002();
  const WheelWearDepths one = MeasureWheelWear(s1002, Worn(s1002, {{2e-3, 0.8e-3, 12e-3}}));
  EXPECT_NEAR(one.tread_m, 0.8e-3, 0.02e-3);
  EXPECT_EQ(one.tread_hollows, 1);
  const WheelWearDepths two = MeasureWheelWear(s1002, Worn(s1002, {{-5e-3, 0.4e-3, 3e-3}, {12e-3, 0.5e-3, 3e-3}}));
  EXPECT_EQ(two.tread_hollows, 2);
  const WheelWearDepths three =
      MeasureWheelWear(s1002, Worn(s1002, {{-10e-3, 0.3e-3, 2.5e-3}, {0.0, 0.3e-3, 2.5e-3}, {10e-3, 0.3e-3, 2.5e-3}}));
  EXPECT_EQ(three.tread_hollows, 3);
  // a 10 um ripple beside a 0.8 mm hollow is below max(20 um, 10 % of the depth): one hollow
  const WheelWearDepths ripple = MeasureWheelWear(s1002, Worn(s1002, {{2e-3, 0.8e-3, 6e-3}, {25e-3, 10e-6, 2e-3}}));
  EXPECT_EQ(ripple.tread_hollows, 1);
  // no wear, no hollow; flange wear alone is not a tread hollow
  EXPECT_EQ(MeasureWheelWear(s1002, s1002).tread_hollows, 0);
  EXPECT_EQ(MeasureWheelWear(s1002, Worn(s1002, {{-40e-3, 0.5e-3, 2e-3}})).tread_hollows, 0);
}

}  // namespace
}  // namespace conforma
