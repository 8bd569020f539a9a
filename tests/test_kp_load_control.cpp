// Load control of the KP solvers: several patches of one wheel sharing one rigid approach.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/load_control.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

TEST(KpLoadControl, QuadraticGapGivesLoadProportionalToApproachToThePowerOneAndAHalf) {
  Material material;
  const PatchGeometry patch = kp_test::HertzianPatch(0.8, 1.6, 0.012, 81);
  const KpOptions options = PlanarKpOptions(material);
  const KpResult one = SolveKikPiotrowskiForApproach(patch, 3e-5, options);
  const KpResult two = SolveKikPiotrowskiForApproach(patch, 6e-5, options);
  EXPECT_NEAR(two.fn_N / one.fn_N, std::pow(2.0, 1.5), 1e-9);
  EXPECT_NEAR(two.pmax_Pa / one.pmax_Pa, std::sqrt(2.0), 1e-9);
}

TEST(KpLoadControl, TwoPatchesShareOneApproach) {
  Material material;
  const PatchGeometry tread = kp_test::HertzianPatch(0.8, 1.6, 0.012, 81);
  const PatchGeometry flange = kp_test::HertzianPatch(1.2, 8.0, 0.006, 61);
  const double offset = 2.0e-5;
  std::vector<WheelPatch> patches = {{&tread, 0.0, 1.0}, {&flange, offset, 0.6}};
  LoadControlOptions options;
  options.kp = PlanarKpOptions(material);
  const WheelNormalResult wheel = SolveWheelForLoad(patches, 80.0e3, options);
  ASSERT_EQ(wheel.status, LoadControlStatus::Ok);
  EXPECT_NEAR(wheel.load_N, 80.0e3, 1e-6 * 80.0e3);
  EXPECT_NEAR(wheel.patches[0].fn_N + 0.6 * wheel.patches[1].fn_N, 80.0e3, 1e-6 * 80.0e3);
  EXPECT_GT(wheel.patches[1].fn_N, 0.0);
  EXPECT_NEAR(wheel.patches[0].approach_m - wheel.patches[1].approach_m, offset, 1e-15);
  // Approach-given mode at the found approach reproduces the same forces.
  const WheelNormalResult again = SolveWheelForApproach(patches, wheel.approach_m, options.kp);
  EXPECT_NEAR(again.load_N, wheel.load_N, 1e-9 * wheel.load_N);
  // A light load does not reach the second patch.
  const WheelNormalResult light = SolveWheelForLoad(patches, 1.0e3, options);
  ASSERT_EQ(light.status, LoadControlStatus::Ok);
  EXPECT_LT(light.approach_m, offset);
  EXPECT_EQ(light.patches[1].status, KpStatus::NoContact);
  EXPECT_EQ(light.patches[1].fn_N, 0.0);
  EXPECT_NEAR(light.patches[0].fn_N, 1.0e3, 1e-6 * 1.0e3);
}

TEST(KpLoadControl, LoadGrowsMonotonicallyWithApproach) {
  Material material;
  const PatchGeometry groove = kp_test::GroovePatch(10e-3, 10.05e-3, 0.42, 12e-3, 241);
  double previous = 0.0;
  for (double approach = 1e-6; approach < 4e-5; approach *= 1.3) {
    const KpResult r = SolveKikPiotrowskiForApproach(groove, approach, ConformalKpOptions(material));
    EXPECT_GT(r.fn_N, previous);
    previous = r.fn_N;
  }
}

TEST(KpLoadControl, ZeroLoadAndBadInput) {
  Material material;
  const PatchGeometry patch = kp_test::HertzianPatch(0.8, 1.6, 0.012, 81);
  LoadControlOptions options;
  options.kp = PlanarKpOptions(material);
  const KpResult none = SolveKikPiotrowskiForLoad(patch, 0.0, options);
  EXPECT_EQ(none.status, KpStatus::NoContact);
  EXPECT_EQ(none.fn_N, 0.0);
  EXPECT_THROW(SolveKikPiotrowskiForLoad(patch, -1.0, options), InputError);
  EXPECT_THROW(SolveKikPiotrowskiForLoad(patch, std::nan(""), options), InputError);
  PatchGeometry broken = patch;
  broken.gap_m[3] = std::nan("");
  EXPECT_THROW(SolveKikPiotrowskiForApproach(broken, 1e-5, options.kp), InputError);
  broken = patch;
  broken.longitudinal_curvature_per_m.pop_back();
  EXPECT_THROW(SolveKikPiotrowskiForApproach(broken, 1e-5, options.kp), InputError);
}

TEST(KpLoadControl, CutPatchIsReported) {
  Material material;
  const PatchGeometry narrow = kp_test::HertzianPatch(0.8, 1.6, 0.002, 21);  // strips end inside the contact
  const KpResult r = SolveKikPiotrowskiForApproach(narrow, 5e-5, PlanarKpOptions(material));
  EXPECT_EQ(r.status, KpStatus::ContactAtPatchBoundary);
  EXPECT_GT(r.fn_N, 0.0);
  EXPECT_NEAR(r.width_m, 0.004 + narrow.ds_m, 1e-12);
}

}  // namespace
}  // namespace conforma
