// `conforma bench` machinery (benchmark_cases.hpp): the per-model patch solve against analytic solutions, the
// reference BEM against Hertz, grid convergence of the tangential problem, and the fixed case set on shared data.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/hertz.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

// A Hertzian (elliptic, flat) patch with its Hertz curvatures: every model must give Hertz's normal solution.
BenchCase HertzianCase() {
  BenchCase c;
  c.name = "hertzian";
  c.family = "test";
  const Material material;
  const kp_test::Curvatures k = kp_test::CurvaturesForRatio(1.5, 5.0, material);
  c.hertz_A_per_m = k.A;
  c.hertz_B_per_m = k.B;
  c.patch = kp_test::HertzianPatch(k.A, k.B, 12e-3, 241);
  c.normal_load_N = 20e3;
  c.creepages = {1e-3, 0.0, 0.0};
  return c;
}

TEST(BenchCases, EveryModelReproducesHertzOnAnEllipticPatch) {
  const BenchCase c = HertzianCase();
  const HertzResult h = SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, c.normal_load_N, c.material);
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kpec, ContactModel::Conformal}) {
    PatchSolveOptions o;
    o.model = m;
    const BenchPatchResult s = SolveBenchCase(c, o);
    ASSERT_TRUE(s.in_contact) << to_string(m);
    EXPECT_NEAR(s.fn_N, c.normal_load_N, 1e-5 * c.normal_load_N) << to_string(m);
    // Hertz, KPEC and the conformal model (KPEC's variable virtual penetration, exact for elliptic patches,
    // docs/physics-reference.md §3.3, with the Blanco influence that equals the half-space on a flat patch) to
    // 1 % / 2 %
    const double tol_p = 0.01, tol_a = 0.02;
    EXPECT_NEAR(s.pmax_Pa / h.p0_Pa, 1.0, tol_p) << to_string(m);
    EXPECT_NEAR(s.area_m2 / (M_PI * h.a_m * h.b_m), 1.0, tol_a) << to_string(m);
    EXPECT_NEAR(s.alpha_c_deg, 0.0, 1e-9) << to_string(m);  // a flat patch is not conformal
    // pure longitudinal creepage on a symmetric patch: no lateral force, the force opposes the creepage
    EXPECT_LT(s.fx_N, 0.0) << to_string(m);
    EXPECT_NEAR(s.fy_N, 0.0, 1e-6 * std::fabs(s.fx_N)) << to_string(m);
    EXPECT_GT(s.wear_index_N, 0.0) << to_string(m);
  }
  // the reference BEM on the same strips reproduces Hertz (docs/physics-reference.md §10)
  const BemReferenceSolution bem = SolveBenchReference(c);  // 0.2 mm elements
  EXPECT_EQ(bem.status, "converged");
  EXPECT_NEAR(bem.fn_N, c.normal_load_N, 1e-6 * c.normal_load_N);
  EXPECT_NEAR(bem.pmax_Pa / h.p0_Pa, 1.0, 0.03);
  EXPECT_NEAR(bem.area_m2 / (M_PI * h.a_m * h.b_m), 1.0, 0.06);
  EXPECT_NEAR(bem.approach_m / h.approach_m, 1.0, 0.02);
  // Fn at the BEM's approach: Hertz's N(delta) within the BEM's discretisation error
  PatchSolveOptions o;
  o.model = ContactModel::Hertz;
  EXPECT_NEAR(NormalForceAtApproach(c, o, bem.approach_m) / c.normal_load_N, 1.0, 0.04);
}

TEST(BenchCases, WearIndexIsTractionTimesSlipAndFullSlipGivesMuN) {
  BenchCase c = HertzianCase();
  c.creepages = {0.05, 0.0, 0.0};  // far beyond saturation: full slip, |F_t| = mu N
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Conformal}) {
    // In full slip p_t = mu p (-1, 0) and s = xi - L dp_t/dx, so W = mu N |xi| - mu^2 L int p dp/dx dx dy, and the
    // integral vanishes (p = 0 at both edges). FASTSIM's discrete sum leaves (L / dx) sum (dp)^2 / 2 > 0: first
    // order in the element size, so W approaches mu N |xi| from below as 1/n.
    double error[2];
    const int elements[2] = {10, 50};
    for (int k = 0; k < 2; ++k) {
      PatchSolveOptions o;
      o.model = m;
      o.fastsim_elements = elements[k];
      const BenchPatchResult s = SolveBenchCase(c, o);
      EXPECT_NEAR(std::hypot(s.fx_N, s.fy_N) / (c.friction_coefficient * s.fn_N), 1.0, 1e-3) << to_string(m);
      error[k] = 1.0 - s.wear_index_N / (c.friction_coefficient * s.fn_N * 0.05);
      EXPECT_GT(error[k], 0.0) << to_string(m);
    }
    EXPECT_LT(error[1], 0.004) << to_string(m);
    EXPECT_NEAR(error[0] / error[1], 5.0, 2.0) << to_string(m);  // first order: 50 / 10
  }
}

TEST(BenchCases, TangentialErrorShrinksWithTheGrid) {
  const BenchCase c = MakeGrooveBenchCases({10.25e-3}).front();
  BenchOptions options;
  options.models = {ContactModel::Conformal};
  options.conformal_eps055 = false;
  options.min_time_per_measurement_s = 0.0;
  const std::vector<BenchRow> rows = RunBench({c}, options);
  ASSERT_EQ(rows.size(), options.grids.size());
  const BenchRow &coarse = rows.front(), &fine = rows.back();
  EXPECT_LT(std::hypot(fine.err_fx, fine.err_fy), std::hypot(coarse.err_fx, coarse.err_fy));
  EXPECT_LT(std::fabs(fine.err_wear), std::fabs(coarse.err_wear));
  EXPECT_LT(std::hypot(fine.err_fx, fine.err_fy), 0.02);
  // the groove is conformal: alpha_c well above paper 003's 18 degrees
  EXPECT_GT(fine.alpha_c_deg, 18.0);
  for (const BenchRow& r : rows) EXPECT_GT(r.time_us, 0.0);
}

TEST(BenchCases, FixedCaseSetCoversEveryFamily) {
  const std::vector<BenchCase> cases = MakeBenchCases(CONFORMA_SHARED_DATA);
  std::set<std::string> families;
  int flange_root = 0, mbench = 0;
  for (const BenchCase& c : cases) {
    families.insert(c.family);
    flange_root += c.family == "flange_root";
    mbench += c.family == "mbench";
    EXPECT_GT(c.normal_load_N, 0.0) << c.name;
    EXPECT_GT(c.hertz_A_per_m, 0.0) << c.name;
    EXPECT_GT(c.patch.strips(), 3u) << c.name;
  }
  EXPECT_EQ(families, (std::set<std::string>{"mbench", "groove", "worn", "flange_root"}));
  EXPECT_GE(mbench, 21);        // every Manchester case has at least its tread patch
  EXPECT_EQ(flange_root, 2);    // two separate regions at the flange root
}

}  // namespace
}  // namespace conforma
