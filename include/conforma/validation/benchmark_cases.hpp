#pragma once
// Run time against error (issue 6, `conforma bench`): a fixed set of single-patch contact cases, each a
// PatchGeometry with its normal load and creepages, solved by every model at several grid sizes and compared with
//   normal:     the reference BEM with Blanco-Lorenzo coefficients on the same PatchGeometry (bem_reference.hpp),
//               at the same normal force along the reference normal (fn_bar);
//   tangential: the conformal model (conformal KP + curved FASTSIM) on a finer grid than any benchmarked one.
// Cases: Manchester sweep (left wheel, every interpenetration region at the 10 kN Hertz push-down, creepages
// of the CONTACT reference file), the four CONTACT grooves (analytic groove patch of conforma/validation/analytic_patches.hpp),
// the worn pair worn_high_mileage.prw / site_b_hr.prr at three lateral shifts, and a flange-root two-patch
// contact of S1002 / 60E1 at 1:40 (both patches).
//
// Wear index of a patch: W = sum over elements |p_t . s| dA (traction times dimensionless slip), i.e. the
// frictional power per unit rolling speed [N]; the integrand of the T-gamma / Archard wear laws.
#include <string>
#include <vector>

#include "conforma/fastsim.hpp"
#include "conforma/material.hpp"
#include "conforma/patch.hpp"
#include "conforma/patch_solver.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

struct BenchCase {
  std::string name;          // e.g. "mbench_07_p0", "groove_10.05", "worn_y3_p0", "flange_root_p1"
  std::string family;        // "mbench", "groove", "worn", "flange_root"
  PatchGeometry patch;
  double normal_load_N = 0.0;  // fn_bar, along the reference normal
  FastsimCreepages creepages;  // uniform over the patch (reference point values)
  double hertz_A_per_m = 0.0;  // Hertz curvatures at the smallest rigid gap of the region (the `hertz` model)
  double hertz_B_per_m = 0.0;
  Material material;
  double friction_coefficient = 0.3;
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

// One model on one case at one grid.
struct PatchSolveOptions {
  ContactModel model = ContactModel::Conformal;  // Hertz, Kp, Kpec or Conformal (Reference: InputError)
  int kp_strips = kDefaultKpStrips;          // strips across the contact (KP models)
  int fastsim_elements = kDefaultFastsimElements;   // FASTSIM elements per strip (and strips of the Hertz ellipse)
  double load_tolerance = kDefaultLoadTolerance;  // relative, on fn_bar
  // > 0: approach given (one normal solve, as a multibody code in penetration mode calls it) instead of the load
  double approach_m = 0.0;
  // Conformal model only: KPEC's variable virtual penetration (the pipeline's default, ConformalKpecOptions); false:
  // Kik-Piotrowski's eps = 0.55 (ConformalKpOptions), reported by the bench as the model "conformal_eps055".
  bool variable_epsilon = true;
  bool solve_tangential = true;
  void validate() const;
};

// The bench's summary of one patch solve (patch_solver.hpp), in the bench's measures.
struct BenchPatchResult {
  ContactModel model = ContactModel::Hertz;  // the model that solved it (auto: the chosen one)
  bool in_contact = false;
  std::string normal_status, tangential_status;
  double pmax_Pa = 0.0, area_m2 = 0.0;
  double fn_N = 0.0;          // along the reference normal
  double fx_N = 0.0, fy_N = 0.0;  // tangential force on the wheel, patch reference frame (x, t0)
  double wear_index_N = 0.0;  // sum |p_t . s| dA
  double approach_m = 0.0;
  double alpha_c_deg = 0.0;   // conformity index (KP models; 0 for Hertz)
};
// One case through the one patch solver (load given, or approach given with options.approach_m > 0).
PatchSolution SolveBenchPatch(const BenchCase& bench_case, const PatchSolveOptions& options);
BenchPatchResult SummariseBenchPatch(const PatchSolution& solution);
BenchPatchResult SolveBenchCase(const BenchCase& bench_case, const PatchSolveOptions& options);
// The same model at a given approach (normal problem only): for the Fn error at the reference BEM's approach.
double NormalForceAtApproach(const BenchCase& bench_case, const PatchSolveOptions& options, double approach_m);

struct BemReferenceSolution {
  std::string status;
  double pmax_Pa = 0.0, area_m2 = 0.0, fn_N = 0.0, approach_m = 0.0;
  bool contact_at_grid_edge = false;
};
// Reference BEM (Blanco-Lorenzo coefficients, load control on fn_bar) on the case's patch.
BemReferenceSolution SolveBenchReference(const BenchCase& bench_case, int bem_x_elements = kDefaultBemXElements);

struct BenchGrid {
  int kp_strips = kDefaultKpStrips;
  int fastsim_elements = kDefaultFastsimElements;
  std::string label() const;  // "s31e30"
};
// 11/10, 21/20, 31/30 (the models' default), 61/50.
std::vector<BenchGrid> DefaultBenchGrids();

struct BenchRow {
  std::string model, grid, case_name, family;
  double time_us = 0.0;       // median wall time per patch: load-controlled normal + tangential solve
  double time_approach_us = 0.0;  // the same with the approach given (one normal solve) + tangential
  double time_normal_us = 0.0;    // the approach-given normal solve alone
  // Relative errors, signed: (model - reference) / reference; creep forces relative to |F_t| of the reference.
  double err_pmax = 0.0, err_area = 0.0, err_fn = 0.0, err_fx = 0.0, err_fy = 0.0, err_wear = 0.0;
  double alpha_c_deg = 0.0;
  std::string status;          // normal/tangential status of the model
};

struct BenchOptions {
  std::vector<ContactModel> models{ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal};
  std::vector<BenchGrid> grids = DefaultBenchGrids();
  bool conformal_eps055 = true;  // also run the conformal model with eps = 0.55 ("conformal_eps055")
  BenchGrid tangential_reference{121, 100};  // conformal model on this grid
  int bem_x_elements = kDefaultBemXElements;
  double min_time_per_measurement_s = 0.02;  // repeats per timing until this much time has passed (>= 5 repeats)
  int max_repeats = 201;
};

// Runs every model x grid x case (sequential, so that the timings are not disturbed). Deterministic apart from
// time_us.
std::vector<BenchRow> RunBench(const std::vector<BenchCase>& cases, const BenchOptions& options);

}  // namespace conforma
