// KP and KPEC on Hertzian gaps against the exact Hertz solution (docs/physics-reference.md §1.2, §3.2 table, §3.3).
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cstdio>

#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

struct Case {
  double ratio;
  HertzResult hertz;
  KpResult kp;
  KpResult kpec;
};

Case Solve(double ratio, double load_N) {
  Material material;
  const auto curv = kp_test::CurvaturesForRatio(ratio, 2.5, material);
  Case out;
  out.ratio = ratio;
  out.hertz = SolveHertzForLoad(curv.A, curv.B, load_N, material);
  const PatchGeometry patch = kp_test::HertzianPatch(curv.A, curv.B, 1.6 * out.hertz.b_m, 81);
  KpLoadOptions options;
  options.kp = PlanarKpOptions(material);
  out.kp = SolveKikPiotrowskiForLoad(patch, load_N, options);
  options.kp = KpecOptions(material);
  out.kpec = SolveKikPiotrowskiForLoad(patch, load_N, options);
  return out;
}

double Rel(double value, double reference) { return value / reference - 1.0; }

TEST(KpHertz, KpecWithinTwoPercentAndKpWithinTwelvePercentOfHertz) {
  const double load = 50.0e3;
  std::printf("  a/b    KP dp0    KP dA     KP dwidth KP dlen  KP ddelta | KPEC dp0  KPEC dA   KPEC dwidth KPEC ddelta\n");
  for (double ratio : {0.2, 0.37, 0.5, 1.0, 1.33, 2.0, 3.16, 5.0}) {
    const Case c = Solve(ratio, load);
    ASSERT_EQ(c.kp.status, KpStatus::Ok);
    ASSERT_EQ(c.kpec.status, KpStatus::Ok);
    EXPECT_NEAR(c.kp.fn_N, load, 1e-8 * load);
    EXPECT_NEAR(c.kpec.fn_N, load, 1e-8 * load);
    const double area = M_PI * c.hertz.a_m * c.hertz.b_m;
    std::printf("  %4.2f  %+7.2f%%  %+7.2f%%  %+7.2f%%  %+7.2f%%  %+7.2f%% | %+7.3f%%  %+7.3f%%  %+7.3f%%  %+7.3f%%\n",
                ratio, 100 * Rel(c.kp.pmax_Pa, c.hertz.p0_Pa), 100 * Rel(c.kp.area_m2, area),
                100 * Rel(c.kp.width_m, 2 * c.hertz.b_m), 100 * Rel(c.kp.length_m, 2 * c.hertz.a_m),
                100 * Rel(c.kp.approach_m, c.hertz.approach_m), 100 * Rel(c.kpec.pmax_Pa, c.hertz.p0_Pa),
                100 * Rel(c.kpec.area_m2, area), 100 * Rel(c.kpec.width_m, 2 * c.hertz.b_m),
                100 * Rel(c.kpec.approach_m, c.hertz.approach_m));
    EXPECT_LT(std::abs(Rel(c.kpec.pmax_Pa, c.hertz.p0_Pa)), 0.02) << "a/b " << ratio;
    EXPECT_LT(std::abs(Rel(c.kpec.area_m2, area)), 0.02) << "a/b " << ratio;
    // Plain KP: within 12 % over the range of the docs/physics-reference.md §3.2 table (a/b = 0.37 ... 3.16). Outside
    // it the constant eps = 0.55 bias grows beyond 12 % (measured -13.9 % p0 / +16.2 % area at a/b = 0.2 and 5): that
    // is KP's model error, asserted as a growing bias rather than hidden by a looser bound.
    if (ratio >= 0.37 && ratio <= 3.16) {
      EXPECT_LT(std::abs(Rel(c.kp.pmax_Pa, c.hertz.p0_Pa)), 0.12) << "a/b " << ratio;
      EXPECT_LT(std::abs(Rel(c.kp.area_m2, area)), 0.12) << "a/b " << ratio;
    } else {
      EXPECT_LT(Rel(c.kp.pmax_Pa, c.hertz.p0_Pa), -0.105) << "a/b " << ratio;
    }
    // KP's known bias (docs/physics-reference.md §3.2): pressure low, area large.
    EXPECT_LT(c.kp.pmax_Pa, c.hertz.p0_Pa);
    EXPECT_GT(c.kp.area_m2, area);
  }
}

TEST(KpHertz, CircleTableValues) {
  // docs/physics-reference.md §3.2 table: a/b = 1 -> p0 -6.2 %, area +6.6 %; a/b = 3.16 -> -10.5 %, +11.7 %.
  const Case circle = Solve(1.0, 100.0e3);
  EXPECT_NEAR(Rel(circle.kp.pmax_Pa, circle.hertz.p0_Pa), -0.062, 0.01);
  EXPECT_NEAR(Rel(circle.kp.area_m2, M_PI * circle.hertz.a_m * circle.hertz.b_m), 0.066, 0.01);
  const Case long_patch = Solve(3.16, 100.0e3);
  EXPECT_NEAR(Rel(long_patch.kp.pmax_Pa, long_patch.hertz.p0_Pa), -0.105, 0.015);
  EXPECT_NEAR(Rel(long_patch.kp.area_m2, M_PI * long_patch.hertz.a_m * long_patch.hertz.b_m), 0.117, 0.015);
}

TEST(KpHertz, KpecApproachGivenReproducesHertzPressure) {
  Material material;
  const auto curv = kp_test::CurvaturesForRatio(1.33, 2.5, material);
  const HertzResult hertz = SolveHertzForLoad(curv.A, curv.B, 50.0e3, material);
  const PatchGeometry patch = kp_test::HertzianPatch(curv.A, curv.B, 1.6 * hertz.b_m, 81);
  const KpResult kpec = SolveKikPiotrowskiForApproach(patch, hertz.approach_m, KpecOptions(material));
  EXPECT_NEAR(kpec.pmax_Pa / hertz.p0_Pa, 1.0, 0.005);
  EXPECT_NEAR(kpec.fn_N / hertz.normal_force_N, 1.0, 0.005);
  EXPECT_NEAR(kpec.width_m / (2 * hertz.b_m), 1.0, 1e-6);
  EXPECT_NEAR(kpec.length_m / (2 * hertz.a_m), 1.0, 1e-6);
}

}  // namespace
}  // namespace conforma
