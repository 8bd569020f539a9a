// `conforma bench` machinery (benchmark_cases.hpp): the per-model patch solve against analytic solutions, the exact
// reference (BEM + Kalker's exact steady rolling) against Hertz, the linear theory and full slip, the bench run on a
// near-Hertzian groove against its reference, and the fixed case set on shared data.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kalker.hpp"
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
  // the exact reference on the same strips reproduces Hertz (docs/physics-reference.md §10; 0.2 mm elements)
  const BenchReference ref = SolveBenchReference(c);
  EXPECT_TRUE(ref.converged) << ref.status();
  EXPECT_EQ(ref.status(), "converged");
  EXPECT_NEAR(ref.fn_N, c.normal_load_N, 1e-6 * c.normal_load_N);
  EXPECT_NEAR(ref.pmax_Pa / h.p0_Pa, 1.0, 0.03);
  EXPECT_NEAR(ref.area_m2 / (M_PI * h.a_m * h.b_m), 1.0, 0.06);
  EXPECT_NEAR(ref.approach_m / h.approach_m, 1.0, 0.02);
  EXPECT_FALSE(ref.contact_at_grid_edge);
  // Fn at the reference's approach: Hertz's N(delta) within the BEM's discretisation error
  PatchSolveOptions o;
  o.model = ContactModel::Hertz;
  EXPECT_NEAR(NormalForceAtApproach(c, o, ref.approach_m) / c.normal_load_N, 1.0, 0.04);
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

TEST(BenchCases, ExactReferenceMeetsLinearTheoryAndFullSlip) {
  BenchCase c = HertzianCase();
  const HertzResult h = SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, c.normal_load_N, c.material);
  const double mu_n = c.friction_coefficient * c.normal_load_N;
  // 1. Linear theory (creepage 1e-5, adhesion almost everywhere): F_x = -G a b C11 xi (kalker.hpp). The exact solver
  //    is first order in the element size (docs/physics-reference.md §14.4: +0.6 ... +1.8 % at 80 x 80 elements over
  //    the Hertz rectangle); here the contact spans about 37 x 25 elements of 0.2 mm, hence up to about 4 %.
  //    FASTSIM (the hertz model) takes its flexibility from C11, so it meets the same number, within the same bound.
  c.creepages = {1e-5, 0.0, 0.0};
  const BenchReference linear = SolveBenchReference(c);
  ASSERT_TRUE(linear.converged) << linear.status();
  EXPECT_GT(linear.tangential_iterations, 0);
  EXPECT_LT(linear.tangential_residual, 1e-5);  // ExactTangentialOptions' default tolerance
  const CreepCoefficients k = KalkerCoefficients(h.a_m / h.b_m, c.material.poisson_ratio);
  const double fx_linear = -c.material.shear_modulus_Pa * h.a_m * h.b_m * k.c11 * 1e-5;
  EXPECT_NEAR(linear.fx_N / fx_linear, 1.0, 0.04);
  EXPECT_NEAR(linear.fy_N, 0.0, 1e-4 * std::fabs(linear.fx_N));  // symmetric patch, pure longitudinal creepage
  PatchSolveOptions o;
  o.model = ContactModel::Hertz;
  EXPECT_NEAR(SolveBenchCase(c, o).fx_N / linear.fx_N, 1.0, 0.04);
  // 2. Full slip (creepage 0.05, about 20 times saturation): |F_t| = mu N, and the wear index W = mu sum p |s| dA
  //    = mu N |xi| up to the elastic part of the slip, whose p-weighted integral vanishes (as for FASTSIM, see
  //    WearIndexIsTractionTimesSlipAndFullSlipGivesMuN): within 1 %.
  c.creepages = {0.05, 0.0, 0.0};
  const BenchReference slip = SolveBenchReference(c);
  ASSERT_TRUE(slip.converged) << slip.status();
  EXPECT_EQ(slip.tangential_status, "full_slip");
  EXPECT_NEAR(std::hypot(slip.fx_N, slip.fy_N) / mu_n, 1.0, 1e-4);
  EXPECT_LT(slip.fx_N, 0.0);
  EXPECT_NEAR(slip.wear_index_N / (mu_n * 0.05), 1.0, 0.01);
  // the bench's errors of a FASTSIM model against it: the force exactly (both saturate), the wear index within 1 %
  o.model = ContactModel::Conformal;
  const BenchPatchResult s = SolveBenchCase(c, o);
  EXPECT_NEAR(s.fx_N / slip.fx_N, 1.0, 1e-3);
  EXPECT_NEAR(s.wear_index_N / slip.wear_index_N, 1.0, 0.01);
}

TEST(BenchCases, FastModelsAgainstTheExactReferenceOnTheShallowestGroove) {
  // groove R 10.25 mm, wheel R 10 mm (alpha_c about 32 deg): the least conformal groove, nearly Hertzian
  const BenchCase c = MakeGrooveBenchCases({10.25e-3}).front();
  BenchOptions options;
  options.models = {ContactModel::Hertz, ContactModel::Conformal};
  options.grids = {BenchGrid{31, 30}};
  options.conformal_eps055 = false;
  options.min_time_per_measurement_s = 0.0;
  std::vector<BenchReference> refs;
  const std::vector<BenchRow> rows = RunBench({c}, options, &refs);
  ASSERT_EQ(rows.size(), 2u);
  ASSERT_EQ(refs.size(), 1u);
  const BenchReference& ref = refs.front();
  EXPECT_EQ(ref.status(), "converged");
  EXPECT_GT(ref.tangential_iterations, 0);
  EXPECT_LT(ref.tangential_residual, 1e-5);
  EXPECT_NEAR(ref.fn_N, c.normal_load_N, 1e-6 * c.normal_load_N);
  EXPECT_FALSE(ref.contact_at_grid_edge);
  EXPECT_GT(ref.time_s, 0.0);
  // creepages (1e-3, 0.5e-3, 0.2 /m): partial slip with spin; the force opposes the creepage
  EXPECT_EQ(ref.tangential_status, "ok");
  EXPECT_LT(ref.fx_N, 0.0);
  EXPECT_LT(ref.fy_N, 0.0);
  for (const BenchRow& r : rows) {
    EXPECT_EQ(r.reference_status, "converged") << r.model;
    for (double e : {r.err_pmax, r.err_area, r.err_fn, r.err_fx, r.err_fy, r.err_wear})
      EXPECT_TRUE(std::isfinite(e)) << r.model;
    // FASTSIM against Kalker's exact theory on a Hertzian contact: within 5-8 % for creepage alone, 10-20 % with
    // spin (docs/physics-reference.md §2.5); the creepages here are mostly longitudinal/lateral with a moderate spin:
    // 10 % of |F_t| per component.
    EXPECT_LT(std::fabs(r.err_fx), 0.10) << r.model;
    EXPECT_LT(std::fabs(r.err_fy), 0.10) << r.model;
    EXPECT_GT(r.time_us, 0.0);
  }
}

TEST(BenchCases, FixedCaseSetCoversEveryFamily) {
  const std::vector<BenchCase> cases = MakeBenchCases(CONFORMA_SHARED_DATA);
  std::set<std::string> families;
  int flange_root = 0, mbench = 0, flange_flank = 0, gauge_corner = 0, gauge_face = 0;
  for (const BenchCase& c : cases) {
    families.insert(c.family);
    flange_root += c.family == "flange_root";
    mbench += c.family == "mbench";
    // issue 15: the right wheel on its flange flank (contact angle above 45 deg) and the worn gauge corner (above 25 deg)
    flange_flank += c.family == "flange" && c.patch.contact_angle_rad > M_PI / 4;
    gauge_corner += c.family == "gauge_corner";
    gauge_face += c.family == "gauge_corner" && c.patch.contact_angle_rad > 25 * M_PI / 180;
    EXPECT_GT(c.normal_load_N, 0.0) << c.name;
    EXPECT_GT(c.hertz_A_per_m, 0.0) << c.name;
    EXPECT_GT(c.patch.strips(), 3u) << c.name;
  }
  EXPECT_EQ(families,
            (std::set<std::string>{"mbench", "groove", "worn", "flange_root", "flange", "gauge_corner"}));
  EXPECT_GE(flange_flank, 4);   // y_ws = 7 ... 10 mm: one merged patch on the flange
  // tread at y = 15.0, tread and gauge corner at 15.4 and 15.5 mm; at the roll 0 (15.5 mm) tread, gauge
  // corner and flange face (74 deg)
  EXPECT_EQ(gauge_corner, 8);
  EXPECT_EQ(gauge_face, 4);
  EXPECT_GE(mbench, 21);        // every Manchester case has at least its tread patch
  EXPECT_EQ(flange_root, 2);    // two separate regions at the flange root
}

}  // namespace
}  // namespace conforma
