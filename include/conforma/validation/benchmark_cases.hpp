#pragma once
// Run time against error (issue 6, `conforma bench`): a fixed set of single-patch contact cases, each a
// PatchGeometry with its normal load and creepages, solved by every model at several grid sizes and compared with
// the `exact` model on the same PatchGeometry (issue 14: the BEM normal problem with Blanco-Lorenzo coefficients
// and Kalker's exact steady-rolling tangential theory on the same grid, docs/physics-reference.md §10.4 and §14),
// solved once per case at the same normal force along the reference normal (fn_bar):
//   normal:     p_max, area and fn_bar (at the reference's approach) against its normal part;
//   tangential: Fx, Fy (relative to |F_t| of the reference) and the wear index against its tangential part.
// Cases: Manchester sweep (left wheel, every interpenetration region at the 10 kN Hertz push-down, creepages
// of the CONTACT reference file), the four CONTACT grooves (analytic groove patch of
// conforma/validation/analytic_patches.hpp), the worn pair worn_high_mileage.prw / site_b_hr.prr at three lateral
// shifts, a flange-root two-patch contact of S1002 / 60E1 at 1:40 (both patches), and (issue 15) `flange`: the right
// wheel of the wheelset at y_ws = 5 ... 10 mm on its flange root / flank, and `gauge_corner`: the worn pair's
// right wheel at 137 kN on the worn gauge corner, y = 15.0 ... 15.5 mm (one merged curved patch each).
//
// Wear index of a patch: W = sum over elements |p_t . s| dA (traction times dimensionless slip), i.e. the
// frictional power per unit rolling speed [N]; the integrand of the T-gamma / Archard wear laws.
#include <string>
#include <vector>

#include "conforma/fastsim.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"
#include "conforma/patch_solver.hpp"
#include "conforma/progress.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

struct BenchCase {
  std::string name;          // e.g. "mbench_07_p0", "groove_10.05", "worn_y3_p0", "flange_root_p1"
  std::string family;        // "mbench", "groove", "worn", "flange_root"
  PatchGeometry patch;         // the single patch every model solves
  double normal_load_N = 0.0;  // fn_bar, along the reference normal, N
  FastsimCreepages creepages;  // uniform over the patch (reference point values)
  // Hertz curvatures A, B (1/m) at the smallest rigid gap of the region (the `hertz` model, and `auto`'s choice)
  double hertz_A_per_m = 0.0;
  double hertz_B_per_m = 0.0;
  Material material;                  // both bodies
  double friction_coefficient = 0.3;  // mu (-)
};

// The fixed case set. shared_data_dir: the shared reference data folder (CONFORMA_SHARED_DATA). Throws InputError
// when a profile or reference file is missing or malformed.
std::vector<BenchCase> MakeBenchCases(const std::string& shared_data_dir);
// Individual families (the test uses them on their own).
std::vector<BenchCase> MakeGrooveBenchCases(const std::vector<double>& groove_radii_m, double normal_load_N = 10e3);
// Every interpenetration region of one wheel of `geometry` at the Hertz push-down for vertical_load_N.
std::vector<BenchCase> BenchCasesFromPose(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                          double vertical_load_N, const Material& material,
                                          const FastsimCreepages& creepages, const std::string& name,
                                          const std::string& family);
// BenchCasesFromPose with the non-Manchester creepages (xi, eta) = (1e-3, 0.5e-3) and the spin of a wheel rolling on
// the patch's contact angle delta, phi = -sin(delta) / r (families `flange` and `gauge_corner`).
std::vector<BenchCase> FlangeBenchCases(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                        double vertical_load_N, const Material& material, const std::string& name,
                                        const std::string& family);

// One model on one case at one grid.
struct PatchSolveOptions {
  ContactModel model = ContactModel::Conformal;  // Hertz, Kp, Kpec, Conformal or Auto (Reference: InputError)
  int kp_strips = kDefaultKpStrips;          // strips across the contact (KP models), >= 3
  // FASTSIM elements per strip (and strips of the Hertz ellipse), >= 2
  int fastsim_elements = kDefaultFastsimElements;
  double load_tolerance = kDefaultLoadTolerance;  // relative, on fn_bar, > 0
  // m, >= 0. > 0: approach given (one normal solve, as a multibody code in penetration mode calls it) instead of the
  // load
  double approach_m = 0.0;
  // Conformal model only: KPEC's variable virtual penetration (the pipeline's default, ConformalKpecOptions); false:
  // Kik-Piotrowski's eps = 0.55 (ConformalKpOptions), reported by the bench as the model "conformal_eps055".
  bool variable_epsilon = true;
  bool solve_tangential = true;  // false: normal problem only
  bool kp_spin_about_patch_centre = false;  // WheelContactOptions::kp_spin_about_patch_centre
  bool kp_local_flexibilities = false;      // WheelContactOptions::kp_local_flexibilities
  void validate() const;         // InputError naming the option
};

// The bench's summary of one patch solve (patch_solver.hpp), in the bench's measures.
// The normal numbers are 0 unless in_contact; the tangential ones (fx_N, fy_N, wear_index_N) also need a solved
// tangential problem.
struct BenchPatchResult {
  ContactModel model = ContactModel::Hertz;  // the model that solved it (auto: the chosen one)
  bool in_contact = false;                   // PatchNormalSolution::in_contact
  std::string normal_status, tangential_status;  // PatchNormalSolution / PatchTangentialSolution::status
  double pmax_Pa = 0.0, area_m2 = 0.0;       // maximum pressure (Pa) and contact area (m^2) of the model
  double fn_N = 0.0;          // along the reference normal, N
  double fx_N = 0.0, fy_N = 0.0;  // tangential force on the wheel, patch reference frame (x, t0), N
  double wear_index_N = 0.0;  // sum |p_t . s| dA, N
  double approach_m = 0.0;    // approach solved at (load given) or given, m
  double alpha_c_deg = 0.0;   // conformity index, deg (KP models; 0 for Hertz)
};
// One case through the one patch solver (load given, or approach given with options.approach_m > 0).
PatchSolution SolveBenchPatch(const BenchCase& bench_case, const PatchSolveOptions& options);
BenchPatchResult SummariseBenchPatch(const PatchSolution& solution);
BenchPatchResult SolveBenchCase(const BenchCase& bench_case, const PatchSolveOptions& options);
// The same model at a given approach (normal problem only): for the Fn error at the reference BEM's approach.
double NormalForceAtApproach(const BenchCase& bench_case, const PatchSolveOptions& options, double approach_m);

// The exact reference of one case (model `exact` through the one patch solver, load given on fn_bar).
struct BenchReferenceOptions {
  double element_size_m = kDefaultBemElementSizeM;  // BEM element length along x and s, m, > 0
  double load_tolerance = 1e-8;                     // relative, on fn_bar, > 0 (the BEM tolerance follows it)
  void validate() const;                            // InputError naming the option
};
struct BenchReference {
  // PatchNormalSolution::status ("ok", or the load control's / BEM's failure) and PatchTangentialSolution::status
  // ("ok", "full_slip", "not_converged", ...)
  std::string normal_status, tangential_status;
  bool converged = false;  // normal "ok" and tangential "ok" or "full_slip": the errors against it mean something
  std::string status() const;  // "converged", or "<normal_status>/<tangential_status>"
  // normal part: max pressure (Pa), contact area (m^2), fn_bar (N, = the case's load), solved approach (m)
  double pmax_Pa = 0.0, area_m2 = 0.0, fn_N = 0.0, approach_m = 0.0;
  double alpha_c_deg = 0.0;            // conformity index over the BEM contact, deg
  bool contact_at_grid_edge = false;   // the BEM contact reaches its grid's edge (BemResult)
  int bem_nx = 0, bem_ns = 0;          // the BEM grid of the solution
  int load_iterations = 0;             // root-finder evaluations of the load control (LoadControlResult::iterations)
  // tangential part: creep forces (N, patch frame x, t0), wear index sum |p_t . s| dA (N: frictional power at
  // rolling speed 1), Gauss-Seidel sweeps and last relative traction change (PatchTangentialSolution)
  double fx_N = 0.0, fy_N = 0.0, wear_index_N = 0.0;
  int tangential_iterations = 0;
  double tangential_residual = 0.0;
  double time_s = 0.0;  // wall time of the solve (normal + tangential), s (not reproducible)
};
// One solve of the exact model on the case's patch (SolvePatch with ContactModel::Exact, load given).
BenchReference SolveBenchReference(const BenchCase& bench_case, const BenchReferenceOptions& options = {});

struct BenchGrid {
  int kp_strips = kDefaultKpStrips;                // PatchSolveOptions::kp_strips
  int fastsim_elements = kDefaultFastsimElements;  // PatchSolveOptions::fastsim_elements
  std::string label() const;  // "s31e30"
};
// 11/10, 21/20, 31/30 (the models' default), 61/50.
std::vector<BenchGrid> DefaultBenchGrids();

// One model x grid x case. Times in microseconds (not reproducible); errors dimensionless.
struct BenchRow {
  // model name (to_string, or "conformal_eps055"), BenchGrid::label, BenchCase::name, BenchCase::family
  std::string model, grid, case_name, family;
  double time_us = 0.0;       // median wall time per patch: load-controlled normal + tangential solve
  // the same with the approach given (one normal solve) + tangential; 0 when the model found no contact
  double time_approach_us = 0.0;
  double time_normal_us = 0.0;    // the approach-given normal solve alone; 0 when the model found no contact
  // Relative errors against the exact reference of the case, signed: (model - reference) / reference; creep forces
  // relative to |F_t| of the reference. err_fn: the model's fn_bar at the reference's approach against the
  // reference's.
  double err_pmax = 0.0, err_area = 0.0, err_fn = 0.0, err_fx = 0.0, err_fy = 0.0, err_wear = 0.0;
  double alpha_c_deg = 0.0;   // the model's conformity index, deg (hertz: that of the reference)
  // normal/tangential status of the model, "/bem_edge" appended when the BEM contact reaches its grid's edge, and
  // for auto "/" and the chosen model
  std::string status;
  std::string reference_status;  // BenchReference::status() of the case: "converged" or what failed
};

struct BenchOptions {
  // models run (Exact is not benchmarked: it is the reference; Auto may be included)
  std::vector<ContactModel> models{ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal};
  std::vector<BenchGrid> grids = DefaultBenchGrids();  // each model at each grid
  bool conformal_eps055 = true;  // also run the conformal model with eps = 0.55 ("conformal_eps055")
  double bem_element_size_m = kDefaultBemElementSizeM;  // BemOptions::element_dx_m = element_ds_m of the normal reference, m, > 0
  double min_time_per_measurement_s = 0.02;  // repeats per timing until this much time has passed (>= 5 repeats)
  int max_repeats = 201;                     // ... but at most this many (and at least 5)
  double reference_load_tolerance = 1e-8;    // BenchReferenceOptions::load_tolerance of the exact reference
  bool kp_spin_about_patch_centre = false;  // PatchSolveOptions::kp_spin_about_patch_centre of every timed solve
  bool kp_local_flexibilities = false;      // PatchSolveOptions::kp_local_flexibilities of every timed solve
  // progress (progress.hpp), 2 units per case: its exact reference ("reference <case>"), then its timed models
  // ("timed <case>"); empty: none
  ProgressFunction on_progress;
};

// Runs every model x grid x case (sequential, so that the timings are not disturbed), one exact reference per case.
// Deterministic apart from the times. references (optional): one per case, in the order of `cases`.
std::vector<BenchRow> RunBench(const std::vector<BenchCase>& cases, const BenchOptions& options,
                               std::vector<BenchReference>* references = nullptr);

}  // namespace conforma
