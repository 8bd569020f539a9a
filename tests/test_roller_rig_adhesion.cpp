// test-links: validation
// Roller-rig adhesion tests of paper 000 (Table 6): the data file, the rig contact at the centred position, Kalker's
// linear theory against FASTSIM's initial slope, and the friction-law fit (docs/physics-reference.md §7.5).
#include <gtest/gtest.h>

#include <array>
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

// Table 6's four speeds and loads (per condition) with the given measured slopes; max and steady adhesion generated
// by the model from a known law.
std::vector<RollerRigAdhesionTest> SyntheticTests(const RollerRigLaw& truth, const RollerRigAdhesionOptions& rig,
                                                  const RollerRigFitOptions& fit, const char* condition = "wet",
                                                  const std::array<double, 4>& slope = {8380, 7665, 12038, 17670}) {
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  std::vector<RollerRigAdhesionTest> tests;
  const double rpm[] = {1000, 700, 358, 358}, kg[] = {37, 37, 42, 47};
  for (int i = 0; i < 4; ++i) {
    RollerRigAdhesionTest t;
    t.test = i + 1, t.reference_speed_rpm = rpm[i], t.wheel_load_kg = kg[i], t.initial_slope_N = slope[i];
    t.condition = condition, t.max_adhesion = 1.0, t.steady_adhesion = 1.0;
    const RollerRigTestModel m = EvaluateRollerRigTest(t, rig, c, truth, fit);
    t.max_adhesion = m.model_max, t.steady_adhesion = m.model_steady;
    tests.push_back(t);
  }
  return tests;
}

// The identification recovers a known law: model max and steady values generated from a law (with k from the
// slopes) are fitted back by the shared-law fit (3 parameters from 4 tests x 2 numbers) to the law's parameters.
TEST(RollerRigAdhesionFit, SharedLawFitRecoversAKnownLaw) {
  RollerRigAdhesionOptions rig;
  rig.fastsim_elements = 16;  // coarse mesh: the same model generates and fits the data
  RollerRigFitOptions fit;
  fit.peak_grid_points = 24;
  RollerRigLaw truth;
  truth.mu_static = 0.55, truth.sliding_ratio = 0.65, truth.decay_s_per_m = 1.2;
  const std::vector<RollerRigAdhesionTest> tests = SyntheticTests(truth, rig, fit, "dry", {8700, 7960, 12100, 18000});
  for (const RollerRigAdhesionTest& t : tests) {
    EXPECT_GT(t.max_adhesion, t.steady_adhesion);               // a falling law: a peak above the steady value
    EXPECT_LT(t.max_adhesion, truth.mu_static);                 // below the static coefficient
    EXPECT_GT(t.steady_adhesion, truth.mu_static * truth.sliding_ratio);  // above mu_inf at a finite slip
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

#include "conforma/validation/roller_rig_polach.hpp"

namespace conforma {
namespace {

// Polach's analytic creep force (roller_rig_polach.hpp): initial slope (k_A + k_S)/2 G a b C11, saturation at mu for
// xi -> infinity, and the 1999 form (k_A = k_S = 1) peaks at mu only asymptotically (monotone curve).
TEST(RollerRigPolach, SlopeSaturationAndMonotonicity) {
  const double slope = 80000.0, N = 400.0, mu = 0.3;
  for (double kA : {1.0, 0.4}) {
    const double kS = 0.25 * kA;
    const double xi = 1e-9;
    EXPECT_NEAR(PolachTractionCoefficient(slope, N, kA, kS, mu, xi) * N / xi, 0.5 * (kA + kS) * slope,
                1e-6 * slope);
    EXPECT_NEAR(PolachTractionCoefficient(slope, N, kA, kS, mu, 1e6), mu, 1e-4);
  }
  double prev = 0.0;
  for (double xi = 1e-4; xi < 1.0; xi *= 1.5) {
    const double f = PolachTractionCoefficient(slope, N, 1.0, 1.0, mu, xi);
    EXPECT_GT(f, prev);
    EXPECT_LT(f, mu);
    prev = f;
  }
  // k_S << k_A: the adhesion term peaks at k_A eps = 1 and the curve has a local maximum there
  const double kA = 1.0, kS = 0.05, eps_peak = 1.0 / kA;
  const double xi_peak = eps_peak * 4.0 * N * mu / (3.14159265358979323846 * slope);
  const double f_peak = PolachTractionCoefficient(slope, N, kA, kS, mu, xi_peak);
  EXPECT_GT(f_peak, PolachTractionCoefficient(slope, N, kA, kS, mu, 3.0 * xi_peak));
  EXPECT_THROW(PolachTractionCoefficient(slope, N, 0.0, kS, mu, 0.01), InputError);
}

// The static level of the speed-dependent variants: mu_s at V_ref, the published or fitted shape elsewhere.
TEST(RollerRigAdhesionFit, SpeedDependentStaticLevel) {
  RollerRigLaw l;
  l.mu_static = 0.3;
  const double Vr = kRollerRigReferenceSpeed;
  EXPECT_DOUBLE_EQ(l.StaticLevel(3.0), 0.3);  // slip_velocity: no rolling-speed dependence
  l.variant = RollerRigLawVariant::SpeedPower, l.speed_exponent = 0.5;
  EXPECT_NEAR(l.StaticLevel(Vr), 0.3, 1e-15);
  EXPECT_NEAR(l.StaticLevel(4.0 * Vr), 0.15, 1e-12);
  l.variant = RollerRigLawVariant::SpeedHyperbolic, l.speed_scale_m_per_s = Vr;
  EXPECT_NEAR(l.StaticLevel(3.0 * Vr), 0.15, 1e-12);
  l.variant = RollerRigLawVariant::CurtiusKniffler;
  // Curtius-Kniffler at 0 and 100 km/h relative to V_ref = 36 km/h: (0.161 + 7.5/44) / (0.161 + 7.5/80)
  EXPECT_NEAR(l.StaticLevel(100.0 / 3.6) / l.StaticLevel(1e-9),
              (0.161 + 7.5 / 144.0) / (0.161 + 7.5 / 44.0), 1e-9);
  EXPECT_EQ(ParseRollerRigLawVariant("speed_power"), RollerRigLawVariant::SpeedPower);
  EXPECT_THROW(ParseRollerRigLawVariant("speed"), InputError);
  for (RollerRigLawVariant v : AllRollerRigLawVariants()) EXPECT_EQ(ParseRollerRigLawVariant(to_string(v)), v);
}

// The rolling-speed-dependent law (4 parameters from 4 tests x 2 numbers, FASTSIM) is recovered from data it
// generated, including the speed exponent; the peaks fall with the rolling speed as the static level does.
TEST(RollerRigAdhesionFit, SpeedPowerFitRecoversAKnownLaw) {
  RollerRigAdhesionOptions rig;
  rig.fastsim_elements = 12;
  RollerRigFitOptions fit;
  fit.peak_grid_points = 20;
  fit.variant = RollerRigLawVariant::SpeedPower;
  RollerRigLaw truth;
  truth.variant = RollerRigLawVariant::SpeedPower;
  truth.mu_static = 0.28, truth.sliding_ratio = 0.75, truth.decay_s_per_m = 0.8, truth.speed_exponent = 0.35;
  const auto tests = SyntheticTests(truth, rig, fit);
  EXPECT_LT(tests[0].max_adhesion, tests[1].max_adhesion);  // 1000 rpm below 700 rpm
  EXPECT_LT(tests[1].max_adhesion, tests[2].max_adhesion);  // 700 rpm below 358 rpm
  const RollerRigFit f = FitRollerRigSharedLaw(tests, rig, fit);
  EXPECT_TRUE(f.converged);
  EXPECT_EQ(f.parameters, 4);
  EXPECT_EQ(f.data_points, 8);
  EXPECT_NEAR(f.law.mu_static, truth.mu_static, 2e-3);
  EXPECT_NEAR(f.law.speed_exponent, truth.speed_exponent, 5e-3);
  EXPECT_NEAR(f.law.sliding_ratio, truth.sliding_ratio, 5e-3);
  EXPECT_NEAR(f.law.decay_s_per_m, truth.decay_s_per_m, 5e-2);
  EXPECT_LT(f.max_abs_error_percent, 0.05);
  EXPECT_EQ(f.within_5_percent, 8);
}

// The maximum up to the steady creepage (peak_before_steady): a constant friction coefficient (A = 1) gives a curve
// that rises monotonically to mu, so its maximum up to xi_s is the steady value itself; the falling law of the same
// mu_s has an interior peak above its steady value, the same with either definition of the maximum.
TEST(RollerRigAdhesionFit, MaximumBeforeSteadyCreepage) {
  RollerRigAdhesionOptions rig;
  rig.fastsim_elements = 16;
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  RollerRigFitOptions fit;
  fit.peak_grid_points = 16;
  fit.peak_before_steady = true;
  RollerRigAdhesionTest t;
  t.test = 1, t.reference_speed_rpm = 700, t.wheel_load_kg = 37, t.initial_slope_N = 7960, t.condition = "dry";
  t.max_adhesion = 0.4, t.steady_adhesion = 0.3;
  RollerRigLaw constant;
  constant.mu_static = 0.4, constant.sliding_ratio = 1.0;
  const RollerRigTestModel m = EvaluateRollerRigTest(t, rig, c, constant, fit);
  EXPECT_DOUBLE_EQ(m.model_max, m.model_steady);
  EXPECT_DOUBLE_EQ(m.peak_creepage, fit.steady_creepage);
  EXPECT_LT(m.model_steady, 0.4);
  RollerRigLaw falling = constant;
  falling.sliding_ratio = 0.5, falling.decay_s_per_m = 2.0;
  const RollerRigTestModel f = EvaluateRollerRigTest(t, rig, c, falling, fit);
  EXPECT_LT(f.peak_creepage, fit.steady_creepage);
  EXPECT_GT(f.model_max, f.model_steady);
  fit.peak_before_steady = false;
  EXPECT_NEAR(EvaluateRollerRigTest(t, rig, c, falling, fit).model_max, f.model_max, 1e-9);
}

// Polach's extended model with the steady creepage fitted (5 parameters for 8 numbers): k_S/k_A and the steady
// creepage of the synthetic data are recovered.
TEST(RollerRigAdhesionFit, PolachExtendedFitRecoversSlipAreaRatioAndSteadyCreepage) {
  RollerRigAdhesionOptions rig;
  RollerRigFitOptions gen;
  gen.steady_creepage = 0.07;
  gen.variant = RollerRigLawVariant::PolachExtended;
  RollerRigLaw truth;
  truth.variant = RollerRigLawVariant::PolachExtended;
  truth.mu_static = 0.4, truth.sliding_ratio = 0.5, truth.decay_s_per_m = 0.6, truth.slip_area_ratio = 0.3;
  const auto tests = SyntheticTests(truth, rig, gen);
  RollerRigFitOptions fit = gen;
  fit.steady_creepage = 0.1;  // the start; fitted
  fit.fit_steady_creepage = true;
  const RollerRigFit f = FitRollerRigSharedLaw(tests, rig, fit);
  EXPECT_TRUE(f.converged);
  EXPECT_EQ(f.parameters, 5);
  EXPECT_NEAR(f.steady_creepage, 0.07, 1e-3);
  EXPECT_NEAR(f.law.slip_area_ratio, 0.3, 5e-3);
  EXPECT_NEAR(f.law.mu_static, 0.4, 2e-3);
  EXPECT_LT(f.max_abs_error_percent, 0.05);
}

}  // namespace
}  // namespace conforma
