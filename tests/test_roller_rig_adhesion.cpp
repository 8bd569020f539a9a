// test-links: validation
// Roller-rig adhesion tests of paper 000 (Table 6): the data file, the rig contact at the centred position, Kalker's
// linear theory against FASTSIM's initial slope, and the friction-law fit (docs/physics-reference.md §7.5).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "conforma/error.hpp"
#include "conforma/validation/roller_rig_adhesion.hpp"
#include "conforma/validation/roller_rig_adhesion_fit.hpp"

namespace conforma {
namespace {

const std::string kTable = std::string(CONFORMA_SOURCE_DIR) + "/validation/data/roller_rig_000_table6.csv";

TEST(RollerRigAdhesion, TableHasTheEightTestsOfTable6) {
  const auto tests = ReadRollerRigAdhesionTable(kTable);
  ASSERT_EQ(tests.size(), 8u);
  EXPECT_EQ(tests[0].test, 1);
  EXPECT_DOUBLE_EQ(tests[0].reference_speed_rpm, 1000.0);
  EXPECT_DOUBLE_EQ(tests[6].wheel_load_kg, 47.0);
  EXPECT_DOUBLE_EQ(tests[6].initial_slope_N, 18000.0);
  EXPECT_EQ(tests[7].condition, "wet");
  EXPECT_THROW(ReadRollerRigAdhesionTable(kTable + ".missing"), InputError);
}

// The rig ellipse: A = 1/(2 r_w) + 1/(2 R_r) exactly; B from the scaled profiles is 5 times the full-scale B.
TEST(RollerRigAdhesion, CentredCurvaturesScaleWithTheLengthFactor) {
  RollerRigAdhesionOptions o;
  const RollerRigCurvatures c = RollerRigCentredCurvatures(o);
  EXPECT_NEAR(c.A_per_m, 0.5 / 0.0944 + 0.5 / 0.185, 1e-12);
  EXPECT_NEAR(c.B_per_m, 5.0 * c.full_scale_B_per_m, 1e-9 * c.B_per_m);
  EXPECT_GT(c.full_scale_B_per_m, 0.0);
  // centred wheelset: tread contact near the taping line, small contact angle
  EXPECT_LT(std::abs(c.contact_angle_rad), 0.1);
  o.roller_profile = RollerProfileChoice::TrackEllipseRatio;
  const RollerRigCurvatures t = RollerRigCentredCurvatures(o);
  EXPECT_NEAR(t.A_per_m / t.B_per_m, t.full_scale_A_per_m / t.full_scale_B_per_m, 1e-12);
  std::printf("A = %.4f 1/m, B = %.4f 1/m (scaled UIC60), B = %.4f 1/m (track a/b); full scale A %.4f B %.4f; "
              "kappa_w %.4f kappa_r %.4f; y_w %.2f mm; angle %.4f rad\n",
              c.A_per_m, c.B_per_m, t.B_per_m, c.full_scale_A_per_m, c.full_scale_B_per_m,
              c.full_scale_wheel_curvature_per_m, c.full_scale_rail_curvature_per_m, c.wheel_profile_y_m * 1e3,
              c.contact_angle_rad);
}

// FASTSIM at a small creepage (full adhesion) has the slope of Kalker's linear theory, G a b C11 (paper 000 eq. 22),
// to its discretisation accuracy (centre-exact marching: exact in adhesion, docs/physics-reference.md §2.4), and the
// slope scales with N^(2/3) (a, b ~ N^(1/3) at a fixed a/b).
TEST(RollerRigAdhesion, FastsimInitialSlopeIsKalkersLinearTheory) {
  const RollerRigAdhesionOptions o;
  const RollerRigCurvatures c = RollerRigCentredCurvatures(o);
  const double V = RollerRigRollingSpeed(1000.0, o.roller_radius_m);
  for (double kg : {37.0, 42.0, 47.0}) {
    const RollerRigLinearContact lin = RollerRigLinearTheory(c, kg * o.gravity_m_per_s2, o.material);
    const double xi = 1e-7;
    const double mu = RollerRigTractionCoefficient(lin, o.material, FrictionLaw::Constant(0.4), 1.0, xi, V, 30);
    const double slope = mu * lin.normal_force_N / xi;
    EXPECT_NEAR(slope / lin.linear_slope_N, 1.0, 2e-3) << kg << " kg";
    // slope reduction k multiplies the slope by k
    const double mu_k = RollerRigTractionCoefficient(lin, o.material, FrictionLaw::Constant(0.4), 0.1, xi, V, 30);
    EXPECT_NEAR(mu_k / mu, 0.1, 1e-6);
    std::printf("%.0f kg: N %.1f N, a %.4f mm, b %.4f mm, a/b %.4f, p0 %.0f MPa, C11 %.4f, G a b C11 %.0f N, FASTSIM %.0f N\n",
                kg, lin.normal_force_N, lin.hertz.a_m * 1e3, lin.hertz.b_m * 1e3, lin.hertz.a_over_b,
                lin.hertz.p0_Pa * 1e-6, lin.c11, lin.linear_slope_N, slope);
  }
  const double s37 = RollerRigLinearTheory(c, 37.0 * 9.81, o.material).linear_slope_N;
  const double s47 = RollerRigLinearTheory(c, 47.0 * 9.81, o.material).linear_slope_N;
  EXPECT_NEAR(s47 / s37, std::pow(47.0 / 37.0, 2.0 / 3.0), 1e-9);
}

}  // namespace
}  // namespace conforma

namespace conforma {
namespace {

// The identification recovers a known law: model max and steady values generated from a law (with k from the
// slopes) are fitted back by the shared-law fit (3 parameters from 4 tests x 2 numbers) to the law's parameters.
TEST(RollerRigAdhesionFit, SharedLawFitRecoversAKnownLaw) {
  RollerRigAdhesionOptions rig;
  rig.fastsim_elements = 16;  // coarse mesh: the same model generates and fits the data
  RollerRigFitOptions fit;
  fit.peak_grid_points = 24;
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  RollerRigLaw truth;
  truth.mu_static = 0.55, truth.sliding_ratio = 0.65, truth.decay_s_per_m = 1.2;
  std::vector<RollerRigAdhesionTest> tests;
  const double rpm[] = {1000, 700, 358, 358}, kg[] = {37, 37, 42, 47}, slope[] = {8700, 7960, 12100, 18000};
  for (int i = 0; i < 4; ++i) {
    RollerRigAdhesionTest t;
    t.test = i + 1, t.reference_speed_rpm = rpm[i], t.wheel_load_kg = kg[i], t.initial_slope_N = slope[i];
    t.condition = "dry", t.max_adhesion = 1.0, t.steady_adhesion = 1.0;
    const RollerRigTestModel m = EvaluateRollerRigTest(t, rig, c, truth, fit);
    t.max_adhesion = m.model_max, t.steady_adhesion = m.model_steady;
    EXPECT_GT(m.model_max, m.model_steady);               // a falling law: a peak above the steady value
    EXPECT_LT(m.model_max, truth.mu_static);              // below the static coefficient
    EXPECT_GT(m.model_steady, truth.mu_static * truth.sliding_ratio);  // above mu_inf at a finite slip
    tests.push_back(t);
  }
  // higher speed -> more slip velocity at the same creepage -> lower steady value (paper 000 §5.1, dry)
  EXPECT_LT(tests[0].steady_adhesion, tests[1].steady_adhesion);
  const RollerRigFit f = FitRollerRigSharedLaw(tests, rig, fit);
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.law.mu_static, truth.mu_static, 2e-3);
  EXPECT_NEAR(f.law.sliding_ratio, truth.sliding_ratio, 2e-3);
  EXPECT_NEAR(f.law.decay_s_per_m, truth.decay_s_per_m, 2e-2);
  EXPECT_LT(f.max_abs_error_percent, 0.05);
}

// The per-test identification reproduces the measured max and steady of Table 6 test 1 (2 parameters, 2 numbers).
TEST(RollerRigAdhesionFit, PerTestFitReproducesTable6Test1) {
  RollerRigAdhesionOptions rig;
  rig.fastsim_elements = 16;
  RollerRigFitOptions fit;
  fit.peak_grid_points = 24;
  const auto tests = ReadRollerRigAdhesionTable(kTable);
  const RollerRigFit f = FitRollerRigTestLaw(tests[0], 1.0, rig, fit);
  EXPECT_TRUE(f.converged);
  EXPECT_LT(f.max_abs_error_percent, 0.01);
  EXPECT_GT(f.law.mu_static, tests[0].max_adhesion);  // the static level lies above the measured peak
  EXPECT_NEAR(f.tests[0].slope_reduction * f.tests[0].linear.linear_slope_N, tests[0].initial_slope_N, 1e-6);
}

}  // namespace
}  // namespace conforma
