#pragma once
// Conformity-index threshold study (issue 6, `conforma threshold`): above which conformity index alpha_c
// (paper 003 eq. 13) does the conformal model differ from the planar one by more than a tolerance?
//
// Per contact situation (one PatchGeometry with its load and creepages, benchmark_cases.hpp) the conformal model
// (conformal KP + curved FASTSIM) and the planar comparison model (by default planar KP + FASTSIM on the patch
// flattened onto the reference tangent plane; see PlanarComparison) are solved at the same grid, normal load and
// creepages. Relative differences, taken against the conformal result (or, ThresholdReference::Exact, against the
// exact solution: c below is then the exact reference):
//   d_pmax = |p_max,c - p_max,p| / p_max,c,  d_area likewise,
//   d_creep = |F_t,c - F_t,p| / |F_t,c|   (F_t = (F_x, F_y) in the patch reference frame, vector difference),
//   d_wear = |W_c - W_p| / W_c            (W = sum |p_t . s| dA),
//   d = max(d_pmax, d_area, d_creep, d_wear).
//
// Threshold fit (FitConformityThreshold): the study asks for the smallest alpha_c above which the difference
// exceeds the tolerance. The data are a scatter, not a function of alpha_c alone (the difference also depends on
// the patch shape and the creepages), so the threshold is fitted as the best step function: the alpha* that
// minimises the number of misclassified situations, #{alpha_c < alpha*, d > tol} + #{alpha_c >= alpha*, d <= tol},
// ties resolved to the smallest alpha* (alpha* = infinity, i.e. no threshold, only when strictly better). Its
// bracket is [largest alpha_c below alpha*, alpha*]. As a cross-check a power law d = c alpha_c^k is fitted by
// least squares in log-log (points with alpha_c >= 0.5 deg and d > 1e-4), giving alpha_pow = (tol / c)^(1/k) (the
// conformal correction grows ~ alpha_c^2 for small angles).
#include <string>
#include <vector>

#include "conforma/progress.hpp"
#include "conforma/validation/benchmark_cases.hpp"

namespace conforma {

enum class PlanarComparison {
  FlattenedKp,    // planar KP (half-space, eps = 0.55) on the patch projected onto the reference tangent plane
                  // (FlattenPatch): the classic non-conformal model; the default
  CurvilinearKp,  // the pipeline's `kp` model: planar KP on the curvilinear strips (only the influence function and
                  // the FASTSIM frames differ from the conformal model)
  Hertz,          // Hertz + FASTSIM with the curvatures at the smallest rigid gap
};
const char* to_string(PlanarComparison comparison);  // "flat_kp", "kp", "hertz"
PlanarComparison ParsePlanarComparison(const std::string& name);

// The side the planar model is measured against (issue 15).
enum class ThresholdReference {
  Conformal,  // the conformal model (paper 003's question: where does the conformal correction matter?); default
  Exact,      // the exact solver (BEM + Kalker's exact tangential, SolveBenchReference at its default grid): where is
              // the planar model wrong; alpha_c over the exact contact. Slow (a BEM per situation): a CLI study.
};
const char* to_string(ThresholdReference reference);  // "conformal", "exact"
ThresholdReference ParseThresholdReference(const std::string& name);

// The patch as a planar contact model sees it: rail and wheel surfaces of the curvilinear strips (rail points
// integrated from the tangents t(s) = cos(alpha) t0 - sin(alpha) n0, wheel points displaced by gap(s) along
// n(s) = cos(alpha) n0 + sin(alpha) t0, patch.hpp / curved_fastsim.hpp) resampled on a uniform lateral grid along t0
// (spacing ds) with the gap measured along the reference normal n0, alpha = 0. Strips whose normal is turned by
// 85 deg or more, and any part where the surfaces fold back over t0, are left out. Throws InputError for an
// inconsistent patch.
PatchGeometry FlattenPatch(const PatchGeometry& curved);

// validate() throws InputError outside the ranges given.
struct ThresholdOptions {
  double tolerance = 0.05;                                   // on d (relative difference, dimensionless), > 0
  PlanarComparison against = PlanarComparison::FlattenedKp;  // the planar model compared
  ThresholdReference reference = ThresholdReference::Conformal;  // ... against this
  int kp_strips = kDefaultKpStrips;                          // grid of both models: strips across the contact, >= 3
  int fastsim_elements = kDefaultFastsimElements;            // ... and FASTSIM elements per strip, >= 2
  // Virtual-penetration rule of BOTH models compared. false (default): Kik-Piotrowski's eps = 0.55, the formulation
  // of paper 003 whose 18 deg threshold is examined (conformal KP vs planar KP). true: KPEC's variable eps on both
  // sides (the pipeline's default conformal model vs KPEC); there the Blanco correction changes p_max far less.
  bool variable_epsilon = false;
  // progress (progress.hpp) of the situation sweep, one unit per situation (its name); empty: none
  ProgressFunction on_progress;
  void validate() const;
};

struct ThresholdPoint {
  std::string name, family;       // of the BenchCase situation
  double alpha_c_deg = 0.0;       // conformal KP patch
  double contact_angle_deg = 0.0; // reference normal from the track vertical
  double d_pmax = 0.0, d_area = 0.0, d_creep = 0.0, d_wear = 0.0, d_max = 0.0;  // relative differences (above), >= 0
  bool valid = false;             // both models found a contact
  bool failed = false;            // a solve threw (the sweep's CompareConformalPlanar): status holds the error
  // "normal/tangential|normal/tangential" statuses of the conformal and the planar model, "flatten: <error>", or
  // "error: <what the solve threw>" (failed)
  std::string status;
};

// One situation (solves both models).
ThresholdPoint CompareConformalPlanar(const BenchCase& situation, const ThresholdOptions& options);
// Every situation, in parallel with OpenMP (results identical for any thread count).
std::vector<ThresholdPoint> CompareConformalPlanar(const std::vector<BenchCase>& situations,
                                                   const ThresholdOptions& options);

struct ThresholdFit {
  double threshold_deg = 0.0;      // alpha* of the step fit (infinity when no point exceeds the tolerance)
  double bracket_low_deg = 0.0;    // largest alpha_c below alpha* (0 if none)
  int misclassified = 0, points = 0;  // points on the wrong side of alpha*; valid points fitted
  int exceeding = 0;               // points with d > tol
  double power_c = 0.0, power_k = 0.0, power_r2 = 0.0;  // d = c alpha_c^k (alpha_c in deg) and its R^2 in log-log
  double power_threshold_deg = 0.0;  // (tol / c)^(1/k); 0 when the fit is impossible
};
// d_of selects the difference (d_max by default: pass nullptr).
ThresholdFit FitConformityThreshold(const std::vector<ThresholdPoint>& points, double tolerance,
                                    double (*d_of)(const ThresholdPoint&) = nullptr);

// Situation sweeps (left wheel, every interpenetration region as its own situation):
//  "new":    S1002 on 60E1 at 1:20, lateral shift -4 ... 10 mm step 0.1 mm, yaw 0, 5, 10, 15, 20 mrad
//  "worn":   worn_high_mileage.prw on site_b_hr.prr on its measured track (worn_heavy_haul_track.hpp, issue 15),
//            lateral shift -4 ... 15.5 mm (up to the conformal gauge-corner contact), same yaws; `conforma threshold`
//            loads it with the heavy-haul wheel load (--worn-load-N, 137 kN)
//  "groove": CONTACT's circle R = 10 mm in grooves of decreasing radius 14 ... 10.02 mm
// Creepages xi = 1e-3, eta = 0.5e-3, phi = 0.2 /m; vertical load per wheel vertical_load_N.
std::vector<BenchCase> MakeThresholdSituations(const std::string& set, const std::string& shared_data_dir,
                                               double vertical_load_N = 10e3);

}  // namespace conforma
