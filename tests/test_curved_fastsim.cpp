// Curved-patch FASTSIM (paper 003 eqs. 9-12): reduction to classic FASTSIM on a flat ellipse, Kalker's linear
// theory through the SDEC flexibilities, full slip, the CONTACT reference case, frame rotation.
// test-links: fastsim_ext  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"
#include "conforma/kalker.hpp"
#include "tangential_test_patches.hpp"

using namespace conforma;
using tangential_test::EllipticStrips;

namespace {

double MaxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

// Flat elliptic patch, same mesh, same flexibilities: the curved solver is classic FASTSIM (1e-10 relative),
// through the uniform path and the per-strip path, both marchings.
TEST(CurvedFastsim, FlatEllipseEqualsClassicFastsim) {
  const Material steel;
  const double a = 6e-3, b = 4e-3, N = 80e3;
  const int nx = 30, ny = 30;
  const KpResult kp = EllipticStrips(a, b, N, ny);
  const CreepCoefficients C = KalkerCoefficients(a / b, steel.poisson_ratio);
  const FastsimFlexibilities L = KalkerFlexibilities(a, b, C, steel.shear_modulus_Pa);
  for (FastsimMarching marching : {FastsimMarching::CentreExact, FastsimMarching::ClassicFullStep}) {
    for (FastsimCreepages creep : {FastsimCreepages{2e-4, -1e-4, 0.2}, FastsimCreepages{2e-3, 1e-3, -1.5},
                                   FastsimCreepages{0.0, -0.000625, 0.625}}) {
      FastsimHertzInput hin;
      hin.a_m = a;
      hin.b_m = b;
      hin.normal_force_N = N;
      hin.creepages = creep;
      hin.friction_coefficient = 0.3;
      hin.nx = nx;
      hin.ny = ny;
      FastsimOptions fo;
      fo.marching = marching;
      const FastsimResult ref = SolveFastsimHertz(hin, fo);
      for (bool per_strip : {false, true}) {
        CurvedFastsimInput in;
        in.strip_creepages.assign(per_strip ? ny : 1, creep);
        in.strip_flexibilities = {L};
        in.friction = FrictionLaw::Constant(0.3);
        CurvedFastsimOptions options;
        options.elements_per_strip = nx;
        options.marching = marching;
        options.load_N = N;
        const CurvedFastsimResult r = SolveCurvedFastsim(kp, in, options);
        const double scale = std::hypot(ref.fx_N, ref.fy_N);
        EXPECT_NEAR(r.fx_N, ref.fx_N, 1e-10 * scale);
        EXPECT_NEAR(r.fs_N, ref.fy_N, 1e-10 * scale);
        EXPECT_NEAR(r.mz_Nm, ref.mz_Nm, 1e-10 * std::abs(ref.mz_Nm));
        EXPECT_NEAR(r.slip_area_m2, ref.slip_area_m2, 1e-10 * (ref.slip_area_m2 + ref.adhesion_area_m2));
        ASSERT_EQ(r.field.px_Pa.size(), ref.px_Pa.size());
        const double pmax = std::max(MaxAbs(ref.px_Pa), MaxAbs(ref.py_Pa));
        for (size_t e = 0; e < ref.px_Pa.size(); ++e) {
          ASSERT_NEAR(r.field.px_Pa[e], ref.px_Pa[e], 1e-10 * pmax) << e;
          ASSERT_NEAR(r.field.py_Pa[e], ref.py_Pa[e], 1e-10 * pmax) << e;
          ASSERT_EQ(r.field.in_slip[e], ref.in_slip[e]) << e;
        }
        // Flat patch: the reference-frame resultant is the same force, its moment about n0 the spin moment.
        EXPECT_NEAR(r.force_reference_N.x(), ref.fx_N, 1e-10 * scale);
        EXPECT_NEAR(r.force_reference_N.y(), ref.fy_N, 1e-10 * scale);
        EXPECT_NEAR(r.force_reference_N.z(), 0.0, 1e-12 * scale);
        EXPECT_NEAR(r.moment_reference_Nm.z(), ref.mz_Nm, 1e-10 * std::abs(ref.mz_Nm));
      }
    }
  }
}

// Small creepage through the new solver with the SDEC flexibilities (a, b reduced from the strips, not given):
// Kalker's linear theory within 1 % for a/b = 0.2 ... 5 (docs/physics-reference.md §2.1).
TEST(CurvedFastsim, LinearTheoryThroughSdec) {
  const Material steel;
  const double G = steel.shear_modulus_Pa, N = 80e3, mu = 0.3;
  for (double ab : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double c = 5e-3, a = c * std::sqrt(ab), b = c / std::sqrt(ab);
    const KpResult kp = EllipticStrips(a, b, N, 40);
    const CreepCoefficients C = KalkerCoefficients(ab, steel.poisson_ratio);
    CurvedFastsimOptions options;
    options.elements_per_strip = 30;
    CurvedFastsimInput in;
    in.friction = FrictionLaw::Constant(mu);
    const double xi = 1e-3 * mu * N / (G * c * c * C.c11);
    in.strip_creepages = {{xi, 0.0, 0.0}};
    const CurvedFastsimResult rx = SolveCurvedFastsim(kp, in, options);
    EXPECT_NEAR(rx.fx_N / (-G * c * c * C.c11 * xi), 1.0, 0.01) << ab;
    const double eta = 1e-3 * mu * N / (G * c * c * C.c22);
    in.strip_creepages = {{0.0, eta, 0.0}};
    const CurvedFastsimResult ry = SolveCurvedFastsim(kp, in, options);
    EXPECT_NEAR(ry.fs_N / (-G * c * c * C.c22 * eta), 1.0, 0.01) << ab;
    const double phi = 1e-3 * mu * N / (G * c * c * c * C.c23);
    in.strip_creepages = {{0.0, 0.0, phi}};
    const CurvedFastsimResult rs = SolveCurvedFastsim(kp, in, options);
    EXPECT_NEAR(rs.fs_N / (-G * c * c * c * C.c23 * phi), 1.0, 0.01) << ab;
    EXPECT_NEAR(rs.fx_N, 0.0, 1e-9 * mu * N);
  }
}

// Full slip: |F| = mu Fn within 0.5 %, opposite to the creepage; the whole patch slips.
TEST(CurvedFastsim, FullSlipSaturatesAtMuN) {
  const double N = 80e3, mu = 0.3;
  for (double ab : {0.2, 1.0, 5.0}) {
    const double c = 5e-3;
    const KpResult kp = EllipticStrips(c * std::sqrt(ab), c / std::sqrt(ab), N, 30);
    for (double angle : {0.0, 0.9, 2.2, 4.0}) {
      CurvedFastsimInput in;
      in.friction = FrictionLaw::Constant(mu);
      in.strip_creepages = {{0.05 * std::cos(angle), 0.05 * std::sin(angle), 0.0}};
      const CurvedFastsimResult r = SolveCurvedFastsim(kp, in, CurvedFastsimOptions{});
      EXPECT_NEAR(std::hypot(r.fx_N, r.fs_N), mu * r.bound_load_N, 0.005 * mu * N) << ab << " " << angle;
      EXPECT_NEAR(r.bound_load_N, N, 0.01 * N);
      EXPECT_LT(r.fx_N * std::cos(angle) + r.fs_N * std::sin(angle), 0.0);
      EXPECT_EQ(r.status, FastsimStatus::FullSlip);
    }
  }
}

// contact_basic_cases.csv (CONTACT, Kalker's exact theory): a = 8 mm, b = 4 mm, 82 kN, eta = -0.000625,
// phi = 0.000625 rad/mm, mu = 0.3: Fy = -14940 N within 3 %, Mz = -48210 N mm within 5 %, through the new
// solver with the SDEC flexibilities of the elliptic strip set, on CONTACT's 44 x 44 grid with the marching of
// paper 003 eq. 9 (p_A(x_i) = p_t(x_{i-1}) - dx L^-1 S: the classic full step). With the second-order centre
// marching Fy is also within 3 %, but the spin moment converges to about 8 % below the exact value (a known
// FASTSIM limitation, docs/physics-reference.md §2.5), so that Mz is reported, not asserted against the exact theory.
TEST(CurvedFastsim, ContactBasicCase) {
  const double N = 82e3;
  const KpResult kp = EllipticStrips(8e-3, 4e-3, N, 44);
  CurvedFastsimInput in;
  in.friction = FrictionLaw::Constant(0.3);
  in.strip_creepages = {{0.0, -0.000625, 0.625}};
  CurvedFastsimOptions options;
  options.elements_per_strip = 44;
  options.load_N = N;
  options.marching = FastsimMarching::ClassicFullStep;
  const CurvedFastsimResult r = SolveCurvedFastsim(kp, in, options);
  std::printf("paper eq. 9 marching 44x44: Fy = %.1f N (exact -14940), Mz = %.1f N mm (exact -48210)\n", r.fs_N,
              r.mz_Nm * 1e3);
  EXPECT_NEAR(r.fs_N, -14940.0, 0.03 * 14940.0);
  EXPECT_NEAR(r.mz_Nm * 1e3, -48210.0, 0.05 * 48210.0);
  options.marching = FastsimMarching::CentreExact;
  const CurvedFastsimResult c = SolveCurvedFastsim(kp, in, options);
  std::printf("centre marching 44x44: Fy = %.1f N, Mz = %.1f N mm\n", c.fs_N, c.mz_Nm * 1e3);
  EXPECT_NEAR(c.fs_N, -14940.0, 0.03 * 14940.0);
}

// A flat patch tilted by alpha0: local results are unchanged, the reference-frame force is the local one rotated
// (t = cos a t0 - sin a n0).
TEST(CurvedFastsim, TiltedPatchRotatesForces) {
  const double N = 60e3, alpha = 0.4;
  const KpResult flat = EllipticStrips(5e-3, 4e-3, N, 24);
  const KpResult tilted = EllipticStrips(5e-3, 4e-3, N, 24, alpha);
  CurvedFastsimInput in;
  in.strip_creepages = {{1e-3, 2e-3, 0.5}};
  const CurvedFastsimResult f = SolveCurvedFastsim(flat, in, CurvedFastsimOptions{});
  const CurvedFastsimResult t = SolveCurvedFastsim(tilted, in, CurvedFastsimOptions{});
  EXPECT_DOUBLE_EQ(f.fx_N, t.fx_N);
  EXPECT_DOUBLE_EQ(f.fs_N, t.fs_N);
  EXPECT_NEAR(t.force_reference_N.y(), f.fs_N * std::cos(alpha), 1e-9 * std::abs(f.fs_N));
  EXPECT_NEAR(t.force_reference_N.z(), -f.fs_N * std::sin(alpha), 1e-9 * std::abs(f.fs_N));
  // The moment about the tilted normal n_local = cos a n0 + sin a t0 is the curvilinear spin moment.
  const double m_local = t.moment_reference_Nm.z() * std::cos(alpha) + t.moment_reference_Nm.y() * std::sin(alpha);
  EXPECT_NEAR(m_local, f.mz_Nm, 1e-9 * std::abs(f.mz_Nm));
}

TEST(CurvedFastsim, BadInputAndNoContact) {
  const KpResult kp = EllipticStrips(5e-3, 4e-3, 1e4, 10);
  CurvedFastsimInput in;
  EXPECT_THROW(SolveCurvedFastsim(kp, in, CurvedFastsimOptions{}), InputError);  // no creepages
  in.strip_creepages = {{0, 0, 0}, {0, 0, 0}};
  EXPECT_THROW(SolveCurvedFastsim(kp, in, CurvedFastsimOptions{}), InputError);  // wrong count
  in.strip_creepages = {{1e-3, 0, 0}};
  CurvedFastsimOptions bad;
  bad.slope_reduction = 0.0;
  EXPECT_THROW(SolveCurvedFastsim(kp, in, bad), InputError);
  KpResult nan = kp;
  nan.strips[3].half_length_m = std::nan("");
  EXPECT_THROW(SolveCurvedFastsim(nan, in, CurvedFastsimOptions{}), InputError);
  const CurvedFastsimResult empty = SolveCurvedFastsim(KpResult{}, in, CurvedFastsimOptions{});
  EXPECT_EQ(empty.status, FastsimStatus::NoContact);
  EXPECT_EQ(empty.fx_N, 0.0);
}
