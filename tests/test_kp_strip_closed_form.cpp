// The closed form of the KP strip integral F1 = int sqrt(c^2 - (x-d)^2) / sqrt(x^2 + u^2) dx (complete elliptic
// integrals, kp_strip_integrals.cpp) against (a) high-precision values (mpmath, 40 digits, tanh-sinh quadrature split
// at the point x = 0) and (b) the solver's former graded Gauss quadrature over a range of strip geometries, and the
// strip influence integral built on it against the same integral with the quadrature inside.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "../conformal/kp_strip_integrals.hpp"

namespace conforma {
namespace {

using kp_detail::SemiEllipseOverDistance;
using kp_detail::SemiEllipseOverDistanceQuadrature;

TEST(KpStripClosedForm, MatchesHighPrecisionValues) {
  struct Case {
    double c, d, u, value;
  };
  // mpmath 1.3, mp.dps = 40: quad(c^2 cos^2 t / sqrt((d + c sin t)^2 + u^2), [-pi/2, asin(-d/c), pi/2])
  const std::vector<Case> cases = {
      {1, 0.3, 0.1, 5.1530779011100537957},      {1, -0.7, 0.01, 7.2537281721575666498},
      {2, 1.5, 0.5, 5.3274799875471210539},      {1, 3, 0.2, 0.53762967167281130268},
      {1, 0.99, 0.001, 3.7833053576067427956},   {0.5, 0.01, 2.0, 0.19484809307536464578},
      {1, 1, 1e-06, 3.1391963735573316016},      {1, -1.2, 1e-05, 1.6860143688197912933},
      // where the former quadrature was off by 9e-8 and 7e-8 (near the ends of the segment)
      {1, 1, 0.2, 2.1081942081122605356},        {1, 0.75, 0.7, 1.5714003235580992323},
  };
  for (const Case& k : cases) {
    EXPECT_NEAR(SemiEllipseOverDistance(k.c, k.d, k.u) / k.value - 1.0, 0.0, 2e-13)
        << "c " << k.c << " d " << k.d << " u " << k.u;
    // the same in metres (scale invariance: F1(lambda c, lambda d, lambda u) = lambda F1)
    EXPECT_NEAR(SemiEllipseOverDistance(1e-3 * k.c, 1e-3 * k.d, 1e-3 * k.u) / (1e-3 * k.value) - 1.0, 0.0, 2e-13);
  }
}

TEST(KpStripClosedForm, MatchesFormerQuadratureOverStripGeometries) {
  // The former quadrature's own error reaches ~2e-7 where the observation point is near the end of the segment
  // (|d| ~ c); elsewhere the two agree to ~1e-9 (the closed form matches the 40-digit values above to 2e-13).
  // c from 0.1 to 8 mm, centre offsets |d|/c up to 4 (both signs, through the ends of the segment), distances u/c
  // from 1e-4 to 20: every regime the KP solver meets (observation point on, near and far from the strip).
  double worst = 0.0;
  for (double c : {1e-4, 2e-3, 8e-3}) {
    for (double d_over_c = -4.0; d_over_c <= 4.0001; d_over_c += 0.0625) {
      for (double u_over_c : {1e-4, 1e-3, 1e-2, 0.05, 0.2, 0.7, 2.0, 20.0}) {
        const double d = d_over_c * c, u = u_over_c * c;
        const double closed = SemiEllipseOverDistance(c, d, u);
        const double quadrature = SemiEllipseOverDistanceQuadrature(c, d, u);
        const double relative = std::abs(closed / quadrature - 1.0);
        worst = std::max(worst, relative);
        EXPECT_LT(relative, 5e-7) << "c " << c << " d/c " << d_over_c << " u/c " << u_over_c << " closed " << closed
                                 << " quadrature " << quadrature;
      }
    }
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
  std::printf("worst relative difference closed form / quadrature: %.3g\n", worst);
}

TEST(KpStripClosedForm, ReducesToTheCentredClosedFormAsTheOffsetVanishes) {
  // d -> 0: the general formula (d != 0 branch) tends to 2 sqrt(c^2 + u^2) (K - E) continuously.
  for (double u : {1e-5, 1e-3, 0.3}) {
    const double centred = SemiEllipseOverDistance(1.0, 0.0, u);
    EXPECT_NEAR(SemiEllipseOverDistance(1.0, 1e-12, u) / centred - 1.0, 0.0, 1e-12);
    EXPECT_NEAR(SemiEllipseOverDistance(1.0, -1e-9, u) / centred - 1.0, 0.0, 1e-12);
  }
}

TEST(KpStripClosedForm, BatchEqualsSingleCalls) {
  // lanes converge after different numbers of AGM steps; each must equal its own single evaluation bit for bit
  const double u[kp_detail::kMaxSemiEllipseBatch] = {1e-9, 1e-5, 3e-4, 1e-3, 2e-3, 5e-3, 2e-2, 1.0};
  for (double d : {0.0, 4e-4, -1.1e-3, 1e-3, 3e-3}) {
    double batch[kp_detail::kMaxSemiEllipseBatch];
    kp_detail::SemiEllipseOverDistanceBatch(1e-3, d, u, kp_detail::kMaxSemiEllipseBatch, batch);
    for (int i = 0; i < kp_detail::kMaxSemiEllipseBatch; ++i)
      EXPECT_EQ(batch[i], SemiEllipseOverDistance(1e-3, d, u[i])) << "d " << d << " u " << u[i];
  }
}

TEST(KpStripClosedForm, AnyBatchEqualsSingleCallsOverRandomGeometries) {
  // The batch runs lanes side by side (AVX vectors on x86-64 with AVX, 4 or 8 lanes at a time, each with its own
  // convergence); a single call is the scalar form. Random strips inside, outside and at the edge of the segment,
  // distances from 1e-9 to 10 half-lengths, every batch size: bit for bit the same values.
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const double c = 1e-4 + 5e-3 * unit(random);
    const double pick = unit(random);
    const double d = pick < 0.1 ? 0.0 : (pick < 0.2 ? c : (unit(random) - 0.5) * 6.0 * c);
    const int count = 1 + trial % kp_detail::kMaxSemiEllipseBatch;
    double u[kp_detail::kMaxSemiEllipseBatch], batch[kp_detail::kMaxSemiEllipseBatch];
    for (int i = 0; i < count; ++i) u[i] = c * std::pow(10.0, -9.0 + 10.0 * unit(random));
    if (trial % 7 == 0 && d != 0.0 && std::abs(d) < c) u[0] = 0.0;  // on the segment when |d| < c: the quadrature's value
    kp_detail::SemiEllipseOverDistanceBatch(c, d, u, count, batch);
    for (int i = 0; i < count; ++i)
      ASSERT_EQ(batch[i], SemiEllipseOverDistance(c, d, u[i])) << "c " << c << " d " << d << " u " << u[i];
  }
}

TEST(KpStripClosedForm, EveryAvailableKernelEqualsTheScalarForm) {
  // The vector kernels (AVX, and AVX-512VL: the same operations with 32 registers, contraction off) on lanes each with
  // its own strip and distance, every lane count up to 40 (chunks of 16, a scalar tail of one or two): the scalar
  // form's bits. A kernel the CPU lacks is skipped (and refused by SemiEllipseOverDistanceLanes).
  using kp_detail::SemiEllipseKernel;
  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> c(40), d(40), u(40), scalar(40), vector(40);
  for (SemiEllipseKernel kernel : {SemiEllipseKernel::Avx, SemiEllipseKernel::Avx512vl}) {
    if (!kp_detail::SemiEllipseKernelAvailable(kernel)) {
      EXPECT_THROW(kp_detail::SemiEllipseOverDistanceLanes(kernel, c.data(), d.data(), u.data(), 3, vector.data()),
                   std::logic_error);
      continue;
    }
    for (int trial = 0; trial < 200; ++trial) {
      const int count = 1 + trial % 40;
      for (int i = 0; i < count; ++i) {
        c[i] = unit(random) < 0.05 ? 0.0 : 1e-4 + 5e-3 * unit(random);
        const double pick = unit(random);
        d[i] = pick < 0.1 ? 0.0 : (pick < 0.2 ? c[i] : (unit(random) - 0.5) * 6.0 * (c[i] + 1e-4));
        u[i] = (c[i] + 1e-4) * std::pow(10.0, -9.0 + 10.0 * unit(random));
        if (i % 11 == 3 && d[i] != 0.0 && std::abs(d[i]) < c[i]) u[i] = 0.0;  // on the segment: the quadrature
      }
      kp_detail::SemiEllipseOverDistanceLanes(SemiEllipseKernel::Scalar, c.data(), d.data(), u.data(), count,
                                              scalar.data());
      kp_detail::SemiEllipseOverDistanceLanes(kernel, c.data(), d.data(), u.data(), count, vector.data());
      for (int i = 0; i < count; ++i)
        ASSERT_EQ(vector[i], scalar[i]) << "kernel " << static_cast<int>(kernel) << " lane " << i << " of " << count
                                        << " c " << c[i] << " d " << d[i] << " u " << u[i];
    }
  }
}

TEST(KpStripClosedForm, RowOfStripsEqualsStripByStrip) {
  // A collocation row (§5.3): strips far, near, holding and touching the observation point, empty ones, Blanco weights
  // with and without the coupling; all strips' nodes evaluated together equal the strip-by-strip integrals bit for bit.
  std::vector<kp_detail::StripLoad> strips;
  const double ds = 0.8e-3;
  for (int j = -6; j <= 6; ++j) {
    kp_detail::StripLoad load;
    load.s_low = j * ds - 0.5 * ds;
    load.s_high = j * ds + 0.5 * ds;
    load.half_length = j == 4 ? 0.0 : 3e-3 * std::sqrt(1.0 - (j / 7.0) * (j / 7.0));
    load.centre_offset = 1e-4 * j;
    load.alpha_low = 0.02 * j;
    load.alpha_high = 0.02 * j + 0.015;
    strips.push_back(load);
  }
  for (double s_observation : {0.0, 0.1e-3, 0.4e-3, 2.9e-3})  // 0.4 mm: on a strip edge (touching)
    for (int variant = 0; variant < 3; ++variant) {
      const bool blanco = variant > 0;
      const double coupling_K = variant == 2 ? 0.12 : 0.0;
      std::vector<double> row(strips.size());
      kp_detail::StripNormalDisplacementIntegrals(strips.data(), static_cast<int>(strips.size()), s_observation, 0.28,
                                                  blanco, coupling_K, row.data());
      for (size_t k = 0; k < strips.size(); ++k)
        EXPECT_EQ(row[k], kp_detail::StripNormalDisplacementIntegral(strips[k], s_observation, 0.28, blanco, coupling_K))
            << "strip " << k << " s_obs " << s_observation << " variant " << variant;
    }
}

TEST(KpStripClosedForm, IsFiniteAndPositiveForEveryGeometry) {
  for (double d : {-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0})
    for (double u : {1e-12, 1e-8, 1.0, 1e3}) {
      const double value = SemiEllipseOverDistance(1.0, d, u);
      EXPECT_TRUE(std::isfinite(value) && value > 0.0) << "d " << d << " u " << u;
    }
  EXPECT_EQ(SemiEllipseOverDistance(0.0, 0.3, 0.1), 0.0);
}

// The cosine weight of the strip integrals (paper 003 eq. 5): the series on |alpha| <= pi/4 within one ulp of the
// cosine in extended precision (cosl, 64-bit mantissa on x86-64; the truncation, 3.3e-21, and the Horner rounding
// stay below that), and exactly std::cos beyond.
TEST(KpStripClosedForm, CosineOfSmallAngleIsWithinOneUlp) {
  const double limit = 0.25 * M_PI;
  double worst_ulps = 0.0, worst_library_ulps = 0.0;
  for (int i = -20000; i <= 20000; ++i) {
    const double alpha = limit * i / 20000.0;
    const long double reference = std::cos(static_cast<long double>(alpha));
    const double ulp = std::nextafter(static_cast<double>(reference), 0.0) - static_cast<double>(reference);
    auto ulps = [&](double value) { return static_cast<double>(std::fabs(value - reference)) / std::fabs(ulp); };
    worst_ulps = std::max(worst_ulps, ulps(kp_detail::CosOfSmallAngle(alpha)));
    worst_library_ulps = std::max(worst_library_ulps, ulps(std::cos(alpha)));
  }
  std::printf("CosOfSmallAngle: worst %.3f ulp against cosl over [-pi/4, pi/4] (std::cos %.3f)\n", worst_ulps,
              worst_library_ulps);
  EXPECT_LE(worst_ulps, 1.0);
  for (double alpha : {0.7854, 1.0, -1.3, 2.5, 10.0}) EXPECT_EQ(kp_detail::CosOfSmallAngle(alpha), std::cos(alpha));
  EXPECT_TRUE(std::isnan(kp_detail::CosOfSmallAngle(std::nan(""))));
}

}  // namespace
}  // namespace conforma
