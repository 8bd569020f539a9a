// Half-space influence coefficients (Love 1929; Kalker 1990) and the Blanco-Lorenzo correction.
// Formulas: docs/physics-reference.md §0 (combined constants), §4.2-4.3 (correction, point kernels), §10.2
// (rectangle coefficients); paper 003 eqs. (2), (3), (5).
#include "conforma/influence.hpp"

#include <cmath>

#include "conforma/error.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Primitives F with d^2F / (dxi deta) = kernel, written so that terms depending on one variable only
// (which cancel in the corner double difference) are dropped and no ln 0 occurs (§10.2).
// xi * asinh(eta / |xi|) -> 0 for xi -> 0.
double XiAsinh(double xi, double eta) { return xi == 0.0 ? 0.0 : xi * std::asinh(eta / std::fabs(xi)); }

// j3 = eta ln(xi + r) + xi ln(eta + r)  ->  kernel 1/r
double PrimitiveInverseDistance(double xi, double eta) { return XiAsinh(xi, eta) + XiAsinh(eta, xi); }
// j1 = eta ln(xi + r)  ->  kernel xi^2 / r^3
double PrimitiveJ1(double xi, double eta) { return XiAsinh(eta, xi); }
// j2 = xi ln(eta + r)  ->  kernel eta^2 / r^3
double PrimitiveJ2(double xi, double eta) { return XiAsinh(xi, eta); }
// j4 = -r  ->  kernel xi eta / r^3
double PrimitiveJ4(double xi, double eta) { return -std::hypot(xi, eta); }
// j5 = eta ln r + xi atan(eta / xi)  ->  kernel xi / r^2
double PrimitiveJ5(double xi, double eta) {
  const double r = std::hypot(xi, eta);
  const double log_term = eta == 0.0 ? 0.0 : eta * std::log(r);
  const double atan_term = xi == 0.0 ? 0.0 : xi * std::atan(eta / xi);
  return log_term + atan_term;
}
// j6 = xi ln r + eta atan(xi / eta)  ->  kernel eta / r^2
double PrimitiveJ6(double xi, double eta) { return PrimitiveJ5(eta, xi); }

// Corner double difference [[f]] of §10.2 for the rectangle of half sizes (h, k) at offset (X, Y).
template <class F>
double CornerDifference(F f, double X, double Y, double h, double k) {
  return f(X + h, Y + k) - f(X + h, Y - k) - f(X - h, Y + k) + f(X - h, Y - k);
}

void CheckRectangle(double offset_x_m, double offset_s_m, double dx_m, double ds_m) {
  require_finite(offset_x_m, "influence offset x");
  require_finite(offset_s_m, "influence offset s");
  require_positive(dx_m, "influence element size dx");
  require_positive(ds_m, "influence element size ds");
}

}  // namespace

ElasticConstants CombinedElasticConstants(const Material& both_bodies) {
  return CombinedElasticConstants(both_bodies, both_bodies);
}

// docs/physics-reference.md §0 (CONTACT combin_mater; K with the minus sign of the code).
ElasticConstants CombinedElasticConstants(const Material& body1, const Material& body2) {
  body1.validate();
  body2.validate();
  const double g1 = body1.shear_modulus_Pa, g2 = body2.shear_modulus_Pa;
  const double n1 = body1.poisson_ratio, n2 = body2.poisson_ratio;
  ElasticConstants c;
  c.shear_modulus_Pa = 2.0 / (1.0 / g1 + 1.0 / g2);
  c.poisson_ratio = c.shear_modulus_Pa * 0.5 * (n1 / g1 + n2 / g2);
  c.difference_parameter = 0.25 * c.shear_modulus_Pa * ((1.0 - 2.0 * n1) / g1 - (1.0 - 2.0 * n2) / g2);
  return c;
}

double HalfSpaceInfluence::operator()(int i, int j) const {
  const double m[3][3] = {{xx, xs, xn}, {sx(), ss, sn}, {nx(), ns(), nn}};
  if (i < 0 || i > 2 || j < 0 || j > 2) throw InputError("HalfSpaceInfluence index out of range 0..2");
  return m[i][j];
}

// §10.2: A_nn = (1-nu)/pi [[j3]], A_xx = 1/pi [[j1 + (1-nu) j2]], A_yy = 1/pi [[j2 + (1-nu) j1]],
// A_xy = nu/pi [[j4]], A_xn = -K/pi [[j5]], A_yn = -K/pi [[j6]], all divided by G.
HalfSpaceInfluence RectangleInfluence(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                                      const ElasticConstants& elastic) {
  CheckRectangle(offset_x_m, offset_s_m, dx_m, ds_m);
  const double X = offset_x_m, Y = offset_s_m, h = 0.5 * dx_m, k = 0.5 * ds_m;
  const double nu = elastic.poisson_ratio;
  const double scale = 1.0 / (kPi * elastic.shear_modulus_Pa);
  const double j1 = CornerDifference(PrimitiveJ1, X, Y, h, k);
  const double j2 = CornerDifference(PrimitiveJ2, X, Y, h, k);
  HalfSpaceInfluence a;
  a.nn = scale * (1.0 - nu) * (j1 + j2);  // j3 = j1 + j2
  a.xx = scale * (j1 + (1.0 - nu) * j2);
  a.ss = scale * (j2 + (1.0 - nu) * j1);
  a.xs = scale * nu * CornerDifference(PrimitiveJ4, X, Y, h, k);
  if (elastic.difference_parameter != 0.0) {
    a.xn = -scale * elastic.difference_parameter * CornerDifference(PrimitiveJ5, X, Y, h, k);
    a.sn = -scale * elastic.difference_parameter * CornerDifference(PrimitiveJ6, X, Y, h, k);
  }
  return a;
}

double RectangleNormalInfluence(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                                const ElasticConstants& elastic) {
  CheckRectangle(offset_x_m, offset_s_m, dx_m, ds_m);
  const double j3 =
      CornerDifference(PrimitiveInverseDistance, offset_x_m, offset_s_m, 0.5 * dx_m, 0.5 * ds_m);
  return (1.0 - elastic.poisson_ratio) / (kPi * elastic.shear_modulus_Pa) * j3;
}

double RectangleCouplingIntegral(double offset_x_m, double offset_s_m, double dx_m, double ds_m) {
  CheckRectangle(offset_x_m, offset_s_m, dx_m, ds_m);
  return CornerDifference(PrimitiveJ6, offset_x_m, offset_s_m, 0.5 * dx_m, 0.5 * ds_m);
}

// §4.3, two-body combination.
HalfSpaceInfluence PointInfluence(double offset_x_m, double offset_s_m, const ElasticConstants& elastic) {
  require_finite(offset_x_m, "influence offset x");
  require_finite(offset_s_m, "influence offset s");
  HalfSpaceInfluence a;
  const double x = offset_x_m, s = offset_s_m;
  const double r = std::hypot(x, s);
  if (r == 0.0) return a;
  const double nu = elastic.poisson_ratio, K = elastic.difference_parameter;
  const double scale = 1.0 / (kPi * elastic.shear_modulus_Pa);
  const double r3 = r * r * r;
  a.nn = scale * (1.0 - nu) / r;
  a.xx = scale * ((1.0 - nu) / r + nu * x * x / r3);
  a.ss = scale * ((1.0 - nu) / r + nu * s * s / r3);
  a.xs = scale * nu * x * s / r3;
  a.xn = -scale * K * x / (r * r);
  a.sn = -scale * K * s / (r * r);
  return a;
}

const char* to_string(ConformalCoupling coupling) {
  switch (coupling) {
    case ConformalCoupling::CombinedBodies: return "combined-bodies";
    case ConformalCoupling::PaperSingleBody: return "paper-single-body";
  }
  return "unknown";
}

double CouplingParameter(ConformalCoupling coupling, const ElasticConstants& elastic) {
  if (coupling == ConformalCoupling::PaperSingleBody) {
    const double nu = elastic.poisson_ratio;
    return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));  // quasi-identity parameter, docs/physics-reference.md §4.3
  }
  return elastic.difference_parameter;
}

// §4.2 version 1: B_ix = A_ix, B_is = A_is cos + A_in sin, B_in = A_in cos - A_is sin.
// §4.2 version 3: B_xj = A_xj, B_sj = A_sj cos - A_nj sin, B_nj = A_sj sin + A_nj cos.
ConformalInfluence BlancoCorrected(const HalfSpaceInfluence& a, double relative_rotation_rad, BlancoVersion version) {
  require_finite(relative_rotation_rad, "relative normal rotation alpha");
  const double c = std::cos(relative_rotation_rad), sn = std::sin(relative_rotation_rad);
  ConformalInfluence b;
  for (int k = 0; k < 3; ++k) {
    if (version == BlancoVersion::RotatedRows) {
      b.b[0][k] = a(0, k);
      b.b[1][k] = a(1, k) * c - a(2, k) * sn;
      b.b[2][k] = a(1, k) * sn + a(2, k) * c;
    } else {
      b.b[k][0] = a(k, 0);
      b.b[k][1] = a(k, 1) * c + a(k, 2) * sn;
      b.b[k][2] = a(k, 2) * c - a(k, 1) * sn;
    }
  }
  return b;
}

// Paper 003 eq. (2) integrated over the rectangle: B_nn = A_nn cos(alpha) - A_ns sin(alpha),
// A_ns = -A_sn = (K / (pi G)) [[j6]].
double BlancoNormalRectangle(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                             double relative_rotation_rad, const ElasticConstants& elastic,
                             ConformalCoupling coupling) {
  require_finite(relative_rotation_rad, "relative normal rotation alpha");
  const double a_nn = RectangleNormalInfluence(offset_x_m, offset_s_m, dx_m, ds_m, elastic);
  double b_nn = a_nn * std::cos(relative_rotation_rad);
  const double K = CouplingParameter(coupling, elastic);
  if (K != 0.0) {
    const double a_ns = K / (kPi * elastic.shear_modulus_Pa) *
                        RectangleCouplingIntegral(offset_x_m, offset_s_m, dx_m, ds_m);
    b_nn -= a_ns * std::sin(relative_rotation_rad);
  }
  return b_nn;
}

// Paper 003 eq. (5) integrand (x2 for both bodies): [cos(alpha)(1-nu)/r - sin(alpha) K s/r^2] / (pi G),
// s = s_I - s_J (the paper writes + sin(alpha) K (s_J - s_I) / r^2, the same thing).
double BlancoNormalPoint(double offset_x_m, double offset_s_m, double relative_rotation_rad,
                         const ElasticConstants& elastic, ConformalCoupling coupling) {
  require_finite(relative_rotation_rad, "relative normal rotation alpha");
  const HalfSpaceInfluence a = PointInfluence(offset_x_m, offset_s_m, elastic);
  const double r = std::hypot(offset_x_m, offset_s_m);
  if (r == 0.0) return 0.0;
  const double K = CouplingParameter(coupling, elastic);
  const double a_ns = K * offset_s_m / (kPi * elastic.shear_modulus_Pa * r * r);
  return a.nn * std::cos(relative_rotation_rad) - a_ns * std::sin(relative_rotation_rad);
}

}  // namespace conforma
