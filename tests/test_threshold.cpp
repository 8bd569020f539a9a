// Conformity-threshold study (threshold.hpp): the fit on synthetic data with a known threshold, conformal equal
// to planar on a flat patch, and the difference growing with the conformity of CONTACT's grooves.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "conforma/error.hpp"
#include "conforma/validation/threshold.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

ThresholdPoint Point(double alpha, double d) {
  ThresholdPoint p;
  p.valid = true;
  p.alpha_c_deg = alpha;
  p.d_pmax = p.d_max = d;
  return p;
}

TEST(Threshold, StepAndPowerFitsRecoverAKnownThreshold) {
  // d = 0.05 (alpha / 12)^2: exceeds 5 % exactly above 12 degrees
  std::vector<ThresholdPoint> points;
  for (double a = 0.75; a <= 40.0; a += 0.5) points.push_back(Point(a, 0.05 * (a / 12.0) * (a / 12.0)));
  const ThresholdFit fit = FitConformityThreshold(points, 0.05);
  EXPECT_EQ(fit.misclassified, 0);
  EXPECT_DOUBLE_EQ(fit.threshold_deg, 12.25);  // the smallest sampled alpha with d > tol
  EXPECT_DOUBLE_EQ(fit.bracket_low_deg, 11.75);
  EXPECT_NEAR(fit.power_k, 2.0, 1e-9);
  EXPECT_NEAR(fit.power_threshold_deg, 12.0, 1e-6);
  EXPECT_NEAR(fit.power_r2, 1.0, 1e-12);
  // one outlier below the threshold and one above do not move the step fit (two misclassified points)
  points.push_back(Point(3.0, 0.2));
  points.push_back(Point(30.0, 0.01));
  const ThresholdFit noisy = FitConformityThreshold(points, 0.05);
  EXPECT_DOUBLE_EQ(noisy.threshold_deg, 12.25);
  EXPECT_EQ(noisy.misclassified, 2);
  // nothing exceeds: no threshold
  EXPECT_TRUE(std::isinf(FitConformityThreshold(points, 10.0).threshold_deg));
  // the per-metric selector is used
  EXPECT_TRUE(std::isinf(FitConformityThreshold(points, 0.05, [](const ThresholdPoint& p) { return p.d_area; })
                             .threshold_deg));
}

// A flat Hertzian patch (a/b ~ 0.8, 50 kN, moderate creepages with spin).
BenchCase FlatHertzianSituation() {
  BenchCase c;
  c.name = "flat";
  const kp_test::Curvatures k = kp_test::CurvaturesForRatio(0.8, 4.0, c.material);
  c.patch = kp_test::HertzianPatch(k.A, k.B, 10e-3, 201);
  c.hertz_A_per_m = k.A;
  c.hertz_B_per_m = k.B;
  c.normal_load_N = 50e3;
  c.creepages = {1e-3, 1e-3, 0.5};
  return c;
}

TEST(Threshold, ConformalEqualsPlanarOnAFlatPatch) {
  const BenchCase c = FlatHertzianSituation();
  const ThresholdPoint t = CompareConformalPlanar(c, ThresholdOptions{});
  ASSERT_TRUE(t.valid) << t.status;
  EXPECT_NEAR(t.alpha_c_deg, 0.0, 1e-12);
  // same influence function (alpha = 0, K = 0) and the same FASTSIM on the same strips
  EXPECT_LT(t.d_max, 1e-9);
  ThresholdOptions curvilinear;
  curvilinear.against = PlanarComparison::CurvilinearKp;
  EXPECT_LT(CompareConformalPlanar(c, curvilinear).d_max, 1e-9);
}

TEST(Threshold, FlattenedGrooveHasTheVerticalGapOfTheTwoCircles) {
  // wheel circle R_w touching a groove R_g at the bottom: z_rail(y) = R_g - sqrt(R_g^2 - y^2), z_wheel likewise
  const double Rw = 10e-3, Rg = 10.25e-3;
  const PatchGeometry curved = kp_test::GroovePatch(Rw, Rg, 0.42, 9e-3, 181);
  const PatchGeometry flat = FlattenPatch(curved);
  ASSERT_GT(flat.strips(), 100u);
  EXPECT_NEAR(flat.ds_m, curved.ds_m, 1e-15);
  int checked = 0;
  for (size_t j = 0; j < flat.strips(); ++j) {
    const double y = flat.s_m[j];
    EXPECT_EQ(flat.alpha_rad[j], 0.0);
    if (std::fabs(y) > 0.7 * Rw) continue;
    const double expected = (Rw - std::sqrt(Rw * Rw - y * y)) - (Rg - std::sqrt(Rg * Rg - y * y));
    EXPECT_NEAR(flat.gap_m[j], expected, 0.3e-6) << "y = " << y;
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // a flat patch is its own projection
  const PatchGeometry hertzian = kp_test::HertzianPatch(2.0, 3.0, 5e-3, 51);
  const PatchGeometry same = FlattenPatch(hertzian);
  ASSERT_EQ(same.strips(), hertzian.strips());
  for (size_t j = 0; j < same.strips(); ++j) {
    EXPECT_NEAR(same.s_m[j], hertzian.s_m[j], 1e-15);
    EXPECT_NEAR(same.gap_m[j], hertzian.gap_m[j], 1e-15);
  }
}

TEST(Threshold, DifferenceGrowsWithTheConformityOfTheGroove) {
  const std::vector<BenchCase> grooves = MakeThresholdSituations("groove", CONFORMA_SHARED_DATA);
  ASSERT_GE(grooves.size(), 6u);
  const std::vector<ThresholdPoint> points = CompareConformalPlanar(grooves, ThresholdOptions{});
  double previous_alpha = 0.0;
  for (const ThresholdPoint& p : points) {
    ASSERT_TRUE(p.valid) << p.name << " " << p.status;
    EXPECT_GT(p.alpha_c_deg, previous_alpha) << p.name;  // radii decrease: conformity increases
    previous_alpha = p.alpha_c_deg;
  }
  // the difference grows with the conformity, from < 1 % for the loosest groove to beyond 5 % for the tightest
  for (size_t k = 1; k < points.size(); ++k) {
    EXPECT_GT(points[k].d_pmax, points[k - 1].d_pmax) << points[k].name;
    EXPECT_GT(points[k].d_area, points[k - 1].d_area) << points[k].name;
  }
  EXPECT_LT(points.front().d_max, 0.01);
  EXPECT_GT(points.back().d_max, 0.05);
  // size of the conformal correction at the tightest groove: CONTACT's half-space and Blanco rows of
  // contact_groove_li.csv differ by 4.5 % in p_max (296.8 vs 283.6 MPa); the same order here
  EXPECT_GT(points.back().d_pmax, 0.5 * 0.045);
  EXPECT_LT(points.back().d_pmax, 2.0 * 0.045);
  const ThresholdFit fit = FitConformityThreshold(points, 0.05);
  EXPECT_EQ(fit.misclassified, 0);
  EXPECT_GT(fit.threshold_deg, points.front().alpha_c_deg);
  EXPECT_LE(fit.threshold_deg, points.back().alpha_c_deg);
  // the correction grows like a power of alpha_c (alpha_c^2 for the cos(alpha_J - alpha_I) factor at small angles)
  EXPECT_GT(fit.power_k, 1.0);
  EXPECT_LT(fit.power_k, 3.0);
}

TEST(Threshold, AgainstTheExactSolutionAFlatHertzianPatchIsWithinTheTolerance) {
  // a flat Hertzian patch (a/b ~ 0.8): planar KP against the exact solver (BEM + Kalker's exact tangential) differs
  // by KP's own approximation only: p_max and area within a few per cent (bench: KP tread rows 1-8 %), alpha_c of
  // the exact contact 0
  const BenchCase c = FlatHertzianSituation();
  ThresholdOptions exact;
  exact.reference = ThresholdReference::Exact;
  exact.against = PlanarComparison::Hertz;
  const ThresholdPoint h = CompareConformalPlanar(c, exact);
  ASSERT_TRUE(h.valid) << h.status;
  EXPECT_NEAR(h.alpha_c_deg, 0.0, 1e-9);
  EXPECT_LT(h.d_pmax, 0.02) << "Hertz on a Hertzian patch";
  EXPECT_LT(h.d_area, 0.03);
  exact.against = PlanarComparison::CurvilinearKp;
  const ThresholdPoint kp = CompareConformalPlanar(c, exact);
  ASSERT_TRUE(kp.valid) << kp.status;
  EXPECT_GT(kp.d_pmax, h.d_pmax) << "KP's eps = 0.55 is less exact than Hertz on an elliptic patch";
  EXPECT_LT(kp.d_pmax, 0.15);
  std::printf("against exact: hertz d_pmax %.4f d_area %.4f; kp d_pmax %.4f d_area %.4f\n", h.d_pmax, h.d_area,
              kp.d_pmax, kp.d_area);
  EXPECT_THROW(ParseThresholdReference("bem"), InputError);
  EXPECT_EQ(ParseThresholdReference("exact"), ThresholdReference::Exact);
}

}  // namespace
}  // namespace conforma
