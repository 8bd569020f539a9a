#pragma once
// Influence coefficients of the elastic half-space and their conformal (Blanco-Lorenzo) correction.
//
// Indices: x = rolling direction, s (= y of the half-space) = lateral / curvilinear rail profile direction,
// n = normal. A_ij is the COMBINED displacement difference of the two bodies in direction i at an
// observation point I per unit traction in direction j at a load point J (Kalker's convention, both
// bodies together: docs/physics-reference.md §0 and §10.2). Offsets are always OBSERVATION minus LOAD:
// X = x_I - x_J, Y = s_I - s_J.
//
// Two forms:
//   * Rectangle coefficients (Love 1929; Kalker 1990; docs/physics-reference.md §10.2): displacement at the
//     observation point per unit uniform traction (Pa) on a dx * ds rectangle centred at the load point,
//     unit m/Pa. Evaluated with the corner double difference [[f]] in the numerically stable asinh form.
//   * Point kernels (Boussinesq-Cerruti, docs/physics-reference.md §4.3): displacement per unit point force,
//     unit m/N, singular at r = 0, for use by quadrature (KP strip integrals).
//
// Conformal correction (docs/physics-reference.md §4.2, CONTACT "version 1 = original Blanco formulas"; paper 003
// eq. 2): for a relative rotation alpha = alpha_J - alpha_I of the local normals,
//     B_ix = A_ix,   B_is = A_is cos(alpha) + A_in sin(alpha),   B_in = A_in cos(alpha) - A_is sin(alpha).
// Version 1 is chosen because it is what paper 003 eq. (2) writes (B_nn cos - B_nt sin). CONTACT's groove
// reference (shared data; groove_li.inp has IF_VAR = 3) used version 3, which rotates the displacement rows
// (B_nn = A_sn sin + A_nn cos, B_ns = A_ss sin + A_ns cos); for identical steels (K = 0) both give the same
// B_nn = A_nn cos(alpha), which is all a normal-only solver uses. They differ in B_ns (version 1: A_nn sin,
// version 3: A_ss sin), i.e. in how lateral tractions feed the normal displacement.
//
// Coupling term. With the physically consistent COMBINED two-body coefficients the n-s coupling is
// A_ns = (K/pi G) * Y / r^2 with Kalker's difference parameter K (0 for identical materials), so
//     B_nn = A_nn cos(alpha) - A_ns sin(alpha) = A_nn cos(alpha)                (default, K = 0)
// and the main new coupling is B_sn = -A_ss sin(alpha) (docs/physics-reference.md §4.3). Paper 003 eqs. (3)/(5)
// instead keep a non-zero coupling "K s^r / r^2" built from single-body Cerruti coefficients; that variant
// is available as ConformalCoupling::PaperSingleBody with the quasi-identity parameter
// K_q = (1 - 2 nu) / (2 (1 - nu)) (the single-body ratio of normal-from-tangential to normal-from-normal
// point responses, docs/physics-reference.md §4.3). It is not the default: for two bodies of the same steel the
// single-body couplings of wheel and rail cancel, so the extra term is not physical in the combined
// formulation. Its sign follows the same convention as version 1: -sin(alpha_J - alpha_I) * K_q (s_I - s_J)/r^2.
#include "conforma/material.hpp"

namespace conforma {

// Combined two-body elastic constants (docs/physics-reference.md §0; CONTACT combin_mater).
struct ElasticConstants {
  double shear_modulus_Pa = 82.0e9;    // combined G:  1/G = (1/G1 + 1/G2) / 2
  double poisson_ratio = 0.28;         // combined nu: nu/G = (nu1/G1 + nu2/G2) / 2
  double difference_parameter = 0.0;   // Kalker's K = G/4 [(1-2nu1)/G1 - (1-2nu2)/G2]; 0 for equal materials
};
// Both bodies of the same material (K = 0). Validates the material (InputError).
ElasticConstants CombinedElasticConstants(const Material& both_bodies);
// Body 1 and body 2 of different materials. Validates both (InputError).
ElasticConstants CombinedElasticConstants(const Material& body1, const Material& body2);

// Half-space coefficients for one offset. nn, xx, ss, xs (= sx), xn, sn; the antisymmetric partners are
// A_nx = -A_xn and A_ns = -A_sn (docs/physics-reference.md §10.2).
struct HalfSpaceInfluence {
  double nn = 0.0;
  double xx = 0.0;
  double ss = 0.0;
  double xs = 0.0;
  double xn = 0.0;
  double sn = 0.0;
  double sx() const { return xs; }
  double nx() const { return -xn; }
  double ns() const { return -sn; }
  // Component by index, 0 = x, 1 = s, 2 = n: displacement i per traction j.
  double operator()(int i, int j) const;
};

// Uniform traction on the rectangle [-dx/2, dx/2] x [-ds/2, ds/2] around the load point; observation at
// offset (X, Y) from its centre. m/Pa. Throws InputError for non-finite offsets or non-positive sizes.
HalfSpaceInfluence RectangleInfluence(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                                      const ElasticConstants& elastic);
// Only A_nn of the rectangle (the hot path of normal solvers). m/Pa.
double RectangleNormalInfluence(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                                const ElasticConstants& elastic);
// Rectangle integral of (s_I - s_J') / r^2 over the load rectangle, i.e. [[j6]] of §10.2 (unit m): the
// shape of the n-s coupling, A_ns = (K / (pi G)) * RectangleCouplingIntegral.
double RectangleCouplingIntegral(double offset_x_m, double offset_s_m, double dx_m, double ds_m);

// Point kernels per unit point force at offset (x, s) = observation - load, r > 0. m/N.
// A_nn = (1-nu)/(pi G r), A_xx = [(1-nu)/r + nu x^2/r^3]/(pi G), A_xs = nu x s/(pi G r^3),
// A_xn = -K x/(pi G r^2), A_sn = -K s/(pi G r^2) (docs/physics-reference.md §4.3, two-body combination).
// Returns all zeros at r = 0 (the singular point is the caller's business).
HalfSpaceInfluence PointInfluence(double offset_x_m, double offset_s_m, const ElasticConstants& elastic);

// Which n-s coupling the conformal correction uses (see the header comment).
enum class ConformalCoupling {
  CombinedBodies,   // default: Kalker's K of the combined bodies (0 for the same steel)
  PaperSingleBody,  // paper 003 eqs. (3)/(5): K_q = (1 - 2 nu) / (2 (1 - nu))
};
const char* to_string(ConformalCoupling coupling);
// The K used in the coupling term for the chosen variant.
double CouplingParameter(ConformalCoupling coupling, const ElasticConstants& elastic);

// Blanco-Lorenzo corrected 3x3 coefficients (indices 0 = x, 1 = s, 2 = n), version 1 (§4.2):
// relative normal rotation alpha = alpha_J - alpha_I (rad).
struct ConformalInfluence {
  double b[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  double operator()(int i, int j) const { return b[i][j]; }
  double nn() const { return b[2][2]; }
};
enum class BlancoVersion {
  Original = 1,     // §4.2 version 1 (default): rotate the load at J (columns)
  RotatedRows = 3,  // §4.2 version 3 (CONTACT IF_VAR = 3): B_sj = A_sj cos - A_nj sin, B_nj = A_sj sin + A_nj cos
};
ConformalInfluence BlancoCorrected(const HalfSpaceInfluence& half_space, double relative_rotation_rad,
                                   BlancoVersion version = BlancoVersion::Original);

// Corrected normal-normal rectangle coefficient B_nn = A_nn cos(alpha) - A_ns sin(alpha) with the coupling
// of the chosen variant (paper 003 eq. 2 / eq. 5 integrated over the rectangle). m/Pa.
double BlancoNormalRectangle(double offset_x_m, double offset_s_m, double dx_m, double ds_m,
                             double relative_rotation_rad, const ElasticConstants& elastic,
                             ConformalCoupling coupling = ConformalCoupling::CombinedBodies);
// Point-kernel form of the same (paper 003 eq. 5 integrand, times 2 for the two bodies). m/N.
double BlancoNormalPoint(double offset_x_m, double offset_s_m, double relative_rotation_rad,
                         const ElasticConstants& elastic,
                         ConformalCoupling coupling = ConformalCoupling::CombinedBodies);

}  // namespace conforma
