// Influence coefficients: closed forms against numerical quadrature of the point kernels, known values,
// symmetries and the Blanco-Lorenzo correction structure (docs/physics-reference.md §4.2-4.3, §10.2).
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "conforma/error.hpp"
#include "conforma/influence.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;

ElasticConstants Steel() { return CombinedElasticConstants(Material{}); }

// Gauss-Legendre (8 points) on a sub-grid of n x n cells of the rectangle: integral of f(x', s') over the
// load rectangle centred at 0, for an observation point at (X, Y) well outside the rectangle or with the
// singularity on a cell corner (the quadrature then converges slowly, so only used off the element).
double Quadrature(const std::function<double(double, double)>& f, double dx, double ds, int n) {
  static const double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                               0.7966664774136267,  0.9602898564975363};
  static const double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                               0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                               0.2223810344533745, 0.1012285362903763};
  double sum = 0.0;
  const double hx = dx / n, hs = ds / n;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double cx = -0.5 * dx + (a + 0.5) * hx, cs = -0.5 * ds + (b + 0.5) * hs;
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
          sum += gw[i] * gw[j] * 0.25 * hx * hs * f(cx + 0.5 * hx * gx[i], cs + 0.5 * hs * gx[j]);
    }
  return sum;
}

TEST(Influence, SelfCoefficientOfSquareIsLoveValue) {
  // integral of dA/r over a square of side a from its centre = 4 a ln(1 + sqrt 2); A_nn = (1-nu)/(pi G) * that.
  const ElasticConstants e = Steel();
  const double a = 1e-3;
  const double expected = (1.0 - e.poisson_ratio) / (kPi * e.shear_modulus_Pa) * 4.0 * a * std::log(1.0 + std::sqrt(2.0));
  EXPECT_NEAR(RectangleNormalInfluence(0.0, 0.0, a, a, e), expected, 1e-12 * expected);
  EXPECT_NEAR(RectangleInfluence(0.0, 0.0, a, a, e).nn, expected, 1e-12 * expected);
}

TEST(Influence, RectangleMatchesQuadratureOfPointKernels) {
  // Combined materials with K != 0 so every coefficient is exercised.
  Material wheel, rail;
  rail.shear_modulus_Pa = 60e9;
  rail.poisson_ratio = 0.22;
  const ElasticConstants e = CombinedElasticConstants(wheel, rail);
  ASSERT_GT(std::fabs(e.difference_parameter), 1e-3);
  const double dx = 0.8e-3, ds = 1.3e-3;
  const double offsets[][2] = {{2.1e-3, 0.7e-3}, {-1.7e-3, 2.4e-3}, {0.0, -3.0e-3}, {5e-3, -4e-3}};
  for (const auto& o : offsets) {
    const double X = o[0], Y = o[1];
    const HalfSpaceInfluence rect = RectangleInfluence(X, Y, dx, ds, e);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double q = Quadrature(
            [&](double xp, double sp) { return PointInfluence(X - xp, Y - sp, e)(i, j); }, dx, ds, 4);
        const double scale = std::fabs(rect.nn);
        EXPECT_NEAR(rect(i, j), q, 1e-7 * scale) << "component " << i << j << " at " << X << "," << Y;
      }
    const double coupling =
        Quadrature([&](double xp, double sp) { return (Y - sp) / ((X - xp) * (X - xp) + (Y - sp) * (Y - sp)); },
                   dx, ds, 4);
    EXPECT_NEAR(RectangleCouplingIntegral(X, Y, dx, ds), coupling, 1e-9 * std::fabs(coupling) + 1e-12);
  }
}

TEST(Influence, FarFieldTendsToPointKernelTimesArea) {
  const ElasticConstants e = Steel();
  const double dx = 0.1e-3, ds = 0.2e-3;
  const double X = 30e-3, Y = 40e-3;  // r = 50 mm, 250x the element size
  const HalfSpaceInfluence rect = RectangleInfluence(X, Y, dx, ds, e);
  const HalfSpaceInfluence point = PointInfluence(X, Y, e);
  EXPECT_NEAR(rect.nn, point.nn * dx * ds, 1e-5 * point.nn * dx * ds);
  EXPECT_NEAR(rect.xx, point.xx * dx * ds, 1e-5 * point.xx * dx * ds);
  EXPECT_NEAR(rect.xs, point.xs * dx * ds, 1e-4 * std::fabs(point.xs) * dx * ds);
}

TEST(Influence, SymmetriesOfTheHalfSpace) {
  const ElasticConstants e = Steel();
  const double dx = 0.3e-3, ds = 0.5e-3, X = 0.7e-3, Y = 1.1e-3;
  const HalfSpaceInfluence a = RectangleInfluence(X, Y, dx, ds, e);
  const HalfSpaceInfluence b = RectangleInfluence(-X, Y, dx, ds, e);
  const HalfSpaceInfluence c = RectangleInfluence(X, -Y, dx, ds, e);
  EXPECT_DOUBLE_EQ(a.nn, b.nn);
  EXPECT_DOUBLE_EQ(a.nn, c.nn);
  EXPECT_NEAR(a.xs, -b.xs, 1e-15);  // odd in x and in s
  EXPECT_NEAR(a.xs, -c.xs, 1e-15);
  // Identical materials: no normal-tangential coupling.
  EXPECT_EQ(a.xn, 0.0);
  EXPECT_EQ(a.sn, 0.0);
  // Swapping the roles of x and s swaps xx and ss.
  const HalfSpaceInfluence t = RectangleInfluence(Y, X, ds, dx, e);
  EXPECT_NEAR(t.xx, a.ss, 1e-12 * a.ss);
  EXPECT_NEAR(t.ss, a.xx, 1e-12 * a.xx);
  // Combined constants of two equal bodies equal the body's own.
  EXPECT_DOUBLE_EQ(e.shear_modulus_Pa, Material{}.shear_modulus_Pa);
  EXPECT_NEAR(e.poisson_ratio, Material{}.poisson_ratio, 1e-15);
  EXPECT_EQ(e.difference_parameter, 0.0);
}

TEST(Influence, BlancoCorrectionStructureForEqualMaterials) {
  // docs/physics-reference.md §4.3: with K = 0, B_nn = A_nn cos, B_ns = A_nn sin, B_sn = -A_ss sin, B_xx = A_xx.
  const ElasticConstants e = Steel();
  const double alpha = 0.3;
  const HalfSpaceInfluence a = RectangleInfluence(0.4e-3, -0.9e-3, 0.2e-3, 0.25e-3, e);
  const ConformalInfluence b = BlancoCorrected(a, alpha);
  EXPECT_NEAR(b(2, 2), a.nn * std::cos(alpha), 1e-15);
  EXPECT_NEAR(b(2, 1), a.nn * std::sin(alpha), 1e-15);
  EXPECT_NEAR(b(1, 2), -a.ss * std::sin(alpha), 1e-15);
  EXPECT_EQ(b(0, 0), a.xx);
  EXPECT_NEAR(BlancoNormalRectangle(0.4e-3, -0.9e-3, 0.2e-3, 0.25e-3, alpha, e), b.nn(), 1e-18);
  // Zero rotation gives back the half-space.
  const ConformalInfluence b0 = BlancoCorrected(a, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(b0(i, j), a(i, j));
}

TEST(Influence, BlancoVersionThreeRotatesTheDisplacementRows) {
  const ElasticConstants e = Steel();
  const double alpha = -0.4;
  const HalfSpaceInfluence a = RectangleInfluence(-0.6e-3, 0.8e-3, 0.2e-3, 0.25e-3, e);
  const ConformalInfluence v1 = BlancoCorrected(a, alpha);
  const ConformalInfluence v3 = BlancoCorrected(a, alpha, BlancoVersion::RotatedRows);
  // K = 0: the same B_nn; B_ns differs (A_nn sin in version 1, A_ss sin in version 3).
  EXPECT_NEAR(v3.nn(), v1.nn(), 1e-18);
  EXPECT_NEAR(v3(2, 1), a.ss * std::sin(alpha), 1e-18);
  EXPECT_NEAR(v1(2, 1), a.nn * std::sin(alpha), 1e-18);
  EXPECT_NEAR(v3(1, 2), -a.nn * std::sin(alpha), 1e-18);
  // Version 3 is a rotation of the rows: the s-n block keeps its determinant.
  const double det_a = a.ss * a.nn - a.ns() * a.sn;
  EXPECT_NEAR(v3(1, 1) * v3(2, 2) - v3(1, 2) * v3(2, 1), det_a, 1e-12 * std::fabs(det_a));
}

TEST(Influence, PaperSingleBodyCouplingVariant) {
  const ElasticConstants e = Steel();
  const double nu = e.poisson_ratio;
  EXPECT_NEAR(CouplingParameter(ConformalCoupling::PaperSingleBody, e), (1 - 2 * nu) / (2 * (1 - nu)), 1e-15);
  EXPECT_NEAR(CouplingParameter(ConformalCoupling::PaperSingleBody, e), 0.30555555555555, 1e-12);
  // Point form: paper 003 eq. (5) x2 = [cos(a)(1-nu)/r + sin(a) K (s_J - s_I)/r^2] / (pi G).
  const double x = 0.3e-3, s = -0.5e-3, alpha = 0.2, r = std::hypot(x, s), K = 0.30555555555555556;
  const double paper = (std::cos(alpha) * (1 - nu) / r + std::sin(alpha) * K * (-s) / (r * r)) /
                       (kPi * e.shear_modulus_Pa);
  EXPECT_NEAR(BlancoNormalPoint(x, s, alpha, e, ConformalCoupling::PaperSingleBody), paper, 1e-12 * paper);
  // Rectangle form integrates the point form.
  const double dx = 0.1e-3, ds = 0.2e-3, X = 0.9e-3, Y = -1.3e-3;
  const double q = Quadrature(
      [&](double xp, double sp) {
        return BlancoNormalPoint(X - xp, Y - sp, alpha, e, ConformalCoupling::PaperSingleBody);
      },
      dx, ds, 4);
  EXPECT_NEAR(BlancoNormalRectangle(X, Y, dx, ds, alpha, e, ConformalCoupling::PaperSingleBody), q, 1e-8 * q);
  // For equal materials the default differs from the paper variant only by the coupling term.
  EXPECT_NE(BlancoNormalRectangle(X, Y, dx, ds, alpha, e), BlancoNormalRectangle(X, Y, dx, ds, alpha, e,
                                                                                ConformalCoupling::PaperSingleBody));
}

TEST(Influence, BadInputThrows) {
  const ElasticConstants e = Steel();
  EXPECT_THROW(RectangleNormalInfluence(std::nan(""), 0.0, 1e-3, 1e-3, e), InputError);
  EXPECT_THROW(RectangleInfluence(0.0, 0.0, -1e-3, 1e-3, e), InputError);
  EXPECT_THROW(BlancoCorrected(HalfSpaceInfluence{}, INFINITY), InputError);
  Material bad;
  bad.poisson_ratio = 0.6;
  EXPECT_THROW(CombinedElasticConstants(bad), InputError);
}

}  // namespace
}  // namespace conforma
