#pragma once
// SDEC reduction (KBTNH, Piotrowski, Liu & Bruni 2017; core paper 003 §4.2, Fig. 6; docs/physics-reference.md §6): a
// non-elliptic, non-symmetric, curved contact patch given as strips along s^r (each with a contact length
// 2 c_j along x^r) becomes a simplified double elliptical contact: two half-ellipses with a common longitudinal
// semi-axis a, lateral semi-axes b_neg (towards -s) and b_pos (towards +s), b = (b_neg + b_pos) / 2, with
//     a = sqrt(A_c / pi * W3 / (W1 + W2)),   b = sqrt(A_c / pi * (W1 + W2) / W3)          (paper 003, §4.2)
// so that pi a b = A_c (area kept) and a / b = W3 / (W1 + W2) (length/width ratio kept).
//
// How W1, W2, W3 are measured (decision; the paper does not define them, docs/physics-reference.md §6.2 gives the
// likely meaning, which is followed):
//   * A_c = sum_j 2 c_j ds_j over the strips in contact (curved surface area, arc length along s^r);
//   * the LONGEST STRIP line s*: the strip of largest half-length c_max, refined by the vertex of the parabola
//     through it and its two neighbours (when both exist and are in contact); W3 = 2 c_max(s*) = the length of
//     the patch along x^r at s*;
//   * W1 = s* - s_lo and W2 = s_hi - s*, the widths (along s^r) on the negative and positive side of s*, where
//     s_lo and s_hi are the outer edges of the first and last strips in contact (s_j -/+ ds_j / 2).
//   The asymmetry is kept by splitting 2b in the ratio W1 : W2:  b_neg = 2 b W1 / (W1 + W2),
//   b_pos = 2 b W2 / (W1 + W2); psi = (b_pos - b_neg) / (2 b) (CONTACT's SDEC asymmetry,
//   docs/physics-reference.md §6.1).
//   For an exactly elliptic patch W3 = 2a, W1 = W2 = b and the formulas return the ellipse.
//
// Creep coefficients of the SDEC (decision): Kalker's C_ij at the SDEC ratio a / b (KalkerCoefficients), i.e. the
// area-equivalent ellipse; the asymmetry enters through the lever arm of the SDEC area centroid, which sits at
//     y_c = s* + 2 (b_pos^2 - b_neg^2) / (3 pi b)
// (centroids 4 b_pos / (3 pi), -4 b_neg / (3 pi) of the two half-ellipses): the linear-theory forces of a spin
// phi about a centre s_o are Kalker's about the centroid, with the longitudinal creepage shifted by the rigid
// slip of the spin there: F_x = -G c^2 C11 (xi - phi (y_c - s_o)), F_y = -G c^2 C22 eta - G c^3 C23 phi.
// The FASTSIM flexibilities of the SDEC are KalkerFlexibilities(a, b, C_ij(a/b)) (docs/physics-reference.md §2.3,
// §3.4); the curved-patch solver applies them on the REAL patch, where the asymmetry acts through the real strip
// positions. The KBTNH tables themselves (non-Hertzian C_ij as a function of psi) are not available
// (docs/physics-reference.md §6.3) and are not used.
#include <vector>

#include "conforma/fastsim.hpp"
#include "conforma/kalker.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/material.hpp"

namespace conforma {

// One strip of a patch for the reduction (KpStrip carries the same fields).
struct SdecStrip {
  double s_m = 0.0;            // strip centre along s^r, m
  double ds_m = 0.0;           // strip width along s^r, m, >= 0
  double x_centre_m = 0.0;     // centre of the strip's contact length, m
  double half_length_m = 0.0;  // c_j, m, >= 0 (0 = strip not in contact)
};

// Ok: at least one strip with c_j > 0 and ds_j > 0 (every field of SdecResult filled);
// NoContact: none (every field 0).
enum class SdecStatus { Ok, NoContact };
const char* to_string(SdecStatus status);  // "ok", "no_contact"

// The SDEC of a patch (docs/physics-reference.md §6.5). Lengths in m along the patch coordinates of the strips.
struct SdecResult {
  SdecStatus status = SdecStatus::NoContact;  // see SdecStatus
  double area_m2 = 0.0;            // A_c, m^2
  double w1_m = 0.0, w2_m = 0.0;   // widths on the -s and +s side of the longest strip line, m, >= 0
  double w3_m = 0.0;               // longest contact length along x^r, 2 c_max(s*), m
  double a_m = 0.0, b_m = 0.0;     // SDEC semi-axes (paper 003 §4.2), m; pi a b = A_c
  double b_neg_m = 0.0, b_pos_m = 0.0;  // lateral semi-axes of the -s and +s half-ellipses, m; sum 2 b
  double asymmetry = 0.0;          // psi = (b_pos - b_neg) / (2 b), dimensionless, in [-1, 1]
  double longest_strip_s_m = 0.0;  // s*, m (parabola vertex through the longest strip and its neighbours)
  double longest_strip_x_m = 0.0;  // x centre of the longest strip, m
  double centroid_s_m = 0.0;       // y_c of the SDEC area, m
  CreepCoefficients coefficients;  // Kalker at a / b
  FastsimFlexibilities flexibilities;  // KalkerFlexibilities(a, b, coefficients, G), m/Pa
};

// Throws InputError for NaN, negative widths or half-lengths.
SdecResult ReduceToSdec(const std::vector<SdecStrip>& strips, const Material& material);
SdecResult ReduceToSdec(const KpResult& normal, const Material& material);

// Linear-theory forces of the SDEC (see the header comment); the spin centre at s_o = spin_centre_s_m.
struct SdecLinearForces {
  double fx_N = 0.0, fy_N = 0.0;  // linear-theory creep forces on the wheel, N; 0 when the SDEC is not Ok
};
SdecLinearForces SdecLinearCreepForces(const SdecResult& sdec, const FastsimCreepages& creepages,
                                       double spin_centre_s_m, double shear_modulus_Pa);

}  // namespace conforma
