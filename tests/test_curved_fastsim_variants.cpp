// The two FASTSIM variants on a KP patch (issue 15 item 2, docs/physics-reference.md §5.4), both off by default:
// spin about the patch centre (origin invariance, Kalker's linear F_x of a spin referred to an off-centre point) and
// strip-wise flexibilities from the local half-length (Kalker's linear theory on the ellipse, Carter's 2-D strip).
// test-links: fastsim_ext  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/curved_fastsim.hpp"
#include "conforma/kalker.hpp"
#include "tangential_test_patches.hpp"

using namespace conforma;
using tangential_test::EllipticStrips;

namespace {

// Pure spin phi whose rigid slip is referred to the point s = d (spin_origin_s_m = d, xi = eta = 0 there): the rigid
// slip is w_x = -phi (s - d) = phi d - phi s, i.e. a longitudinal creepage phi d at the ellipse's centre plus the spin.
CurvedFastsimResult SpinReferredTo(const KpResult& kp, double phi, double d, bool about_centre) {
  CurvedFastsimInput in;
  in.friction = FrictionLaw::Constant(0.3);
  in.strip_creepages = {{0.0, 0.0, phi}};
  CurvedFastsimOptions options;
  options.elements_per_strip = 30;
  options.spin_origin_s_m = d;
  options.spin_about_patch_centre = about_centre;
  return SolveCurvedFastsim(kp, in, options);
}

}  // namespace

// Linear theory (Kalker, docs/physics-reference.md §2.1, §6.5): F_x = -G c^2 C11 (xi - phi (y_c - s_o)) does not depend
// on where the creepages are referred to. Spin about the patch centre: F_x within 1 % of it, F_y (= -G c^3 C23 phi)
// within 1 %, and every resultant the same (1e-9) for d = 0, 2, 5 mm. The classic form (spin about the given point)
// puts the translation part phi d of the spin through L3 instead of L1: its F_x is Kalker's times L1/L3.
TEST(CurvedFastsimVariants, SpinAboutPatchCentreIsIndependentOfTheCreepageOrigin) {
  const Material steel;
  const double G = steel.shear_modulus_Pa, N = 80e3, mu = 0.3;
  for (double ab : {0.5, 1.0, 2.0}) {
    const double c = 5e-3, a = c * std::sqrt(ab), b = c / std::sqrt(ab);
    const KpResult kp = EllipticStrips(a, b, N, 40);
    const CreepCoefficients C = KalkerCoefficients(ab, steel.poisson_ratio);
    const FastsimFlexibilities L = KalkerFlexibilities(a, b, C, G);
    const double phi = 1e-3 * mu * N / (G * c * c * c * C.c23);  // linear range
    const CurvedFastsimResult at_centre = SpinReferredTo(kp, phi, 0.0, true);
    for (double d : {2e-3, 5e-3}) {
      const CurvedFastsimResult r = SpinReferredTo(kp, phi, d, true);
      const double fx_kalker = -G * c * c * C.c11 * (phi * d);
      EXPECT_NEAR(r.force_reference_N.x() / fx_kalker, 1.0, 0.01) << ab << " " << d;
      EXPECT_NEAR(r.force_reference_N.y() / (-G * c * c * c * C.c23 * phi), 1.0, 0.01) << ab << " " << d;
      // the same patch solved about the same centre: the results do not depend on d (nor do the field positions)
      const CurvedFastsimResult r0 = SpinReferredTo(kp, phi, 0.0, true);
      const CurvedFastsimResult same = SpinReferredTo(kp, phi, d, false);  // classic form, for the contrast below
      EXPECT_NEAR(same.force_reference_N.x() / (fx_kalker * L.L1 / L.L3), 1.0, 0.01) << ab << " " << d;
      EXPECT_GT(std::abs(L.L1 / L.L3 - 1.0), 0.15);  // so the classic form really misses Kalker's F_x
      ASSERT_EQ(r.field.y_m.size(), same.field.y_m.size());
      for (size_t e = 0; e < r.field.y_m.size(); ++e) {
        ASSERT_NEAR(r.field.y_m[e], same.field.y_m[e], 1e-15) << e;  // positions in the given frame
        ASSERT_NEAR(r.field.x_m[e], same.field.x_m[e], 1e-15) << e;
      }
      // moving the creepage point (and the creepages with it) changes nothing about the centre
      const double xi_at_d = -phi * (d - 0.0);  // w_x(d) of the rigid slip of r0 (xi = 0 at s = 0)
      CurvedFastsimInput in;
      in.friction = FrictionLaw::Constant(mu);
      in.strip_creepages = {{xi_at_d, 0.0, phi}};
      CurvedFastsimOptions options;
      options.elements_per_strip = 30;
      options.spin_origin_s_m = d;
      options.spin_about_patch_centre = true;
      const CurvedFastsimResult moved = SolveCurvedFastsim(kp, in, options);
      const double scale = std::hypot(r0.fx_N, r0.fs_N);
      EXPECT_NEAR(moved.force_reference_N.x(), r0.force_reference_N.x(), 1e-9 * scale) << ab << " " << d;
      EXPECT_NEAR(moved.force_reference_N.y(), r0.force_reference_N.y(), 1e-9 * scale) << ab << " " << d;
      EXPECT_NEAR(moved.moment_reference_Nm.z(), r0.moment_reference_Nm.z(), 1e-9 * scale * c) << ab << " " << d;
    }
    // about the centre of a centred ellipse the option changes nothing
    const CurvedFastsimResult classic = SpinReferredTo(kp, phi, 0.0, false);
    EXPECT_NEAR(at_centre.fx_N, classic.fx_N, 1e-9 * std::abs(classic.fs_N)) << ab;
    EXPECT_NEAR(at_centre.fs_N, classic.fs_N, 1e-9 * std::abs(classic.fs_N)) << ab;
  }
}

// Strip-wise flexibilities L1_j = pi c_j/(C11 G), L2_j = pi c_j/(C22 G), L3_j = 8 c_j sqrt(a/b)/(9 C23 G):
// (1) on an ellipse they give Kalker's linear F_x, F_y(eta), F_y(phi) (within 1 %, as the uniform SDEC values do);
// (2) as a/b -> 0 (a/b = 0.05) the middle strip carries Carter's 2-D creep force per unit width,
//     F' = pi c G xi / (2 (1 - nu)) (plane strain, two equal steels), within 1 %, where the uniform SDEC flexibility
//     gives 3 C11 (1 - nu)/(2 pi) = 1.18 times it.
TEST(CurvedFastsimVariants, LocalFlexibilitiesReproduceKalkerOnTheEllipseAndCarterOnALongStrip) {
  const Material steel;
  const double G = steel.shear_modulus_Pa, nu = steel.poisson_ratio, N = 80e3, mu = 0.3;
  for (double ab : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double c = 5e-3, a = c * std::sqrt(ab), b = c / std::sqrt(ab);
    const KpResult kp = EllipticStrips(a, b, N, 40);
    const CreepCoefficients C = KalkerCoefficients(ab, nu);
    CurvedFastsimOptions options;
    options.elements_per_strip = 30;
    options.local_flexibilities = true;
    CurvedFastsimInput in;
    in.friction = FrictionLaw::Constant(mu);
    const double xi = 1e-3 * mu * N / (G * c * c * C.c11);
    in.strip_creepages = {{xi, 0.0, 0.0}};
    EXPECT_NEAR(SolveCurvedFastsim(kp, in, options).fx_N / (-G * c * c * C.c11 * xi), 1.0, 0.01) << ab;
    const double eta = 1e-3 * mu * N / (G * c * c * C.c22);
    in.strip_creepages = {{0.0, eta, 0.0}};
    EXPECT_NEAR(SolveCurvedFastsim(kp, in, options).fs_N / (-G * c * c * C.c22 * eta), 1.0, 0.01) << ab;
    const double phi = 1e-3 * mu * N / (G * c * c * c * C.c23);
    in.strip_creepages = {{0.0, 0.0, phi}};
    EXPECT_NEAR(SolveCurvedFastsim(kp, in, options).fs_N / (-G * c * c * c * C.c23 * phi), 1.0, 0.01) << ab;
  }
  // Carter's strip: a/b = 0.05, 41 strips (the middle one at s = 0, c = a)
  const double a = 2e-3, b = 40e-3;
  const KpResult kp = EllipticStrips(a, b, N, 41);
  const CreepCoefficients C = KalkerCoefficients(a / b, nu);
  const double xi = 1e-3 * mu * N / (G * a * b * C.c11);
  const double carter = M_PI * a * G * xi / (2.0 * (1.0 - nu));  // N/m, magnitude
  for (bool local : {true, false}) {
    CurvedFastsimInput in;
    in.friction = FrictionLaw::Constant(mu);
    in.strip_creepages = {{xi, 0.0, 0.0}};
    CurvedFastsimOptions options;
    options.elements_per_strip = 60;
    options.local_flexibilities = local;
    const CurvedFastsimResult r = SolveCurvedFastsim(kp, in, options);
    ASSERT_EQ(r.status, FastsimStatus::Ok);
    const int j = 20, first = r.strip_first_element[j], end = r.strip_first_element[j + 1];
    double fx = 0.0;
    for (int e = first; e < end; ++e) fx += r.field.px_Pa[e] * r.field.area_m2[e];
    const double per_width = -fx / kp.strips[j].ds_m;
    if (local)
      EXPECT_NEAR(per_width / carter, 1.0, 0.01);
    else
      EXPECT_GT(per_width / carter, 1.15);  // the uniform SDEC flexibility: 1.18
  }
}
