#pragma once
// Twin-disc (line contact) FASTSIM with a friction law and slope reduction, and the identification of the law's
// parameters and k from a measured creep curve (paper 002 §3.2, §4; Ceres least squares instead of the paper's
// search over a spectrum of curves).
//
// Twin disc (paper 002 §3.2): two cylinders of radii R1, R2, contact width w (along the axes), normal force N.
// Line-contact Hertz: R* = R1 R2 / (R1 + R2), E* = G / (1 - nu) (same steel for both, E = 2G(1 + nu),
// 1/E* = 2 (1 - nu^2) / E), a = sqrt(4 N R* / (pi w E*)), p0 = 2 N / (pi a w) (consistent with paper 002 eq. 12,
// a = 2 p0 R* / E*). Longitudinal flexibility (eq. 10): L1 = 4 a / (C11 G) with C11 the a/b -> 0 limit
// pi^2 / (4 (1 - nu)) (docs/physics-reference.md §2.2), divided by k. FASTSIM runs on one strip of width w with the
// semi-elliptic bound p0 sqrt(1 - x^2/a^2), pure longitudinal creepage xi; the creep curve is the traction
// coefficient F/N = -F_x / N (positive for xi > 0).
#include <string>
#include <vector>

#include "conforma/fastsim.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/material.hpp"

namespace conforma {

// validate() throws InputError outside the ranges given.
struct TwinDiscSetup {
  double radius_1_m = 0.0235;  // R1, m, > 0. SUROS discs: 47 mm diameter, 10 mm wide (paper 002 §3.1)
  double radius_2_m = 0.0235;  // R2, m, > 0
  double width_m = 0.010;      // contact width w along the axes, m, > 0
  double normal_force_N = 0.0;  // normal force, N, > 0 (no default: set it, e.g. TwinDiscForceForPeakPressure)
  Material material;            // both discs (G, nu)
  int elements = 200;  // along x, >= 1
  void validate() const;
};

struct TwinDiscContact {
  double a_m = 0.0;       // semi-length along the rolling direction, m
  double p0_Pa = 0.0;     // peak pressure, Pa
  double c11 = 0.0;       // Kalker C11 for a/b -> 0
  double L1_m_per_Pa = 0.0;  // eq. 10, before the slope reduction
};
TwinDiscContact TwinDiscHertz(const TwinDiscSetup& setup);
// Normal force giving the peak pressure p0 (a = 2 p0 R*/E*, N = pi a w p0 / 2).
double TwinDiscForceForPeakPressure(const TwinDiscSetup& setup, double p0_Pa);

// Creep curve F/N at the given longitudinal creepages (dimensionless), law and slope reduction k.
std::vector<double> TwinDiscCreepCurve(const TwinDiscSetup& setup, const FrictionLaw& law, double slope_reduction,
                                       const std::vector<double>& creepages,
                                       FastsimMarching marching = FastsimMarching::CentreExact);

struct CreepCurvePoint {
  double creepage = 0.0;             // dimensionless (not %)
  double traction_coefficient = 0.0; // F/N
};
// CSV with two columns creepage, F/N; '#' comments and one optional header line (non-numeric) are skipped.
// Throws InputError naming the file and line for malformed rows.
std::vector<CreepCurvePoint> ReadCreepCurveCsv(const std::string& path);

struct FrictionFitOptions {
  FrictionLaw initial_law;             // kind and starting parameters (validated)
  double initial_slope_reduction = 1.0;  // k to start from (or the fixed k without fit_slope_reduction), > 0
  bool fit_slope_reduction = true;       // identify k too (bounded to [1e-3, 2])
  int max_iterations = 200;              // Ceres iterations per solve (each stage-2 start runs up to 6 solves)
  int refined_starts = 5;  // stage-2 Levenberg-Marquardt runs from the best stage-1 starts
  // Residuals (model - measured) / measured instead of model - measured: the maximum-likelihood choice for a
  // multiplicative (relative) measurement error.
  bool relative_residuals = false;
};

struct FrictionFitResult {
  // A stage-2 run gave a usable solution (finite cost); not Ceres' own convergence flag. false: law and k are the
  // best stage-1 start.
  bool converged = false;
  FrictionLaw law;                   // identified law, kind of initial_law
  double slope_reduction = 1.0;      // identified k (or initial_slope_reduction without fit_slope_reduction)
  double rms_error = 0.0;            // sqrt(mean (model - measured)^2), in F/N
  double relative_error_percent = 0.0;  // paper 002 eq. 11: mean |e_i| / mu_ref * 100, mu_ref at the largest creepage
  int iterations = 0;                // Ceres iterations of the last solve of the winning start
  std::string report;                // Ceres brief report of that solve
};

// Least-squares identification of the law parameters and k from a creep curve measured on the twin disc `setup`.
// Stage 1 (paper 002 §4: pick the best of a spectrum of generated creep curves): the initial guess with its rate /
// threshold parameters (f1a beta, f1b gamma_c, f2 alpha, beta) scaled by 1/4, 1/2, 1, 2, 4; stage 2: Ceres bounded
// Levenberg-Marquardt (numeric central differences) from the refined_starts best, the lowest final cost wins.
// Parameters are kept >= 0 (alpha of F1a <= 1, k <= 2). Throws InputError for an empty curve or NaN entries.
FrictionFitResult FitFrictionLaw(const std::vector<CreepCurvePoint>& curve, const TwinDiscSetup& setup,
                                 const FrictionFitOptions& options);

}  // namespace conforma
