#pragma once
// Kik-Piotrowski (KP) normal contact on one PatchGeometry: planar KP (virtual penetration eps = 0.55),
// KPEC (CONTACT's variable-eps correction, exact for elliptic patches) and the conformal extension of
// Distaso et al. 2026 (paper 003 eqs. 2-8: curvilinear rail coordinates x^r, s^r and the Blanco-Lorenzo
// corrected influence function). docs/physics-reference.md §§3, 4, 5, 9.
//
// The solver resamples the patch: it finds the contact range [s_min, s_max] of the virtual interpenetration
// on the input strips (cubic Hermite interpolation of the gap, exact for quadratic gaps), then lays
// strips_across_contact equal strips over exactly that range. On strip j the pressure is the KP semi-ellipse
//     p(x, s_j) = p0 * sqrt(c_j^2 - (x - m_j)^2) / c_norm                        (paper 003 eq. 7)
// with half-length c_j = sqrt(g_j / A_j), centre m_j = x_offset(s_j), c_norm = c at the contact point (KP)
// or the largest half-length (KPEC). p0 follows from the contact condition u_n = delta at the contact point
// (minimum gap), paper 003 eq. 8, with the influence integrals done per strip exactly in x (complete
// elliptic integrals) and by Gauss quadrature in s with the logarithmic singularity subtracted.
// KpPressureRule::StripCollocation (the conformal model's default, docs/physics-reference.md §5.3) instead fits one
// amplitude per strip to the contact condition along the whole patch.
#include <Eigen/Core>
#include <vector>

#include "conforma/conformity.hpp"
#include "conforma/influence.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"

namespace conforma {

enum class KpPenetrationRule {
  ConstantEpsilon,   // Kik & Piotrowski 2008: g = eps * delta - gap (docs/physics-reference.md §3.1)
  VariableEpsilon,   // KPEC, CONTACT m_snorm.f90 (docs/physics-reference.md §3.3)
};

enum class KpInfluence {
  HalfSpace,      // Boussinesq: (1 - nu) / (pi G r), both bodies combined (paper 003 eq. 1)
  BlancoLorenzo,  // paper 003 eqs. 2, 3, 5, 8: [(1 - nu) cos(a) / r + K sin(a) s / r^2] / (pi G), a = alpha_J - alpha_I
};

// How the strips' pressure amplitudes follow from the contact condition (the strip half-lengths c_j always come from
// the virtual penetration rule).
enum class KpPressureRule {
  // Kik & Piotrowski (paper 003 eq. 8): peak_j = p0 c_j / c_norm, one contact condition u_n = delta at the contact
  // point (minimum gap)
  ContactPoint,
  // Strip collocation (issue 15, docs/physics-reference.md §5.3): one amplitude per strip, the contact condition
  // u_n = delta cos(alpha_i) - gap_i at every strip's centre line point (s_i, m_i), as the BEM's (§10.4); negative
  // amplitudes are set to 0 and the rest re-solved
  StripCollocation,
};

enum class KpStatus {
  Ok,                      // contact found inside the given strips: every field of KpResult filled
  NoContact,               // the virtual interpenetration is nowhere positive (approach <= 0 or gap too large)
  ContactAtPatchBoundary,  // the contact reaches the end of the given strips: the patch was cut (result still valid
                           // for the part inside)
  NoEquivalentEllipse,     // KPEC only: no Hertz solution for the equivalent ellipse
  InfluenceNotPositive,    // conformal only: the corrected influence integral is <= 0 (normals turned > 90 deg)
  LoadNotReached,          // load given (SolveKikPiotrowskiForLoad): the load control did not reach the load; the
                           // last iterate is returned
};
// "ok", "no_contact", "contact_at_patch_boundary", "no_equivalent_ellipse", "influence_not_positive",
// "load_not_reached"
const char* to_string(KpStatus status);

// Default strips across the contact of the KP solvers (the one declaration; see KpOptions::strips_across_contact).
constexpr int kDefaultKpStrips = 31;

// The defaults are the planar `kp` model (PlanarKpOptions); InputError (ValidateKpOptions) outside the ranges given.
struct KpOptions {
  KpPenetrationRule penetration = KpPenetrationRule::ConstantEpsilon;  // eps rule; default constant (planar KP)
  KpInfluence influence = KpInfluence::HalfSpace;                      // influence function; default half-space
  KpPressureRule pressure = KpPressureRule::ContactPoint;              // amplitudes; default Kik-Piotrowski's
  // StripCollocation only: equal strips across the contact on which the amplitudes are collocated, >= 2 (at most
  // strips_across_contact are used: then the strips themselves); docs/physics-reference.md §5.3
  int collocation_strips = 11;
  // eps of Kik & Piotrowski (CONTACT user guide eps_kp = 0.55), dimensionless, in (0, 1]; ConstantEpsilon only (the
  // variable rule computes its own eps(s), docs/physics-reference.md §3.3).
  double virtual_penetration_factor = 0.55;
  // K of the Blanco-Lorenzo sin(alpha) coupling term (paper 003 eq. 3), see influence.hpp: CombinedBodies uses
  // Kalker's difference parameter, 0 for wheel and rail of the same steel (docs/physics-reference.md §0, §4.3) - the
  // default; PaperSingleBody uses the paper's quasi-identity value (1 - 2 nu) / (2 (1 - nu)).
  ConformalCoupling coupling = ConformalCoupling::CombinedBodies;
  // Resolution along s^r (x is integrated exactly), in [3, 100000]. 31 strips: KPEC within 0.2 % of Hertz, groove
  // p_max converged to 0.1 %, about 13-20 us per approach-given patch (tests/bench/bench_kp.cpp).
  int strips_across_contact = kDefaultKpStrips;
  // deg, finite: KpResult::is_conformal = alpha_c_deg > this; paper 003 §4.3 (conformity.hpp). Sets only the flag.
  double conformity_threshold_deg = kConformityThresholdDeg;
  Material material;  // both bodies (G, nu); validated
};

// One strip of the solved patch. Pressure on the strip:
// peak_pressure_Pa * sqrt(1 - ((x - x_centre_m)/half_length_m)^2).
struct KpStrip {
  double s_m = 0.0;               // strip centre along s^r (patch coordinates), m
  double ds_m = 0.0;              // strip width, m
  double x_centre_m = 0.0;        // m_j, m: centre of the strip's pressure along x^r (the patch's x_offset there)
  double half_length_m = 0.0;     // c_j, m, >= 0 (0 where the virtual interpenetration is <= 0)
  double alpha_rad = 0.0;         // local normal angle from the reference normal, rad (+ towards +s)
  double peak_pressure_Pa = 0.0;  // p0 c_j / c_norm, Pa
  double force_N = 0.0;           // (pi/2) peak c_j ds, N, along the strip's own normal
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // strip centre on the rail surface, (tangent t0, normal n0)
                                                          // components relative to the reference point
};

// The normal solution of one patch (docs/physics-reference.md §3.2, §5.1). approach_m and contact_point_s_m / _x_m
// are always set; the strips and every other field only with Ok and ContactAtPatchBoundary (and LoadNotReached, the
// last iterate of the load control, when that had contact); otherwise they are empty / 0 (InfluenceNotPositive
// keeps virtual_penetration_m).
struct KpResult {
  KpStatus status = KpStatus::NoContact;  // see KpStatus
  std::vector<KpStrip> strips;         // strips_across_contact equal strips over exactly [s_min_m, s_max_m]
  double approach_m = 0.0;             // rigid approach delta, m, >= 0 (load given: the solution's)
  double virtual_penetration_m = 0.0;  // eps * delta (KP) or eps(s_contact) * delta (KPEC), m
  double contact_point_s_m = 0.0;      // observation point of the contact condition (minimum gap), s^r, m
  double contact_point_x_m = 0.0;      // its x^r (the patch's x_offset there, yaw lead), m
  double p0_Pa = 0.0;    // Pa, paper 003 eq. 8 (KP: pressure at the contact point; KPEC: scale of the longest strip)
  double pmax_Pa = 0.0;  // largest pressure in the patch, Pa
  double fn_N = 0.0;     // resultant pressure force along the reference normal (CONTACT's fn_bar), N
  double fs_N = 0.0;     // its component along the reference tangent t0 (+s direction), N; 0 for a planar patch
  double fn_surface_N = 0.0;  // integral of the pressure over the curved surface (CONTACT's fn_tilde), N, >= fn_N
  Eigen::Vector2d force_on_wheel_N = Eigen::Vector2d::Zero();  // (fs_N, fn_N): the pressure pushes the wheel along +n
  double moment_Nm = 0.0;     // N m, moment of force_on_wheel about the longitudinal axis through the reference point,
                              // positive turning t0 towards n0
  double action_s_m = 0.0;    // force-weighted mean s of the strips (weights: force_N), m
  double action_x_m = 0.0;    // force-weighted mean x (yaw lead), m
  double area_m2 = 0.0;       // curved contact area, sum 2 c_j ds, m^2
  double width_m = 0.0;       // extent along s^r, s_max - s_min, m
  double length_m = 0.0;      // extent along x^r (over all strips' x_centre -/+ c_j), m
  double s_min_m = 0.0;       // start of the contact range along s^r, m (the patch's first strip edge when cut)
  double s_max_m = 0.0;       // end of the contact range along s^r, m (the patch's last strip edge when cut)
  double alpha_c_deg = 0.0;   // conformity index, paper 003 eq. 13, deg, in [0, 180]: spread of the strip normals
  bool is_conformal = false;  // alpha_c_deg > KpOptions::conformity_threshold_deg
};

// Approach given (approach_m >= 0, m, along the patch's reference normal): contact area, pressure and forces. Throws
// InputError for an inconsistent patch, NaN or a negative approach, bad options.
KpResult SolveKikPiotrowskiForApproach(const PatchGeometry& patch, double approach_m, const KpOptions& options);

// Options of the three KP models named in docs/architecture.md ("Models to compare").
KpOptions PlanarKpOptions(const Material& material);      // eps = 0.55, half-space
KpOptions KpecOptions(const Material& material);          // variable eps, half-space
KpOptions ConformalKpOptions(const Material& material);   // eps = 0.55, Blanco-Lorenzo
// Variable eps (KPEC rule) with the Blanco-Lorenzo influence and the strip-collocated amplitudes
// (KpPressureRule::StripCollocation, docs/physics-reference.md §5.3): the default of the pipeline's `conformal` model.
// Paper 003 leaves the virtual-penetration rule open; the constant eps = 0.55 under-estimates p_max by 6-14 % on
// elliptic and wide patches (docs/physics-reference.md §3.2), which the variable rule removes
// (tests/test_kp_groove.cpp, tests/test_validation_manchester.cpp).
KpOptions ConformalKpecOptions(const Material& material);

// Pressure at (x, s) of a solved patch (0 outside the contact).
double KpPressureAt(const KpResult& result, double x_m, double s_m);

// Load given, one patch: the approach at which the patch carries load_N along its reference normal, by the one
// load control (load_control.hpp) started at the Hertz approach of the patch's minimum-gap strip (A there, B from
// the gaps of its neighbours; docs/physics-reference.md §3.6) or at initial_approach_m.
// InputError for a tolerance or initial approach <= 0 or bad kp options.
struct KpLoadOptions {
  KpOptions kp;                        // the model (PlanarKpOptions, KpecOptions, ...)
  double relative_tolerance = 1e-10;   // on the load: |fn_N - load| <= tol * load (dimensionless, > 0)
  // m, > 0: first guess without hertz_initial_guess, or when Hertz has no solution; also the first bracket size
  double initial_approach_m = 1.0e-5;
  bool hertz_initial_guess = true;     // start at the Hertz approach of the minimum-gap strip (see above)
};
KpResult SolveKikPiotrowskiForLoad(const PatchGeometry& patch, double load_N, const KpLoadOptions& options);

// The pressure sampled on a grid of elements: each strip cut into elements_along_x equal elements across its
// contact length; pressure at the element centre.
struct KpPressureElement {
  // centre (x^r, s^r) and size of the element, m; pressure at the centre, Pa
  double x_m = 0.0, s_m = 0.0, dx_m = 0.0, ds_m = 0.0, pressure_Pa = 0.0;
};
std::vector<KpPressureElement> SampleKpPressure(const KpResult& result, int elements_along_x);

}  // namespace conforma
