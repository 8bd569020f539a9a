// Kalker's creep coefficients (docs/physics-reference.md §2.2): table knots, the steel values at a/b = 1, continuity
// of the interpolation at g = 1, at the knots and at the switch to the asymptotes, and an external fit.
// test-links: hertz_fastsim  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/kalker.hpp"

using conforma::CreepCoefficients;
using conforma::KalkerCoefficients;

TEST(Kalker, SteelValuesAtCircularContact) {
  const CreepCoefficients c = KalkerCoefficients(1.0, 0.28);
  EXPECT_NEAR(c.c11, 4.226, 5e-4);
  EXPECT_NEAR(c.c22, 3.705, 5e-4);
  EXPECT_NEAR(c.c23, 1.488, 5e-4);
  const CreepCoefficients c30 = KalkerCoefficients(1.0, 0.30);
  EXPECT_NEAR(c30.c11, 4.300, 5e-4);
  EXPECT_NEAR(c30.c22, 3.729, 5e-4);
  EXPECT_NEAR(c30.c23, 1.500, 5e-4);
}

TEST(Kalker, ReproducesTableAtKnots) {
  // Selected entries of Table E.3 (§2.2), both orientations, all three Poisson ratios.
  struct Entry { double a_over_b, nu, c11, c22, c23; };
  const Entry entries[] = {
      {0.1, 0.0, 2.51, 2.51, 0.334}, {0.2, 0.25, 3.37, 2.63, 0.603}, {0.5, 0.5, 4.83, 3.14, 1.07},
      {0.8, 0.25, 3.91, 3.41, 1.25}, {0.9, 0.0, 3.29, 3.29, 1.23},   {1.0, 0.5, 5.20, 3.98, 1.63},
      {10.0, 0.0, 10.7, 10.7, 12.2}, {5.0, 0.25, 7.78, 8.14, 6.63},  {2.0, 0.5, 6.11, 5.56, 2.96},
      {1.0 / 0.7, 0.25, 4.54, 4.21, 1.95}, {1.0 / 0.3, 0.0, 5.57, 5.57, 3.79}, {1.0 / 0.9, 0.5, 5.30, 4.16, 1.77}};
  for (const Entry& e : entries) {
    const CreepCoefficients c = KalkerCoefficients(e.a_over_b, e.nu);
    EXPECT_NEAR(c.c11, e.c11, 1e-9) << e.a_over_b << " " << e.nu;
    EXPECT_NEAR(c.c22, e.c22, 1e-9) << e.a_over_b << " " << e.nu;
    EXPECT_NEAR(c.c23, e.c23, 1e-9) << e.a_over_b << " " << e.nu;
  }
}

// Continuity: at g = 1 (switch of tables), at every knot and at g = 0.1 (switch to the asymptotes), the
// coefficients on both sides differ by no more than the local slope allows.
TEST(Kalker, ContinuousAcrossKnotsAndTableSwitch) {
  const double eps = 1e-7;
  for (double nu : {0.0, 0.28, 0.5}) {
    std::vector<double> points = {1.0, 0.1, 10.0};
    for (int i = 2; i <= 9; ++i) {
      points.push_back(0.1 * i);
      points.push_back(1.0 / (0.1 * i));
    }
    for (double p : points) {
      const CreepCoefficients lo = KalkerCoefficients(p * (1 - eps), nu);
      const CreepCoefficients hi = KalkerCoefficients(p * (1 + eps), nu);
      EXPECT_NEAR(lo.c11, hi.c11, 1e-5 * hi.c11) << p << " " << nu;
      EXPECT_NEAR(lo.c22, hi.c22, 1e-5 * hi.c22) << p << " " << nu;
      EXPECT_NEAR(lo.c23, hi.c23, 1e-5 * hi.c23) << p << " " << nu;
    }
  }
}

TEST(Kalker, AsymptotesForVeryElongatedPatches) {
  const double nu = 0.28;
  // a << b: C11 -> pi^2 / (4 (1 - nu)), C22 -> pi^2/4.
  const CreepCoefficients narrow = KalkerCoefficients(1e-4, nu);
  EXPECT_NEAR(narrow.c11, M_PI * M_PI / (4 * (1 - nu)), 1e-3 * narrow.c11);
  EXPECT_NEAR(narrow.c22, M_PI * M_PI / 4, 1e-3 * narrow.c22);
  // a >> b: g C11 grows only logarithmically; C11 increases monotonically with a/b.
  double previous = 0.0;
  for (double ab : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 30.0, 100.0}) {
    const CreepCoefficients c = KalkerCoefficients(ab, nu);
    EXPECT_GT(c.c11, previous) << ab;
    previous = c.c11;
  }
}

// External check: the polynomial fit quoted in §2.2 (nu ~ 0.27-0.28). §2.2 states +-1.5 % for 0.15 <= a/b <= 5,
// but at the knot a/b = 5 (g = 0.2, exactly reproduced, see ReproducesTableAtKnots) the fit's C22 = 8.49 is
// 2.2 % above the table value 8.31 at nu = 0.28 (table 6.96/8.14/9.79), so the fit itself is off there; we check
// 0.15 <= a/b <= 4 at 2 % (largest measured deviation 1.7 %, C22 at a/b = 4).
TEST(Kalker, AgreesWithPolynomialFit) {
  for (double ab : {0.15, 0.2, 0.3, 0.5, 0.7, 1.0, 1.3, 2.0, 3.0, 4.0}) {
    const double r = 1.0 / ab;  // b/a
    const double c11 = 3.2893 + 0.975 / r - 0.012 / (r * r);
    const double c22 = 2.4014 + 1.3179 / r - 0.02 / (r * r);
    const double c23 = 0.4147 + 1.0184 / r + 0.0565 / (r * r) - 0.0013 / (r * r * r);
    const CreepCoefficients c = KalkerCoefficients(ab, 0.28);
    EXPECT_NEAR(c.c11, c11, 0.02 * c11) << ab;
    EXPECT_NEAR(c.c22, c22, 0.02 * c22) << ab;
    EXPECT_NEAR(c.c23, c23, 0.02 * c23) << ab;
  }
}

// The smoother a > b interpolation (g C11 linear in g) at a/b = 7 gives about 9.53 (§2.2), not CONTACT's
// linear-in-C 10.14.
TEST(Kalker, SmootherInterpolationForLongPatches) {
  const CreepCoefficients c = KalkerCoefficients(7.0, 0.28);
  EXPECT_NEAR(c.c11, 9.53, 0.1);
}

TEST(Kalker, C33IsFlaggedUnverified) {
  const CreepCoefficients round = KalkerCoefficients(1.0, 0.28);
  EXPECT_FALSE(round.c33_verified);
  EXPECT_TRUE(round.c33_available);
  // Consistency check of §2.2: the slope of Kalker's exact table gives C33 ~ 1.18 ... 1.23 at a/b = 1.
  EXPECT_GT(round.c33, 1.17);
  EXPECT_LT(round.c33, 1.24);
  const CreepCoefficients along = KalkerCoefficients(2.0, 0.28);
  EXPECT_FALSE(along.c33_available);
  EXPECT_EQ(along.c33, 0.0);
}

TEST(Kalker, BadInputThrows) {
  EXPECT_THROW(KalkerCoefficients(0.0, 0.28), conforma::InputError);
  EXPECT_THROW(KalkerCoefficients(-1.0, 0.28), conforma::InputError);
  EXPECT_THROW(KalkerCoefficients(1.0, 0.6), conforma::InputError);
  EXPECT_THROW(KalkerCoefficients(std::nan(""), 0.28), conforma::InputError);
}
