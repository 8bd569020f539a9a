#pragma once
// Curved-patch FASTSIM (core paper 003 §4.2, eqs. 9-12; docs/physics-reference.md §5, §2.4) on a patch solved by the
// Kik-Piotrowski / conformal KP normal solver (kik_piotrowski.hpp), and FASTSIM on the SDEC for the `kp`/`kpec`
// models.
//
// Grid (paper 003 Fig. 7): one FASTSIM strip per KP strip j, centred at s_j with width ds_j; along x^r from
// x_centre_j + c_j (leading edge) to x_centre_j - c_j in n_x elements, so dx^r = 2 c_j / n_x varies with s^r.
// Traction bound (eq. 10): the KP pressure p_j(x) = peak_j sqrt(1 - ((x - m_j)/c_j)^2) acting along the strip's own
// normal n(s_j), averaged exactly over each element (optionally rescaled so the discrete load equals load_N).
//
// Local tangent frame of strip j: e1 = x^r (rolling direction, common to all strips), e2 = t_j, the rail tangent
// at s_j (t_j = cos(alpha_j) t0 - sin(alpha_j) n0, n_j = cos(alpha_j) n0 + sin(alpha_j) t0, patch.hpp). Tractions
// p = (p_x, p_s) and slips are computed in this frame (eqs. 9, 11, 12), with the creepages of the strip in the same
// frame (local_creepage.hpp).
//
// Flexibility matrix L(s^r) (eq. 9), derivation: in the simplified theory u = L p, and in the local frame of a
// strip the tangential compliance of the two half-spaces is that of a flat contact with the SDEC size (the
// conformal correction of paper 003 eq. 3 acts on the normal problem only; for wheel and rail of the same steel the
// tangential-normal coupling K vanishes, docs/physics-reference.md §4.3). Therefore
//     L(s^r) = diag(L1, L2) / k  in the local frame (e1, t(s^r)),   L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
// with a, b, C_ij of the SDEC (sdec.hpp) and the spin part of the rigid slip with L3 = pi a sqrt(a/b)/(4 C23 G) / k
// (the three-flexibility form, docs/physics-reference.md §2.3-2.4; k = slope reduction, paper 002 eq. 9). Because x^r
// is a principal axis in every local frame (the normal turns about x^r), L has no x-s coupling there; expressed in the
// patch reference frame (x, t0, n0) it is R_j diag(L1, L2) R_j^T with R_j = [e1 t_j], which is what the force and
// moment rotation below applies. On a flat elliptic patch (alpha = 0, a, b the ellipse) L = diag(L1, L2) and L3:
// classic FASTSIM exactly. Per-strip flexibilities may be supplied instead (e.g. a strip-wise calibration).
//
// Solution: per strip, the FASTSIM strip core (SolveFastsimStrips, or SolveFastsimStripsVariableFriction for a
// slip-dependent law) is called with that strip's creepages and flexibilities (one call for the whole patch when
// both are uniform). Forces: tractions in the local frames integrated on the curved surface and rotated into the
// patch reference frame (x, t0, n0) with alpha(s), moments about the patch reference point.
#include <vector>

#include <Eigen/Core>

#include "conforma/fastsim.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"
#include "conforma/sdec.hpp"

namespace conforma {

// InputError outside the ranges given.
struct CurvedFastsimOptions {
  int elements_per_strip = kDefaultFastsimElements;         // n_x, elements along x^r on every strip in contact, >= 1
  FastsimMarching marching = FastsimMarching::CentreExact;   // see fastsim.hpp
  double slope_reduction = 1.0;                              // k of paper 002 eq. 9 (L -> L / k), > 0; 1: none
  bool blend_flexibilities = false;  // CONTACT blending (fastsim.hpp) with the SDEC a, b and the creepages of the
                                     // strip at the longest-strip line; only with uniform flexibilities
  // Strip-wise flexibilities from the local half-length c_j (docs/physics-reference.md §5.4): L1_j = pi c_j/(C11 G),
  // L2_j = pi c_j/(C22 G), L3_j = 8 c_j sqrt(a/b)/(9 C23 G) (C_ij, a/b of the SDEC; then k and blending as above).
  // They reproduce Kalker's linear theory on an elliptic patch like the uniform SDEC values, and Carter's 2-D strip
  // (L = 4 c (1 - nu)/(pi G)) as a/b -> 0. Only when CurvedFastsimInput::strip_flexibilities is empty. false: uniform.
  bool local_flexibilities = false;
  // Spin about the patch centre (docs/physics-reference.md §5.4): Kalker's three-flexibility form (w_x = xi - phi y
  // L1/L3) is calibrated with the spin origin at the centre of the ellipse; elsewhere the translation part -phi y_c of
  // the spin's slip acts through L3 instead of L1 and the forces depend on the origin. true: the spin origin is moved
  // to the c^2-weighted centroid of the strips (where FASTSIM's pure spin gives no F_x) and the creepages with it
  // (the rigid slip is unchanged); spin_origin_x_m/_s_m then only say where the given creepages refer to.
  bool spin_about_patch_centre = false;
  // N, >= 0. > 0: rescale the bound so sum p_n dA = load_N (e.g. KpResult::fn_surface_N); 0 (default): as given
  double load_N = 0.0;
  double spin_origin_x_m = 0.0;  // origin of the spin lever arms (x^r, s^r) in patch coordinates, m; default (0, 0)
  double spin_origin_s_m = 0.0;  // (the patch reference point)
};

struct CurvedFastsimInput {
  // One entry for all strips, or one per KP strip: creepages at the spin origin in the strip's local frame
  // (local_creepage.hpp: StripCreepagesFromKinematics / StripCreepagesFromReference). Size 1 or the KP strip count.
  std::vector<FastsimCreepages> strip_creepages;
  // Empty: SDEC flexibilities for every strip; one entry: uniform; else one per strip (before the slope reduction).
  std::vector<FastsimFlexibilities> strip_flexibilities;
  FrictionLaw friction = FrictionLaw::Constant(0.3);  // mu or a slip-velocity law (friction_law.hpp); default 0.3
  Material material;                                  // G, nu of the SDEC coefficients and flexibilities
  double rolling_speed_m_per_s = 0.0;  // V, m/s, >= 0; > 0 for the frictional power (and a slip-dependent law)
};

// The tangential solution on a KP patch. Filled whenever the strips carry a load and the SDEC exists; otherwise
// status NoContact, an empty field and every sum 0 (sdec and bound_load_N are still set).
struct CurvedFastsimResult {
  FastsimStatus status = FastsimStatus::NoContact;  // that of the field (Ok: some adhesion, FullSlip: none)
  // Per element (strip-major, strip j's elements from first_element[j]): centre x - x_o and s - s_o, curved area,
  // traction (px along x^r, py along t_j) on the wheel, slip, in_slip. fx_N, fy_N, mz_Nm in it are the
  // curvilinear sums (below).
  FastsimResult field;
  std::vector<int> strip_first_element;  // per KP strip: index of its first element in field (strips not in contact
                                         // have no elements: the next strip's index)
  SdecResult sdec;  // the reduction of the patch (flexibilities used unless strip_flexibilities given)
  FastsimFlexibilities flexibilities;  // the uniform flexibilities used (after k and blending), m/Pa, if uniform
  // Curvilinear sums: sum p_x dA, sum p_s dA (local tangents), sum ((x - x_o) p_s - (s - s_o) p_x) dA; N, N, N m.
  double fx_N = 0.0, fs_N = 0.0, mz_Nm = 0.0;
  // Tangential traction resultant in the patch reference frame (x, t0, n0) and its moment about the reference point
  // (strip positions KpStrip::position_m, x from the patch origin); N and N m.
  Eigen::Vector3d force_reference_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment_reference_Nm = Eigen::Vector3d::Zero();
  // m^2, m^2, W: as in FastsimResult (summed over the strips); frictional_power_W 0 when the rolling speed is 0
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
  double bound_load_N = 0.0;  // sum p_n dA of the traction bound on the curved surface, N (= load_N when rescaled)
};

// Reusable buffers (no allocation in loops over patches of the same size). Contents are internal scratch.
struct CurvedFastsimWorkspace {
  FastsimPatch patch;                // the strip patch passed to the FASTSIM core
  std::vector<FastsimStrip> strips;  // one per KP strip
  std::vector<double> shape_means;   // element means of the normalised semi-ellipse
  std::vector<FastsimStripTotals> strip_totals;  // per strip (per-strip creepages)
  std::vector<FastsimFlexibilities> strip_flexibilities;  // per strip (CurvedFastsimOptions::local_flexibilities)
  std::vector<FastsimCreepages> centred_creepages;        // CurvedFastsimOptions::spin_about_patch_centre
};

// Throws InputError for a bad KP result (NaN, negative sizes), creepage/flexibility vectors of the wrong size,
// bad options (n_x < 1, k <= 0) or a bad friction law.
void SolveCurvedFastsim(const KpResult& normal, const CurvedFastsimInput& input, const CurvedFastsimOptions& options,
                        CurvedFastsimWorkspace* workspace, CurvedFastsimResult* result);
CurvedFastsimResult SolveCurvedFastsim(const KpResult& normal, const CurvedFastsimInput& input,
                                       const CurvedFastsimOptions& options);

// `kp` / `kpec` models: FASTSIM with the SDEC flexibilities over the real (planar) KP patch, KP pressure as bound,
// uniform creepages (the patch normals are taken as they are: alpha = 0 for planar KP). No rolling speed is passed:
// the result's frictional_power_W is 0.
CurvedFastsimResult SolveFastsimOnKpPatch(const KpResult& normal, const FastsimCreepages& creepages,
                                          const FrictionLaw& friction, const Material& material,
                                          const CurvedFastsimOptions& options);

// A vector of the patch reference frame (x, t0, n0) in the rail-profile frame (x, y_r, z_r) of the PatchGeometry:
// n0 = reference_normal, t0 = reference_normal turned by -90 deg, (n_z, -n_y): +y_r (field side) for a vertical
// normal, i.e. s^r is assumed to increase towards the field side (as patch.hpp's alpha convention for a convex head).
Eigen::Vector3d ReferenceToRailProfile(const Eigen::Vector3d& reference_vector, const PatchGeometry& geometry);

}  // namespace conforma
