#pragma once
// FASTSIM, Kalker's simplified theory of rolling contact (Kalker 1982; docs/physics-reference.md §2.3-2.4), with
// three flexibilities L1, L2, L3 and an elliptic or parabolic traction bound.
//
// Sign convention (Kalker's, as CONTACT): results are the tractions and forces ON BODY 1 (the wheel); in the
// linear limit F_x = -G c^2 C11 xi, F_y = -G c^2 C22 eta - G c^3 C23 phi (see kalker.hpp). Rolling is in +x:
// material enters the patch at the leading edge x_lead (the larger x) and leaves at x_trail.
// Slip s = (s_x, s_y) is the dimensionless slip (slip velocity / rolling speed); in slip elements the traction
// opposes it. The frictional power density is |p . s| V.
//
// Two layers:
//  * the strip core SolveFastsimStrips works on any strip patch: each strip has its own lateral position and
//    width, its own leading and trailing edge and number of elements, and every element carries its own
//    traction-bound pressure p_n (and optionally its own friction coefficient); the flexibilities are inputs.
//    The non-Hertzian (SDEC, KP) and curved-patch solvers build a FastsimPatch and call this core.
//  * SolveFastsimHertz builds the elliptic Hertz mesh (ny strips, nx elements each, Kalker's elliptic mesh),
//    takes C_ij from KalkerCoefficients and L_i from KalkerFlexibilities, and calls the core.
#include <vector>

#include "conforma/kalker.hpp"
#include "conforma/material.hpp"

namespace conforma {

// Default FASTSIM discretisation (elements per strip; strips of the Hertz ellipse): the one declaration every
// options struct takes its default from.
constexpr int kDefaultFastsimElements = 30;

// Flexibilities [m/Pa] of the simplified theory.
struct FastsimFlexibilities {
  double L1 = 0.0;  // longitudinal creepage, m/Pa, > 0
  double L2 = 0.0;  // lateral creepage, m/Pa, > 0
  double L3 = 0.0;  // spin, m/Pa, > 0
};
// §2.3 exact forms (CONTACT simpflex): L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G).
// With them FASTSIM reproduces Kalker's linear theory as creepage -> 0.
FastsimFlexibilities KalkerFlexibilities(double a_m, double b_m, const CreepCoefficients& coefficients,
                                         double shear_modulus_Pa);

struct FastsimCreepages {
  double xi = 0.0;         // longitudinal creepage [-]
  double eta = 0.0;        // lateral creepage [-]
  double phi_per_m = 0.0;  // spin creepage [1/m]
};

// CONTACT's blending of the three flexibilities towards one combined flexibility at large creepage
// (Vollebregt & Voltr 2023; CONTACT m_hertz.f90 simpflex, docs/physics-reference.md §2.3):
//   q = phi (pi a^2/4)/(8a/3),  L_crss = (xi^2 + eta^2 + q^2) / (xi^2/L1 + eta^2/L2 + q^2/L3)
//   ch_xi = mu N/(c^2 G C11), ch_eta = mu N/(c^2 G C22), ch_phi = mu N/(c^3 G C23)
//   f = sqrt((xi^2 + eta^2 + phi^2)/(ch_xi^2 + ch_eta^2 + ch_phi^2)),  w = min(1, f/3)
//   L_i <- (1 - w) L_i + w L_crss
// (CONTACT's code includes phi and ch_phi in f; §2.3 prints f without them. The code is followed here;
// phi is taken per metre and ch_phi per metre, so f is dimensionally mixed exactly as in CONTACT, where
// both are per mm — hence phi and ch_phi are converted to 1/mm inside to reproduce CONTACT's weight.)
FastsimFlexibilities BlendedFlexibilities(const FastsimFlexibilities& three, double a_m, double b_m,
                                          const CreepCoefficients& coefficients, double shear_modulus_Pa,
                                          double friction_coefficient, double normal_force_N,
                                          const FastsimCreepages& creepages);

// One strip of a general patch: elements are numbered from the leading edge (i = 0) to the trailing edge,
// element i spans [x_lead - (i+1) dx, x_lead - i dx] with dx = (x_lead - x_trail) / n_elements.
struct FastsimStrip {
  double y_m = 0.0;       // lateral position of the strip centre line, m
  double width_m = 0.0;   // dy, m, >= 0
  double x_lead_m = 0.0;  // leading edge (larger x), m
  double x_trail_m = 0.0; // trailing edge, m, <= x_lead_m
  int first_element = 0;  // index of element 0 of this strip in the element arrays
  int n_elements = 0;     // elements of the strip, >= 0 (0: the strip is skipped)
};

struct FastsimPatch {
  std::vector<FastsimStrip> strips;
  // Per element (size = total elements): the pressure that bounds the traction, |p_t| <= mu p_n.
  std::vector<double> bound_pressure_Pa;
  // Optional per-element friction coefficient; empty = use the scalar friction coefficient everywhere.
  std::vector<double> friction_coefficient;
  int elements() const { return static_cast<int>(bound_pressure_Pa.size()); }
};

enum class TractionBound {
  Elliptic,   // Hertz pressure (3N/(2 pi a b)) sqrt(1 - x^2/a^2 - y^2/b^2); CONTACT's advice
  Parabolic,  // Kalker's original (2N/(pi a b)) (1 - x^2/a^2 - y^2/b^2)
};

enum class FastsimMarching {
  // Traction at the element centre, the rigid-slip increment integrated exactly from the previous centre
  // (half a step for the first element): exact in adhesion, forces second-order in the element size.
  CentreExact,
  // Kalker's / CONTACT's classic scheme: a full step dx with the rigid slip at the element centre, starting from
  // p = 0 before the first element. First order: it over-estimates the adhesion traction by (1 + 1/n) per strip.
  // Use it only to reproduce CONTACT's FASTSIM numbers.
  ClassicFullStep,
};

struct FastsimOptions {
  TractionBound bound = TractionBound::Elliptic;  // used by SolveFastsimHertz (the core takes p_n as given)
  bool blend_flexibilities = false;               // SolveFastsimHertz: apply BlendedFlexibilities (CONTACT)
  // Marching scheme along a strip; read by the strip core, so by every FASTSIM of the project (Hertz, SDEC on the
  // KP patch, curved-patch). Default CentreExact.
  FastsimMarching marching = FastsimMarching::CentreExact;
};

enum class FastsimStatus {
  Ok,         // at least one element in adhesion
  FullSlip,   // no element in adhesion (a normal outcome at large creepage)
  NoContact,  // no elements or zero load
};
const char* to_string(FastsimStatus status);  // "ok", "full_slip", "no_contact"

// The tangential solution on a strip patch (docs/physics-reference.md §2.4). Every field is filled when the status
// is Ok or FullSlip; with NoContact the per-element vectors are empty (or sized to a patch of 0 elements) and every
// total is 0.
struct FastsimResult {
  FastsimStatus status = FastsimStatus::NoContact;  // see FastsimStatus
  // Per element, in the element order of the patch.
  std::vector<double> x_m, y_m, area_m2;          // element centre (m, patch frame) and area (m^2)
  std::vector<double> px_Pa, py_Pa;               // tangential traction on body 1, Pa; |p| <= mu p_n
  std::vector<double> sx, sy;                     // dimensionless slip (slip velocity / V; 0 in adhesion)
  std::vector<unsigned char> in_slip;             // 1 = slip element, 0 = adhesion
  double fx_N = 0.0, fy_N = 0.0;                  // total tangential force on body 1, N
  double mz_Nm = 0.0;                             // spin moment sum (x p_y - y p_x) dA about the patch origin, N m
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0;  // summed areas of the adhesion / slip elements, m^2
  double frictional_power_W = 0.0;                // sum |p . s| V dA, W; 0 unless a rolling speed is given
};

// Strip core. Reuses the capacity of *result (no allocation when it already holds enough elements).
// Throws InputError for inconsistent strips, negative/NaN bound pressure or flexibility, negative friction.
void SolveFastsimStrips(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                        const FastsimCreepages& creepages, double friction_coefficient,
                        double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result);

// Totals of one strip (as FastsimResult's, over the strip's elements in order).
struct FastsimStripTotals {
  double fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0, adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
};

// Strip core with creepages per strip (creepages.size() == patch.strips.size()): every strip as SolveFastsimStrips
// on that strip alone with its creepages (the same arithmetic, element by element), the per-element fields in
// *result and each strip's totals in *strip_totals (result's totals are left 0, its status NoContact: the caller
// sums the strips). Strips are marched two at a time (independent recurrences), for speed only.
void SolveFastsimStripsEach(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                            const std::vector<FastsimCreepages>& creepages, double friction_coefficient,
                            double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result,
                            std::vector<FastsimStripTotals>* strip_totals);

// The Hertz ellipse and its load as SolveFastsimHertz takes them; InputError for a value out of the ranges given.
struct FastsimHertzInput {
  double a_m = 0.0;  // semi-axis along x (rolling), m, > 0
  double b_m = 0.0;  // semi-axis along y, m, > 0
  double normal_force_N = 0.0;  // normal load N, N, >= 0 (0: NoContact)
  FastsimCreepages creepages;   // xi, eta (-), phi (1/m), finite
  double friction_coefficient = 0.3;  // mu (-), >= 0, the same at every element
  Material material;                  // G and nu give C_ij and the flexibilities L_i
  int nx = kDefaultFastsimElements;  // elements per strip, >= 1
  int ny = kDefaultFastsimElements;  // strips, >= 1
  double rolling_speed_m_per_s = 0.0;  // V, m/s, >= 0; > 0 to get the frictional power
};

// Hertz patch convenience entry. The traction bound per element is the exact mean of the chosen pressure law
// along x over the element, taken at the strip centre line, scaled so the discrete load equals N exactly.
FastsimResult SolveFastsimHertz(const FastsimHertzInput& input, const FastsimOptions& options);
// Same, reusing *patch and *result (for loops over many patches without allocation).
void SolveFastsimHertz(const FastsimHertzInput& input, const FastsimOptions& options, FastsimPatch* patch,
                       FastsimResult* result);
// Its two halves, for another strip kernel on the same mesh (the slip-dependent friction of fastsim_ext):
// the mesh and the traction bound scaled to the load (an empty patch for N = 0; InputError as above), and the
// flexibilities (Kalker's three, blended at input.friction_coefficient when options.blend_flexibilities).
void BuildFastsimHertzPatch(const FastsimHertzInput& input, const FastsimOptions& options, FastsimPatch* patch);
FastsimFlexibilities FastsimHertzFlexibilities(const FastsimHertzInput& input, const FastsimOptions& options);
// The same with KalkerCoefficients(a_m / b_m, material.poisson_ratio) already at hand.
FastsimFlexibilities FastsimHertzFlexibilities(const FastsimHertzInput& input, const FastsimOptions& options,
                                               const CreepCoefficients& coefficients);

}  // namespace conforma
