// Strip collocation of the KP amplitudes (KpPressureRule::StripCollocation, docs/physics-reference.md §5.3), the
// conformal model's default since issue 15: Hertz on an elliptic patch, and issue 15's accuracy target against the
// exact model (BEM normal + Kalker's exact tangential) on a flange and a gauge-corner bench case, where the
// Kik-Piotrowski amplitude rule (kpec) misses p_max by 14-19 %.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/validation/analytic_patches.hpp"
#include "conforma/validation/benchmark_cases.hpp"

namespace conforma {
namespace {

// Hertz: on an elliptic patch every strip's Hertz pressure p0 sqrt(1 - y^2/b^2) satisfies every collocation equation,
// so the collocated amplitudes give Hertz's p_max and force at Hertz's approach (to the strip discretisation), for
// ellipses elongated either way, with all strips collocated and with the default 11 coarse strips.
TEST(KpCollocation, ReproducesHertzOnEllipticPatches) {
  const Material material;
  for (double ratio : {0.4, 1.0, 3.0}) {
    const kp_test::Curvatures k = kp_test::CurvaturesForRatio(ratio, 5.0, material);
    const PatchGeometry patch = kp_test::HertzianPatch(k.A, k.B, 12e-3, 241);
    const HertzResult h = SolveHertzForLoad(k.A, k.B, 20e3, material);
    ASSERT_EQ(h.status, HertzStatus::Ok);
    for (int coarse : {11, 31}) {
      KpOptions o = ConformalKpecOptions(material);
      ASSERT_EQ(o.pressure, KpPressureRule::StripCollocation);
      o.collocation_strips = coarse;
      const KpResult r = SolveKikPiotrowskiForApproach(patch, h.approach_m, o);
      ASSERT_EQ(r.status, KpStatus::Ok) << ratio;
      EXPECT_NEAR(r.pmax_Pa / h.p0_Pa, 1.0, 0.015) << "a/b " << ratio << ", " << coarse << " strips";
      EXPECT_NEAR(r.fn_N / 20e3, 1.0, 0.02) << "a/b " << ratio << ", " << coarse << " strips";
      EXPECT_NEAR(r.area_m2 / (M_PI * h.a_m * h.b_m), 1.0, 0.02) << "a/b " << ratio;
    }
  }
}

TEST(KpCollocation, RejectsTooFewCollocationStrips) {
  const kp_test::Curvatures k = kp_test::CurvaturesForRatio(1.0, 5.0, Material{});
  KpOptions o = ConformalKpecOptions(Material{});
  o.collocation_strips = 1;
  EXPECT_THROW(SolveKikPiotrowskiForApproach(kp_test::HertzianPatch(k.A, k.B, 12e-3, 241), 1e-5, o), InputError);
}

const BenchCase& FindCase(const std::vector<BenchCase>& cases, const std::string& name) {
  for (const BenchCase& c : cases)
    if (c.name == name) return c;
  throw InputError("bench case " + name + " not in the fixed case set");
}

struct Errors {
  double pmax, area, fx, fy, ft_ref;
};
Errors AgainstExact(const BenchCase& c, ContactModel model) {
  const BenchReference ref = SolveBenchReference(c);
  EXPECT_TRUE(ref.converged) << c.name << ": " << ref.status();
  PatchSolveOptions o;
  o.model = model;
  const BenchPatchResult s = SolveBenchCase(c, o);
  EXPECT_TRUE(s.in_contact) << c.name;
  const double ft = std::hypot(ref.fx_N, ref.fy_N);
  return {s.pmax_Pa / ref.pmax_Pa - 1.0, s.area_m2 / ref.area_m2 - 1.0, s.fx_N - ref.fx_N, s.fy_N - ref.fy_N, ft};
}

// Issue 15, item 3: the conformal model's p_max within 10 % and its area within 15 % of the exact model's
Errors ExpectPmaxAndAreaNearExact(const BenchCase& c) {
  const Errors e = AgainstExact(c, ContactModel::Conformal);
  EXPECT_LT(std::fabs(e.pmax), 0.10) << c.name;
  EXPECT_LT(std::fabs(e.area), 0.15) << c.name;
  return e;
}

// Issue 15, item 3, on a flange-flank case (S1002 / Manchester UIC60, right wheel, y_ws = 8 mm, 17 kN on the flange,
// full slip) and the flange-root/tread case at y_ws = 5 mm (partial slip): p_max within 10 %, area within 15 %,
// creep forces within 15 % of |F_t| or 150 N of the exact model.
TEST(KpCollocation, ConformalMeetsTheExactModelOnFlangeCases) {
  const std::vector<BenchCase> cases = MakeBenchCases(CONFORMA_SHARED_DATA);
  for (const char* name : {"flange_y08_p0", "flange_y05_p0"}) {
    const Errors e = ExpectPmaxAndAreaNearExact(FindCase(cases, name));
    const double creep_tolerance = std::max(0.15 * e.ft_ref, 150.0);
    EXPECT_LT(std::fabs(e.fx), creep_tolerance) << name;
    EXPECT_LT(std::fabs(e.fy), creep_tolerance) << name;
  }
}

// Issue 15, item 3, on the worn gauge corner (worn_high_mileage.prw on site_b_hr.prr, right wheel, 137 kN, y = 15.5 mm):
// both patches of the case, the 118 kN worn tread (kpec: p_max -19 %) and the 22 kN gauge corner (kpec: -9 %).
// The strip collocation brings p_max within 10 % and keeps the area within 15 % of the exact model; the
// Kik-Piotrowski amplitude rule (kpec, same area rule) misses the tread by more than 10 % (the reason for §5.3).
TEST(KpCollocation, ConformalMeetsTheExactModelOnTheWornGaugeCorner) {
  const std::vector<BenchCase> cases = MakeBenchCases(CONFORMA_SHARED_DATA);
  for (const char* name : {"gauge_corner_y15.5_p0", "gauge_corner_y15.5_p1"})
    ExpectPmaxAndAreaNearExact(FindCase(cases, name));
  const Errors kpec = AgainstExact(FindCase(cases, "gauge_corner_y15.5_p1"), ContactModel::Kpec);
  EXPECT_LT(kpec.pmax, -0.10);
}

}  // namespace
}  // namespace conforma

namespace conforma {

// The patch of a data file (header lines '#'; ds_m, an approach, strip count; per strip s, gap, A, r, alpha, x).
PatchGeometry ReadPatch(const std::string& name, double* approach) {
  std::ifstream in(std::string(CONFORMA_SOURCE_DIR) + "/tests/data/kp_worn_tread/" + name);
  EXPECT_TRUE(in.good()) << name;
  std::string line;
  while (in.peek() == '#') std::getline(in, line);
  PatchGeometry patch;
  size_t strips = 0;
  in >> patch.ds_m >> *approach >> strips;
  for (size_t k = 0; k < strips; ++k) {
    double s, gap, A, r, alpha, x;
    in >> s >> gap >> A >> r >> alpha >> x;
    patch.s_m.push_back(s);
    patch.gap_m.push_back(gap);
    patch.longitudinal_curvature_per_m.push_back(A);
    patch.wheel_radius_m.push_back(r);
    patch.alpha_rad.push_back(alpha);
    patch.x_offset_m.push_back(x);
  }
  EXPECT_TRUE(in.good()) << name;
  return patch;
}

// A worn tread's patch whose virtual interpenetration has two lobes with a steep edge between them
// (tests/data/kp_worn_tread/two_lobe_patch.txt, from the default scenario with the dynamic provider): the outermost
// coarse strip of the first lobe sits just inside that edge, where the virtual half-length c drops to nm while the
// required displacement does not. Its collocated amplitude went as 1/c and the ratio P/c the strips take from it as
// 1/c^2: within 2 nm of approach F_n jumped from 20 kN to 7e9 N (p_max 3e16 Pa), and the wheel's load control failed
// there. Its contact condition is now blended with KP's constant ratio P/c (the inward neighbour's), with a weight
// that vanishes with c (kCollocationEdgeBlend): the force is continuous and smooth.
// F_n over [approach - half_range, approach + half_range] in steps of `step` on a patch of tests/data/kp_worn_tread:
// continuous and rising (each step positive and within 3x the Hertzian 1.5 F/d), p_max below 3 GPa (about 2.1-2.4 GPa).
// allowed_drop: a fall of F_n per step tolerated, as a fraction of F_n (0: none).
void ExpectSmoothRisingForce(const char* name, double half_range, double step, double allowed_drop = 0.0) {
  const KpOptions o = ConformalKpecOptions(Material{});
  double approach = 0.0;
  const PatchGeometry patch = ReadPatch(name, &approach);
  ASSERT_GE(patch.s_m.size(), 98u) << name;
  double previous = 0.0, pmax = 0.0;
  const int n = static_cast<int>(std::lround(half_range / step));
  for (int i = -n; i <= n; ++i) {
    const double a = approach + i * step;
    const KpResult r = SolveKikPiotrowskiForApproach(patch, a, o);
    ASSERT_EQ(r.status, KpStatus::Ok) << name << " " << i;
    pmax = std::max(pmax, r.pmax_Pa);
    if (i > -n) {
      EXPECT_GT(r.fn_N - previous, -allowed_drop * r.fn_N) << name << " " << i;
      EXPECT_LT(r.fn_N - previous, 3.0 * 1.5 * r.fn_N / a * step) << name << " " << i;
    }
    previous = r.fn_N;
  }
  EXPECT_LT(pmax, 3e9) << name;
}

TEST(KpCollocation, CoarseStripAtASteepLobeEdgeKeepsTheForceBounded) {
  ExpectSmoothRisingForce("two_lobe_patch.txt", 40e-9, 2e-9);  // +-40 nm around the blow-up, 2 nm steps
}

// A second worn-tread patch whose edge strip's c passes 2 % of its lobe's largest: the earlier rule (no part below
// 2 %) made F_n jump by 7.5 % there (p_max 2.1 -> 7.0 GPa), as the strip re-entered with an inflated ratio P/c; the
// blended row (docs/physics-reference.md §5.3) keeps it continuous.
TEST(KpCollocation, ReenteringEdgeStripKeepsTheForceContinuous) {
  ExpectSmoothRisingForce("two_lobe_patch_b.txt", 3e-6, 10e-9);  // +-3 um, 10 nm steps
}

// A worn tread's wide patch (tests/data/kp_worn_tread/worn_cruise_patch.txt, the dynamic provider's conformal run with
// 0.2 mm steps): a 0.12 um ripple next to the deepest gap is a well of weight 0.03 at 58 um of approach, fading to 0 at
// 61 um (prominence against 0.2-1 % of its approach, §3.3). Its crest cut the main well, so the strips beyond it had
// the ripple's tiny virtual level: c of 0.2-0.7 mm against 4.8 mm, p_max 7-16 GPa, and F_n jumped by 17 % (38.9 ->
// 45.4 kN) when the weight reached 0; the wheel's load control failed there. The main well now reaches past a partial
// well's crest with the share 1 - w. Left (known): the strips are still laid in two lobes split at the ripple's crest
// until its weight is 0; the re-laying then moves F_n by -0.3 % (60.79 um), hence a tolerated drop of 0.5 %.
TEST(KpCollocation, RippleWellFadesOutOfTheMainWellContinuously) {
  ExpectSmoothRisingForce("worn_cruise_patch.txt", 3.5e-6, 50e-9, 0.005);  // 54.4 ... 61.4 um in 50 nm steps
}

}  // namespace conforma

