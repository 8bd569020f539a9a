// Conformal KP (Blanco-Lorenzo) reduces exactly to planar KP on flat patches; strip influence integrals agree
// with the BEM helper's independent rectangle coefficients (influence.hpp).
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../conformal/kp_strip_integrals.hpp"
#include "conforma/influence.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"

namespace conforma {
namespace {

PatchGeometry RandomPatch(std::mt19937& rng, double curvature_tilt) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double B = 0.05 + 3.0 * unit(rng);      // 1/m
  const double cubic = (unit(rng) - 0.5) * 20.0 * B;  // 1/m^2, skews the patch
  const double quartic = unit(rng) * 400.0 * B;       // 1/m^3
  const double A0 = 0.3 + 2.0 * unit(rng);
  const double A_slope = (unit(rng) - 0.5) * 20.0;
  const double yaw_lead = unit(rng) < 0.5 ? 0.0 : (unit(rng) - 0.5) * 0.2;  // x_offset = yaw_lead * s
  PatchGeometry patch;
  const int strips = 61 + static_cast<int>(unit(rng) * 100);
  const double half_range = 0.02;
  patch.ds_m = 2 * half_range / (strips - 1);
  for (int j = 0; j < strips; ++j) {
    const double s = -half_range + j * patch.ds_m;
    patch.s_m.push_back(s);
    patch.gap_m.push_back(B * s * s + cubic * s * s * s * (std::abs(s) < 0.01 ? 1.0 : 0.0) * 0.0 + quartic * s * s * s * s);
    patch.longitudinal_curvature_per_m.push_back(std::max(A0 + A_slope * s, 0.1));
    patch.wheel_radius_m.push_back(0.46);
    patch.alpha_rad.push_back(curvature_tilt * s);
    patch.x_offset_m.push_back(yaw_lead * s);
  }
  (void)cubic;
  return patch;
}

void ExpectRelative(double value, double reference, double tolerance, const char* what) {
  EXPECT_LE(std::abs(value - reference), tolerance * std::abs(reference)) << what;
}

TEST(KpConformal, EqualsPlanarKpOnFlatPatchesRandomCases) {
  std::mt19937 rng(20260522);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Material material;
  for (int trial = 0; trial < 40; ++trial) {
    const PatchGeometry patch = RandomPatch(rng, 0.0);
    const double load = 1.0e3 + 1.0e5 * unit(rng);
    KpLoadOptions planar_options;
    planar_options.kp = trial % 3 == 0 ? KpecOptions(material) : PlanarKpOptions(material);
    KpLoadOptions conformal_options = planar_options;
    conformal_options.kp.influence = KpInfluence::BlancoLorenzo;
    conformal_options.kp.coupling = trial % 2 ? ConformalCoupling::PaperSingleBody : ConformalCoupling::CombinedBodies;
    const KpResult planar = SolveKikPiotrowskiForLoad(patch, load, planar_options);
    const KpResult conformal = SolveKikPiotrowskiForLoad(patch, load, conformal_options);
    ASSERT_EQ(planar.status, conformal.status) << "trial " << trial;
    ASSERT_NE(planar.status, KpStatus::NoContact);
    ExpectRelative(conformal.p0_Pa, planar.p0_Pa, 1e-9, "p0");
    ExpectRelative(conformal.pmax_Pa, planar.pmax_Pa, 1e-9, "pmax");
    ExpectRelative(conformal.fn_N, planar.fn_N, 1e-9, "fn");
    ExpectRelative(conformal.area_m2, planar.area_m2, 1e-9, "area");
    ExpectRelative(conformal.width_m, planar.width_m, 1e-9, "width");
    ExpectRelative(conformal.length_m, planar.length_m, 1e-9, "length");
    ExpectRelative(conformal.approach_m, planar.approach_m, 1e-9, "approach");
    EXPECT_EQ(conformal.fs_N, 0.0);
    EXPECT_EQ(conformal.alpha_c_deg, 0.0);
    EXPECT_FALSE(conformal.is_conformal);
    ASSERT_EQ(conformal.strips.size(), planar.strips.size());
    for (size_t j = 0; j < planar.strips.size(); ++j)
      EXPECT_NEAR(conformal.strips[j].peak_pressure_Pa, planar.strips[j].peak_pressure_Pa, 1e-9 * planar.pmax_Pa);
  }
}

TEST(KpConformal, ContinuousAsTheNormalsStraighten) {
  std::mt19937 rng(7);
  Material material;
  const double tilt_small = 1e-4;  // rad/m: normals turn by 1e-6 rad over the patch
  const PatchGeometry flat = RandomPatch(rng, 0.0);
  std::mt19937 rng2(7);
  const PatchGeometry tilted = RandomPatch(rng2, tilt_small);
  const KpResult planar = SolveKikPiotrowskiForApproach(flat, 5e-5, PlanarKpOptions(material));
  const KpResult conformal = SolveKikPiotrowskiForApproach(tilted, 5e-5, ConformalKpOptions(material));
  ExpectRelative(conformal.p0_Pa, planar.p0_Pa, 1e-9, "p0");
  ExpectRelative(conformal.fn_N, planar.fn_N, 1e-9, "fn");
}

TEST(KpConformal, CurvedNormalsStiffenTheContact) {
  // Blanco's cos(alpha) lowers the compliance, so at a given approach the pressure rises (eq. 8).
  Material material;
  std::mt19937 rng(11), rng2(11);
  const PatchGeometry flat = RandomPatch(rng, 0.0);
  const PatchGeometry curved = RandomPatch(rng2, 1.0 / 0.01);  // 10 mm lateral radius
  const KpResult planar = SolveKikPiotrowskiForApproach(curved, 5e-5, PlanarKpOptions(material));
  const KpResult conformal = SolveKikPiotrowskiForApproach(curved, 5e-5, ConformalKpOptions(material));
  EXPECT_GT(conformal.p0_Pa, planar.p0_Pa);
  EXPECT_GT(conformal.alpha_c_deg, 5.0);
  (void)flat;
}

// Independent check of the strip integrals: sum of influence.hpp rectangle coefficients over a fine grid of
// elements carrying the semi-elliptic pressure (centre values). Differences are the grid's O(h^1.5) edge error.
double RectangleSum(const kp_detail::StripLoad& strip, double s_observation, bool blanco, ConformalCoupling coupling,
                    const ElasticConstants& elastic, int nx, int ns) {
  const double dx = 2 * strip.half_length / nx;
  const double ds = (strip.s_high - strip.s_low) / ns;
  double sum = 0.0;
  for (int j = 0; j < ns; ++j) {
    const double s = strip.s_low + (j + 0.5) * ds;
    const double alpha = strip.alpha_low + (strip.alpha_high - strip.alpha_low) * (s - strip.s_low) / (strip.s_high - strip.s_low);
    for (int i = 0; i < nx; ++i) {
      const double x = -strip.half_length + (i + 0.5) * dx;  // relative to the strip centre
      const double p = std::sqrt(std::max(strip.half_length * strip.half_length - x * x, 0.0));
      const double offset_x = 0.0 - (strip.centre_offset + x), offset_s = s_observation - s;
      sum += p * (blanco ? BlancoNormalRectangle(offset_x, offset_s, dx, ds, alpha, elastic, coupling)
                         : RectangleNormalInfluence(offset_x, offset_s, dx, ds, elastic));
    }
  }
  return sum * M_PI * elastic.shear_modulus_Pa;  // back to the unit of StripNormalDisplacementIntegral
}

TEST(KpConformal, StripIntegralsMatchRectangleCoefficients) {
  Material material;
  const ElasticConstants elastic = CombinedElasticConstants(material);
  struct Case { double s_low, s_high, c, d, a_low, a_high, s_obs; bool blanco; ConformalCoupling coupling; };
  const Case cases[] = {
      {-0.5e-3, 0.5e-3, 6e-3, 0.0, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},        // singular, centred
      {-0.2e-3, 0.8e-3, 6e-3, 0.0, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},        // off-centre split
      {1.0e-3, 2.0e-3, 4e-3, 0.0, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},         // neighbour
      {5.0e-3, 6.0e-3, 3e-3, 0.0, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},         // far
      {-0.5e-3, 0.5e-3, 6e-3, 1.5e-3, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},     // yaw offset
      {2.0e-3, 3.0e-3, 3e-3, -4.0e-3, 0.0, 0.0, 0.0, false, ConformalCoupling::CombinedBodies},     // offset, outside
      {3.0e-3, 4.0e-3, 4e-3, 0.0, 0.3, 0.4, 0.0, true, ConformalCoupling::CombinedBodies},          // Blanco cos
      {3.0e-3, 4.0e-3, 4e-3, 0.0, 0.3, 0.4, 0.0, true, ConformalCoupling::PaperSingleBody},         // paper coupling
      {-0.5e-3, 0.5e-3, 4e-3, 0.5e-3, -0.05, 0.05, 0.0, true, ConformalCoupling::PaperSingleBody},  // singular + both
  };
  for (const Case& c : cases) {
    kp_detail::StripLoad strip{c.s_low, c.s_high, c.c, c.d, c.a_low, c.a_high};
    const double K = c.blanco ? CouplingParameter(c.coupling, elastic) : 0.0;
    const double exact = kp_detail::StripNormalDisplacementIntegral(strip, c.s_obs, elastic.poisson_ratio, c.blanco, K);
    const double grid = RectangleSum(strip, c.s_obs, c.blanco, c.coupling, elastic, 1600, 40);
    EXPECT_NEAR(exact / grid, 1.0, 2e-4) << "strip [" << c.s_low << ", " << c.s_high << "] d " << c.d;
  }
}

}  // namespace
}  // namespace conforma
