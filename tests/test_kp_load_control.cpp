// Load control of the KP solvers: the one load control (load_control.hpp) and the KP load-given mode.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/kik_piotrowski.hpp"
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

// The one load control (load_control.hpp) on an analytic carried load N = C (g + push)^1.5: the root is exact.
TEST(KpLoadControl, OneLoadControlFindsTheAnalyticPush) {
  const double C = 4.0e11, g = 2.0e-5, load = 8.0e4;
  int evaluations = 0;
  auto carried = [&](double push) {
    ++evaluations;
    const double x = std::max(g + push, 0.0);
    return C * x * std::sqrt(x);
  };
  const LoadControlResult r = SolveLoadControl(carried, load, g, 1e-12);
  ASSERT_EQ(r.status, LoadControlStatus::Ok);
  EXPECT_NEAR(g + r.push_m, std::pow(load / C, 2.0 / 3.0), 1e-12 * g);
  EXPECT_LE(std::fabs(r.residual_N), 1e-12 * load);
  // on N^(2/3), linear in the push for N ~ delta^1.5, false position lands on the root in one step
  int linear_steps = r.iterations;
  const LoadControlResult power = SolveLoadControl(carried, load, g, 1e-12, LoadResponse::HertzPower);
  ASSERT_EQ(power.status, LoadControlStatus::Ok);
  EXPECT_NEAR(g + power.push_m, std::pow(load / C, 2.0 / 3.0), 1e-12 * g);
  EXPECT_LE(std::fabs(power.residual_N), 1e-12 * load);
  EXPECT_LE(power.iterations, 2);
  EXPECT_LT(power.iterations, linear_steps);
  // a load the contact cannot carry (saturating N) is a status, not a number
  auto saturating = [&](double push) { return 0.5 * load * std::tanh(1e5 * std::max(push, 0.0)); };
  EXPECT_EQ(SolveLoadControl(saturating, load, g, 1e-10).status, LoadControlStatus::NoBracket);
}

// Load given on one KP patch reaches the load and is the approach-given solution at its approach.
TEST(KpLoadControl, LoadGivenIsTheApproachGivenSolutionAtItsApproach) {
  Material material;
  const PatchGeometry patch = kp_test::HertzianPatch(0.8, 1.6, 0.012, 81);
  KpLoadOptions options;
  options.kp = PlanarKpOptions(material);
  const KpResult by_load = SolveKikPiotrowskiForLoad(patch, 80.0e3, options);
  ASSERT_EQ(by_load.status, KpStatus::Ok);
  EXPECT_NEAR(by_load.fn_N, 80.0e3, options.relative_tolerance * 80.0e3);
  const KpResult again = SolveKikPiotrowskiForApproach(patch, by_load.approach_m, options.kp);
  EXPECT_EQ(again.fn_N, by_load.fn_N);
  EXPECT_EQ(again.pmax_Pa, by_load.pmax_Pa);
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
  KpLoadOptions options;
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
