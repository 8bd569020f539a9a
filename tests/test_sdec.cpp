// SDEC reduction (paper 003 §4.2): elliptic patches give the ellipse, KPEC on a Hertzian gap gives Hertz a, b,
// a double half-ellipse keeps its asymmetry; the KP SDEC drives FASTSIM on the real KP patch.
// test-links: fastsim_ext  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/sdec.hpp"
#include "conforma/validation/analytic_patches.hpp"

using namespace conforma;

namespace {

// Two half-ellipses sharing a: b_neg towards -s, b_pos towards +s, n strips of equal width over [-b_neg, b_pos].
std::vector<SdecStrip> DoubleHalfEllipse(double a, double b_neg, double b_pos, int n) {
  std::vector<SdecStrip> strips;
  const double ds = (b_neg + b_pos) / n;
  for (int j = 0; j < n; ++j) {
    const double s = -b_neg + (j + 0.5) * ds;
    const double b = s < 0.0 ? b_neg : b_pos;
    strips.push_back({s, ds, 1e-4, a * std::sqrt(1.0 - (s / b) * (s / b))});
  }
  return strips;
}

}  // namespace

// An exactly elliptic strip set: SDEC a, b = the ellipse's within 1 %, symmetric, Kalker C_ij at a/b.
TEST(Sdec, EllipticStripsGiveTheEllipse) {
  const Material steel;
  for (double ab : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double a = 5e-3 * std::sqrt(ab), b = 5e-3 / std::sqrt(ab);
    const SdecResult r = ReduceToSdec(DoubleHalfEllipse(a, b, b, 41), steel);
    ASSERT_EQ(r.status, SdecStatus::Ok);
    EXPECT_NEAR(r.a_m, a, 0.01 * a) << ab;
    EXPECT_NEAR(r.b_m, b, 0.01 * b) << ab;
    EXPECT_NEAR(r.area_m2, M_PI * a * b, 0.01 * M_PI * a * b);
    EXPECT_NEAR(r.asymmetry, 0.0, 1e-3);
    EXPECT_NEAR(r.w1_m, r.w2_m, 1e-3 * b);
    EXPECT_NEAR(M_PI * r.a_m * r.b_m, r.area_m2, 1e-12 * r.area_m2);          // area kept exactly
    EXPECT_NEAR(r.a_m / r.b_m, r.w3_m / (r.w1_m + r.w2_m), 1e-12 * r.a_m / r.b_m);  // length/width kept
    EXPECT_NEAR(r.coefficients.c11, KalkerCoefficients(r.a_m / r.b_m, steel.poisson_ratio).c11, 1e-12);
  }
}

// KPEC (exact for elliptic patches) and planar KP on a Hertzian gap: the SDEC of the solved patch reproduces
// Hertz a and b within 1 %.
TEST(Sdec, KpOnHertzianGapGivesHertzAxes) {
  const Material steel;
  for (double ratio : {0.4, 1.0, 2.5}) {
    const kp_test::Curvatures k = kp_test::CurvaturesForRatio(ratio, 6.0, steel);
    const HertzResult h = SolveHertzForLoad(k.A, k.B, 80e3, steel);
    const PatchGeometry patch = kp_test::HertzianPatch(k.A, k.B, 1.5 * h.b_m, 121);
    const KpResult kpec = SolveKikPiotrowskiForApproach(patch, h.approach_m, KpecOptions(steel));
    ASSERT_EQ(kpec.status, KpStatus::Ok);
    const SdecResult r = ReduceToSdec(kpec, steel);
    std::printf("a/b %.1f: KPEC SDEC a %+.3f %%, b %+.3f %% vs Hertz\n", ratio, 100 * (r.a_m / h.a_m - 1),
                100 * (r.b_m / h.b_m - 1));
    EXPECT_NEAR(r.a_m, h.a_m, 0.01 * h.a_m) << ratio;
    EXPECT_NEAR(r.b_m, h.b_m, 0.01 * h.b_m) << ratio;
    // Planar KP (eps = 0.55) is not elliptic-exact in size, but its patch shape is an ellipse: the SDEC keeps the
    // KP area and aspect ratio exactly.
    const KpResult kp = SolveKikPiotrowskiForApproach(patch, h.approach_m, PlanarKpOptions(steel));
    const SdecResult q = ReduceToSdec(kp, steel);
    EXPECT_NEAR(M_PI * q.a_m * q.b_m, kp.area_m2, 1e-9 * kp.area_m2);
    EXPECT_NEAR(q.asymmetry, 0.0, 0.02);
  }
}

// Asymmetric double half-ellipse: a, b = (b_neg + b_pos)/2, b_neg, b_pos and the centroid recovered.
TEST(Sdec, DoubleHalfEllipseKeepsAsymmetry) {
  const Material steel;
  const double a = 6e-3, b_neg = 2e-3, b_pos = 5e-3;
  // s* is located to a fraction of a strip (parabola vertex): 1 % on b_neg needs ds <~ b_neg / 50.
  const SdecResult r = ReduceToSdec(DoubleHalfEllipse(a, b_neg, b_pos, 200), steel);
  const double b = 0.5 * (b_neg + b_pos);
  EXPECT_NEAR(r.a_m, a, 0.01 * a);
  EXPECT_NEAR(r.b_m, b, 0.01 * b);
  EXPECT_NEAR(r.b_neg_m, b_neg, 0.01 * b_neg);
  EXPECT_NEAR(r.b_pos_m, b_pos, 0.01 * b_pos);
  EXPECT_NEAR(r.asymmetry, (b_pos - b_neg) / (2 * b), 0.01);
  EXPECT_NEAR(r.longest_strip_s_m, 0.0, 0.02 * b);
  // Centroid of the real patch (numerical) vs the SDEC formula.
  double first_moment = 0.0, area = 0.0;
  for (const SdecStrip& s : DoubleHalfEllipse(a, b_neg, b_pos, 2000)) {
    first_moment += s.s_m * 2 * s.half_length_m * s.ds_m;
    area += 2 * s.half_length_m * s.ds_m;
  }
  EXPECT_NEAR(r.centroid_s_m, first_moment / area, 0.02 * b);
  // Linear forces: a spin about the centroid gives no F_x; about another centre, the rigid slip there.
  const FastsimCreepages spin{0.0, 0.0, 1.0};
  EXPECT_NEAR(SdecLinearCreepForces(r, spin, r.centroid_s_m, steel.shear_modulus_Pa).fx_N, 0.0, 1e-9);
  EXPECT_GT(SdecLinearCreepForces(r, spin, 0.0, steel.shear_modulus_Pa).fx_N, 0.0);  // y_c > 0: xi_eff = -phi y_c
}

// `kp` model: FASTSIM with the SDEC flexibilities on the KPEC patch of a Hertzian gap = Kalker's linear theory
// within 2 % (KPEC pressure is Hertz's; the SDEC is the ellipse).
TEST(Sdec, FastsimOnKpPatchLinearTheory) {
  const Material steel;
  const kp_test::Curvatures k = kp_test::CurvaturesForRatio(1.5, 6.0, steel);
  const HertzResult h = SolveHertzForLoad(k.A, k.B, 80e3, steel);
  const PatchGeometry patch = kp_test::HertzianPatch(k.A, k.B, 1.5 * h.b_m, 121);
  const KpResult kpec = SolveKikPiotrowskiForApproach(patch, h.approach_m, KpecOptions(steel));
  const double G = steel.shear_modulus_Pa, c = std::sqrt(h.a_m * h.b_m);
  const CreepCoefficients C = KalkerCoefficients(h.a_m / h.b_m, steel.poisson_ratio);
  const double xi = 1e-3 * 0.3 * h.normal_force_N / (G * c * c * C.c11);
  const CurvedFastsimResult r =
      SolveFastsimOnKpPatch(kpec, {xi, 0.0, 0.0}, FrictionLaw::Constant(0.3), steel, CurvedFastsimOptions{});
  EXPECT_NEAR(r.fx_N / (-G * c * c * C.c11 * xi), 1.0, 0.02);
  EXPECT_NEAR(r.bound_load_N, kpec.fn_surface_N, 0.01 * kpec.fn_surface_N);
}

TEST(Sdec, BadInputAndNoContact) {
  const Material steel;
  EXPECT_EQ(ReduceToSdec(std::vector<SdecStrip>{}, steel).status, SdecStatus::NoContact);
  EXPECT_EQ(ReduceToSdec(std::vector<SdecStrip>{{0.0, 1e-3, 0.0, 0.0}}, steel).status, SdecStatus::NoContact);
  EXPECT_THROW(ReduceToSdec(std::vector<SdecStrip>{{0.0, 1e-3, 0.0, -1.0}}, steel), InputError);
  EXPECT_THROW(ReduceToSdec(std::vector<SdecStrip>{{std::nan(""), 1e-3, 0.0, 1e-3}}, steel), InputError);
}
