// Conformity index, paper 003 eq. 13.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/conformity.hpp"
#include "conforma/error.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

TEST(Conformity, SpreadOfNormalAnglesAndThreshold) {
  const ConformityIndex flat = ComputeConformityIndex({0.0, 0.0, 0.0});
  EXPECT_EQ(flat.alpha_c_deg, 0.0);
  EXPECT_FALSE(flat.is_conformal);
  const double deg = M_PI / 180.0;
  const ConformityIndex mild = ComputeConformityIndex({-8.0 * deg, 0.5 * deg, 9.0 * deg});
  EXPECT_NEAR(mild.alpha_c_deg, 17.0, 1e-12);
  EXPECT_FALSE(mild.is_conformal);
  const ConformityIndex strong = ComputeConformityIndex({-10.0 * deg, 9.0 * deg});
  EXPECT_NEAR(strong.alpha_c_deg, 19.0, 1e-12);
  EXPECT_TRUE(strong.is_conformal);
  EXPECT_FALSE(ComputeConformityIndex({-10.0 * deg, 9.0 * deg}, 20.0).is_conformal);
  EXPECT_THROW(ComputeConformityIndex({std::nan("")}), InputError);
}

TEST(Conformity, CircularGrooveGivesTwiceHalfWidthOverRadius) {
  // For a constant lateral radius R the normals turn by (s_max - s_min) / R over the contact
  // (docs/physics-reference.md §9).
  Material material;
  const double groove = 10.10e-3;
  const PatchGeometry patch = kp_test::GroovePatch(10e-3, groove, 0.42, 12e-3, 241);
  const KpResult r = SolveKikPiotrowskiForApproach(patch, 1.8e-5, ConformalKpOptions(material));
  ASSERT_EQ(r.status, KpStatus::Ok);
  EXPECT_NEAR(r.alpha_c_deg, r.width_m / groove * 180.0 / M_PI, 1e-9);
  // Below the threshold for a light load in a loose groove.
  const PatchGeometry loose = kp_test::GroovePatch(10e-3, 12.0e-3, 0.42, 12e-3, 241);
  const KpResult light = SolveKikPiotrowskiForApproach(loose, 1e-6, ConformalKpOptions(material));
  EXPECT_LT(light.alpha_c_deg, 18.0);
  EXPECT_FALSE(light.is_conformal);
}

}  // namespace
}  // namespace conforma
