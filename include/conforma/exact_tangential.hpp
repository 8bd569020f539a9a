#pragma once
// Kalker's exact theory of steady rolling (docs/physics-reference.md §14): the tangential problem on the BEM grid of
// the normal solution (bem_reference.hpp), with the same rectangle influence coefficients.
//
// Conventions as FASTSIM (fastsim.hpp): tractions on body 1 (the wheel); rolling in +x, material enters the patch at
// the leading edge (largest x) and leaves at the trailing edge; slip s = slip velocity / rolling speed V,
// dimensionless. Discretisation (Kalker 1990 §5.2, CONTACT's steady-state rolling): piecewise-constant traction on the
// grid rectangles, slip at the element centres, the material derivative by the upwind difference over one element,
//     s_I = w_I + (u_I - u'_I) / dx,   u_I = sum_J A_IJ p_J,   u'_I = sum_J A(x_I + dx - x_J, s_I - s_J) p_J
// (u'_I: the displacement one element upstream, where the material at I came from), w = rigid slip. Conditions:
//     |p_I| <= g_I = mu(|s_I|) p_n,I;   |p_I| < g_I  =>  s_I = 0 (adhesion);   s_I != 0  =>  p_I = -g_I s_I / |s_I|.
// Curved grids (columns with normal rotation alpha_j): the lateral traction acts along the local tangent
// t_j = cos(alpha_j) t0 - sin(alpha_j) n0; the influence coefficients are the Blanco-Lorenzo corrected B_xx = A_xx,
// B_xs = A_xs cos(alpha_J - alpha_I), B_sx = A_sx, B_ss = A_ss cos(alpha_J - alpha_I) (§4.2 version 1 with K = 0:
// the normal-tangential coupling is off, as CONTACT's default for equal materials).
//
// Solver (§14.2): since the upwind shift commutes with the convolution, s = w + A v with v = dp/dx along the rolling
// direction and A symmetric positive definite. Gauss-Seidel in v: along each grid line from the leading to the trailing
// edge, the 2x2 element problem with the traction bound solved exactly for p (v follows from p and its upstream
// neighbour), Gauss-Seidel between lines (direct summation, with an FFT refresh of the whole slip field per block of
// lines). Slip-dependent friction: the bound follows the slip of the current iterate (a fixed point, converged together
// with the traction).
//
// Thread-safe, deterministic (no threading inside).
#include <functional>
#include <string>

#include <Eigen/Core>

#include "conforma/bem_reference.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/material.hpp"

namespace conforma {

// Rigid slip w = (w_x, w_s) per element of a BemGrid (nx x ns each), dimensionless (velocity / V).
struct RigidSlipField {
  Eigen::MatrixXd wx;  // along x (rolling direction)
  Eigen::MatrixXd ws;  // along the local lateral tangent t_j
};
// Uniform creepages about the spin origin (x_o, s_o): w_x = xi - phi (s - s_o), w_s = eta + phi (x - x_o) (Kalker).
RigidSlipField RigidSlipFromCreepages(const BemGrid& grid, const FastsimCreepages& creepages,
                                      double spin_origin_x_m = 0.0, double spin_origin_s_m = 0.0);
// One creepage set per grid column j (creepages at the spin origin in the strip frame, local_creepage.hpp):
// w_x = xi_j - phi_j (s_j - s_o), w_s = eta_j + phi_j (x - x_o). InputError unless per_column has grid.ns entries.
RigidSlipField RigidSlipFromColumnCreepages(const BemGrid& grid, const std::vector<FastsimCreepages>& per_column,
                                            double spin_origin_x_m = 0.0, double spin_origin_s_m = 0.0);

enum class ExactTangentialStatus {
  Converged,     // the relative traction change per sweep fell below the tolerance
  NotConverged,  // max_sweeps reached; the fields hold the last iterate
  NoContact,     // no element carries pressure
};
const char* to_string(ExactTangentialStatus status);  // "converged", "not_converged", "no_contact"

struct ExactTangentialOptions {
  BemInfluence influence = BemInfluence::HalfSpace;  // Blanco: the corrected coefficients on a curved grid
  double friction_coefficient = 0.3;                 // mu (-), >= 0, used when `friction` is empty
  // mu(gamma) of the dimensionless slip gamma = |s| (friction_law.hpp, FrictionLaw::operator()); empty: constant
  std::function<double(double)> friction;
  double rolling_speed_m_per_s = 0.0;  // V, m/s, >= 0: frictional power sum |p . s| V dA (0: power 0)
  // on max_I |p_I - p_I,old| / max_I g_I per sweep, > 0: the forces then move by less than ~1e-5 mu Fn per sweep
  double tolerance = 1e-5;
  int max_sweeps = 2000;               // >= 1
  bool use_fft = true;                 // false: direct summation (same numbers to rounding, for checking)
  // Gauss-Seidel between lines by blocks of this many lines, the slip refreshed by one FFT product per block (§14.2);
  // 0: chosen from the grid size (§14.2). The iteration is the same; only the cost (and the rounding) differs.
  int lines_per_fft = 0;
  void validate() const;               // InputError naming the option
};

struct ExactTangentialResult {
  ExactTangentialStatus status = ExactTangentialStatus::NoContact;  // see ExactTangentialStatus
  Eigen::MatrixXd px_Pa, ps_Pa;  // traction on body 1 along x and t_j, nx x ns, Pa
  Eigen::MatrixXd sx, ss;        // dimensionless slip (0 in adhesion and outside the contact)
  Eigen::MatrixXi state;         // 0 = no contact, 1 = adhesion, 2 = slip
  Eigen::MatrixXd bound_Pa;      // g = mu(|s|) p_n, Pa
  // Totals on body 1 in the patch reference frame (x, t0, n0): fx along x, fy along t0 (sum ps cos(alpha) dA),
  // fn_tangential along n0 (-sum ps sin(alpha) dA: the normal component of the curved lateral tractions), N.
  double fx_N = 0.0, fy_N = 0.0, fn_tangential_N = 0.0;
  // Spin moment about n0 through the spin origin, sum ((x - x_o) ps - (s - s_o) px) dA, N m (Kalker's Mz).
  double mz_Nm = 0.0;
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0;  // m^2
  double frictional_power_W = 0.0;                    // sum |p . s| V dA, W
  int sweeps = 0;                                     // Gauss-Seidel sweeps done
  double residual = 0.0;  // relative traction change of the last sweep (the convergence measure)
};

// Solve on `grid` with the normal pressure field `pressure_Pa` (nx x ns, >= 0) and the rigid slip `rigid_slip`.
// spin_origin_*: the point the spin moment is taken about. Throws InputError for bad input (sizes, NaN, negative
// pressure, options).
ExactTangentialResult SolveExactTangential(const BemGrid& grid, const Eigen::MatrixXd& pressure_Pa,
                                           const RigidSlipField& rigid_slip, const Material& material,
                                           const ExactTangentialOptions& options, double spin_origin_x_m = 0.0,
                                           double spin_origin_s_m = 0.0);

}  // namespace conforma
