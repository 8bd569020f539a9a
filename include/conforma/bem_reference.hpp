#pragma once
// Reference boundary-element solver of the frictionless normal contact problem (docs/physics-reference.md §10):
// piecewise-constant pressure on an nx x ns grid of rectangles covering the potential contact area,
//     g_I = h_I - delta cos(alpha_I) + sum_J C_IJ p_J >= 0,   p_I >= 0,   g_I p_I = 0,
// solved with the Polonsky-Keer constrained conjugate gradient (§10.3) and an FFT (DC-FFT) matrix-vector
// product. Slow by design: it measures the error of the fast models (Hertz, KP, conformal KP).
//
// Curved patches. The grid lives in curvilinear rail coordinates (x^r along the track, s^r along the rail
// profile); column j is a strip with its own normal rotation alpha_j from the reference normal. The gap is
// measured along the local normal; a rigid approach delta along the reference normal closes it by
// delta cos(alpha_j). The conjugate force is the force along the reference normal
//     fn_bar = sum p cos(alpha) dA        (CONTACT's FN), while fn_tilde = sum p dA
// is the integral of the curved-surface pressure. C_IJ is the half-space coefficient A_nn (§10.2) or the
// Blanco-Lorenzo corrected B_nn = A_nn cos(alpha_J - alpha_I) - A_ns sin(alpha_J - alpha_I) (§4.2; see
// influence.hpp). cos(a - b) = cos a cos b + sin a sin b keeps every product a sum of convolutions, so the
// FFT is exact for any alpha(s), not only for constant curvature.
//
// Thread-safe, deterministic (no threading inside: results are identical for any OMP_NUM_THREADS).
#include <Eigen/Core>
#include <vector>

#include "conforma/influence.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"

namespace conforma {

// Default element size of the BEM grid built from a patch, along x and along s (the one declaration;
// BemOptions::element_dx_m / element_ds_m, WheelContactOptions::exact_element_size_m): 0.2 mm, CONTACT's usual grid.
constexpr double kDefaultBemElementSizeM = 0.2e-3;
// Default largest BEM grid (elements nx ns) of one solve: about 1 kB per element for the normal and the tangential
// solve together (FFTW buffers and spectra of the convolutions, iteration vectors), so 250,000 elements keep a solve
// below ~300 MB. At 0.2 mm elements this is 100 cm^2, far more than any wheel-rail contact needs.
constexpr long kDefaultBemMaxElements = 250000;

// Potential contact area: element (i, j) is centred at (x_first + i dx, s_first + j ds).
struct BemGrid {
  int nx = 0;  // elements along x (rolling)
  int ns = 0;  // elements along s (lateral / rail profile arc length)
  double dx_m = 0.0;       // element length along x, m, > 0
  double ds_m = 0.0;       // element width along s, m, > 0
  double x_first_m = 0.0;  // x of the first element centre, m
  double s_first_m = 0.0;  // s of the first element centre, m
  Eigen::MatrixXd gap_m;          // nx x ns undeformed separation along the local normal at element centres
  std::vector<double> alpha_rad;  // ns normal rotations from the reference normal; empty = flat patch

  double x_centre_m(int i) const { return x_first_m + i * dx_m; }
  double s_centre_m(int j) const { return s_first_m + j * ds_m; }
  double alpha(int j) const { return alpha_rad.empty() ? 0.0 : alpha_rad[static_cast<size_t>(j)]; }
  double element_area_m2() const { return dx_m * ds_m; }
  // Throws InputError naming the problem (sizes, NaN gaps, alpha size, |alpha| >= 90 deg).
  void validate() const;
};

// Quadratic gap h = A (x - x0)^2 + B (s - s0)^2 on a grid centred at (x0, s0) with half lengths
// (half_x, half_s): the Hertz test problem.
BemGrid QuadraticGapGrid(double A_per_m, double B_per_m, int nx, int ns, double half_x_m, double half_s_m);

enum class BemInfluence {
  HalfSpace,  // A_nn, Love's rectangle coefficient (§10.2)
  Blanco,     // Blanco-Lorenzo corrected B_nn (§4.2, paper 003 eq. 2), coupling chosen in BemOptions
};
// NormalForce: the normal force is given (BemOptions::normal_force_N, measured per force_measure), the approach is
// solved; Approach: the rigid approach is given (BemOptions::approach_m), the force follows.
enum class BemLoadControl { NormalForce, Approach };
enum class BemForceMeasure {
  ReferenceNormal,  // the prescribed force is fn_bar = sum p cos(alpha) dA (equilibrium along the reference normal)
  CurvedSurface,    // the prescribed force is fn_tilde = sum p dA
};
enum class BemStatus {
  Converged,     // the relative pressure change per iteration fell below the tolerance
  NotConverged,  // max_iterations reached; the fields hold the last iterate
  NoContact,     // zero load, or an approach that does not close the gap anywhere
};
const char* to_string(BemStatus status);          // "converged", "not_converged", "no_contact"
const char* to_string(BemInfluence influence);    // "half-space", "blanco"

// InputError outside the ranges given.
struct BemOptions {
  BemInfluence influence = BemInfluence::HalfSpace;  // influence coefficient; default half-space
  ConformalCoupling coupling = ConformalCoupling::CombinedBodies;  // only for BemInfluence::Blanco
  BemLoadControl control = BemLoadControl::NormalForce;            // default: force given
  double normal_force_N = 0.0;  // N, >= 0 (0: NoContact), control == NormalForce
  // control == NormalForce: which force is prescribed (fn_bar by default); ignored for a flat grid
  BemForceMeasure force_measure = BemForceMeasure::ReferenceNormal;
  double approach_m = 0.0;      // m, finite, control == Approach (along the reference normal)
  double tolerance = 1e-10;     // on the relative change of the pressure per iteration (L1), > 0
  int max_iterations = 2000;    // conjugate-gradient iterations (per solve), >= 1
  bool use_fft = true;          // false: direct O(n^2) summation (same numbers, for checking)
  // Largest grid nx ns accepted (memory budget, see kDefaultBemMaxElements), >= 1: a larger grid is an InputError
  // naming the grid, the budget and the element size that sets it.
  long max_elements = kDefaultBemMaxElements;
  // PatchGeometry input only: the element length along x and width along s, m, > 0 (default 0.2 mm both), and the
  // margin on the interpenetration length (> 0: the x grid covers x_margin times the half-length
  // sqrt((delta - gap) / A) of every interpenetrating strip).
  double element_dx_m = kDefaultBemElementSizeM;
  double element_ds_m = kDefaultBemElementSizeM;
  double x_margin = 1.1;
};

// With NoContact no element carries pressure: forces, area, p_max, the contact extents and the centre of pressure
// are 0 (approach_m and iterations are still those of the solve).
struct BemResult {
  BemStatus status = BemStatus::NoContact;  // see BemStatus
  BemGrid grid;                  // the grid that was solved (built from the patch for PatchGeometry input)
  Eigen::MatrixXd pressure_Pa;   // nx x ns, >= 0
  Eigen::MatrixXd deformed_gap_m;  // nx x ns, g = h - delta cos(alpha) + u  (>= 0 up to the tolerance)
  double approach_m = 0.0;                // rigid approach delta along the reference normal, m (given or solved)
  double normal_force_reference_N = 0.0;  // fn_bar = sum p cos(alpha) dA
  double normal_force_surface_N = 0.0;    // fn_tilde = sum p dA
  double contact_area_m2 = 0.0;           // elements with p > 0 times dA (on the curved surface)
  int contact_elements = 0;               // elements with p > 0
  double max_pressure_Pa = 0.0;           // Pa
  double contact_s_min_m = 0.0, contact_s_max_m = 0.0;  // outer element edges of the contact along s
  double contact_x_min_m = 0.0, contact_x_max_m = 0.0;  // outer element edges of the contact along x
  double contact_width_s_m = 0.0;   // contact_s_max - contact_s_min
  double contact_length_x_m = 0.0;  // contact_x_max - contact_x_min
  // point of action (x, s) in the grid's patch coordinates, m, weighted by p dA (curved surface)
  double centre_of_pressure_x_m = 0.0;
  double centre_of_pressure_s_m = 0.0;
  double max_complementarity_m = 0.0;  // max over contact of |g| and over the rest of max(-g, 0)
  bool contact_at_grid_edge = false;   // contact reaches the outer row/column: the potential area was too small
  int iterations = 0;                  // conjugate-gradient iterations, all solves together
  double residual = 0.0;               // relative pressure change (L1) of the last iteration: < tolerance if converged
  int regrids = 0;                     // PatchGeometry input: grids tried (0 for grid input)
};

// Solve on a given grid. Throws InputError for bad input (grid, material, negative/NaN load or approach).
BemResult SolveBemNormal(const BemGrid& grid, const Material& material, const BemOptions& options);
// Solve a patch on a grid of element_dx_m x element_ds_m rectangles (§10.4) that covers the interpenetration region
// {h < delta}, which contains the contact, plus a margin: along s the columns lie on the lattice
// s_first strip + m element_ds_m and span the interpenetrating strips plus one strip and one element on each side;
// the strip data (gap, curvature, alpha, x offset) is interpolated linearly in s onto the column centres. Along x the
// grid covers x_margin times the interpenetration half-length of every interpenetrating strip.
BemResult SolveBemNormal(const PatchGeometry& patch, const Material& material, const BemOptions& options);

}  // namespace conforma
