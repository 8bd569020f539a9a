// One model on one bench case, the exact reference, and the timed run over models x grids x cases
// (benchmark_cases.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/patch_solver.hpp"
#include "conforma/model_selection.hpp"

namespace conforma {

void PatchSolveOptions::validate() const {
  if (model == ContactModel::Exact) throw InputError("bench: the exact model is the reference, not a benchmarked model");
  if (kp_strips < 3) throw InputError("bench: kp_strips must be >= 3");
  if (fastsim_elements < 2) throw InputError("bench: fastsim_elements must be >= 2");
  require_positive(load_tolerance, "load_tolerance");
  require_non_negative(approach_m, "approach_m");
}

std::string BenchGrid::label() const { return "s" + std::to_string(kp_strips) + "e" + std::to_string(fastsim_elements); }

std::vector<BenchGrid> DefaultBenchGrids() { return {{11, 10}, {21, 20}, {31, 30}, {61, 50}}; }

namespace {

// The pipeline's options for a bench solve (the defaults of WheelContactOptions, the case's material and friction).
WheelContactOptions ContactOptionsFor(const BenchCase& c, const PatchSolveOptions& o) {
  WheelContactOptions w;
  w.model = o.model;
  w.material = c.material;
  w.friction_coefficient = c.friction_coefficient;
  w.kp_strips = o.kp_strips;
  w.fastsim_elements = o.fastsim_elements;
  w.load_tolerance = o.load_tolerance;
  w.conformal_variable_penetration = o.variable_epsilon;
  w.kp_spin_about_patch_centre = o.kp_spin_about_patch_centre;
  w.kp_local_flexibilities = o.kp_local_flexibilities;
  return w;
}

// The case's patch: its curved patch and its rigid point (the Hertz curvatures at the smallest gap).
RigidContactPoint HertzPointOf(const BenchCase& c) {
  RigidContactPoint point;
  point.hertz_A_per_m = c.hertz_A_per_m;
  point.hertz_B_per_m = c.hertz_B_per_m;
  return point;
}

// Hertz approach of the case's load at its curvatures, or 0 without a Hertz solution.
double HertzApproach(const BenchCase& c) {
  const HertzResult h = SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, c.normal_load_N, c.material);
  return h.status == HertzStatus::Ok ? h.approach_m : 0.0;
}

// The case's patch problem for `model`, load given on fn_bar (approach given when approach_m > 0), the creepages at
// unit rolling speed; `point` (HertzPointOf(c)) must outlive the problem.
PatchProblem CaseProblem(const BenchCase& c, ContactModel model, const RigidContactPoint& point, double approach_m) {
  PatchProblem problem;
  problem.model = model;
  problem.input = PatchInput{&c.patch, &point};
  problem.approach_m = approach_m;
  problem.normal_load_N = c.normal_load_N;
  // the load control starts at the Hertz approach (or the rigid approach where Hertz has no solution)
  const double hertz_approach = HertzApproach(c);
  problem.first_guess_approach_m = hertz_approach > 0.0 ? hertz_approach : std::max(c.patch.rigid_approach_m, 1e-5);
  // `auto` chooses at the patch's rigid approach, or, for a patch built touching (rigid_approach_m = 0, e.g. the
  // analytic grooves), at the Hertz approach for the case's load
  problem.selection_approach_m = c.patch.rigid_approach_m > 0.0 ? c.patch.rigid_approach_m : hertz_approach;
  problem.creepages.reference = c.creepages;
  problem.rolling_speed_m_per_s = 1.0;  // frictional power per unit speed = wear index
  return problem;
}

}  // namespace

PatchSolution SolveBenchPatch(const BenchCase& c, const PatchSolveOptions& options) {
  options.validate();
  const RigidContactPoint point = HertzPointOf(c);
  PatchProblem problem = CaseProblem(c, options.model, point, options.approach_m);
  problem.solve_tangential = options.solve_tangential;
  return SolvePatch(problem, ContactOptionsFor(c, options));
}

BenchPatchResult SummariseBenchPatch(const PatchSolution& s) {
  BenchPatchResult out;
  out.model = s.model;
  out.normal_status = s.normal.status;
  out.tangential_status = s.tangential.status;
  const bool kp = s.model != ContactModel::Hertz;
  if (!s.normal.in_contact) return out;
  out.in_contact = true;
  out.pmax_Pa = s.normal.pmax_Pa;
  out.area_m2 = s.normal.area_m2;
  out.fn_N = s.normal.fn_N;  // along the reference normal (KP: KpResult::fn_N)
  out.approach_m = s.approach_m;
  out.alpha_c_deg = s.normal.alpha_c_deg;
  if (!s.tangential.solved) return out;
  out.fx_N = s.tangential.fx_N;
  out.fy_N = s.tangential.fy_N;
  if (!kp) {
    out.wear_index_N = s.tangential.frictional_power_W;  // at unit rolling speed
  } else {
    // sum |p . s| dA (the KP-patch FASTSIM reports the frictional power only with a rolling speed; compute it here
    // from the field so that both variants are the same sum)
    double wear = 0.0;
    const FastsimResult& f = s.tangential.field;
    for (size_t e = 0; e < f.area_m2.size(); ++e)
      wear += std::fabs(f.px_Pa[e] * f.sx[e] + f.py_Pa[e] * f.sy[e]) * f.area_m2[e];
    out.wear_index_N = wear;
  }
  return out;
}

BenchPatchResult SolveBenchCase(const BenchCase& c, const PatchSolveOptions& options) {
  return SummariseBenchPatch(SolveBenchPatch(c, options));
}

double NormalForceAtApproach(const BenchCase& c, const PatchSolveOptions& options, double approach_m) {
  options.validate();
  if (!(approach_m > 0.0)) return 0.0;
  PatchSolveOptions o = options;
  o.approach_m = approach_m;
  o.solve_tangential = false;
  return SolveBenchCase(c, o).fn_N;
}

void BenchReferenceOptions::validate() const {
  require_positive(element_size_m, "bench reference element_size_m");
  require_positive(load_tolerance, "bench reference load_tolerance");
}

std::string BenchReference::status() const {
  return converged ? "converged" : normal_status + "/" + tangential_status;
}

BenchReference SolveBenchReference(const BenchCase& c, const BenchReferenceOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  const RigidContactPoint point = HertzPointOf(c);
  const PatchProblem problem = CaseProblem(c, ContactModel::Exact, point, 0.0);  // load given on fn_bar
  WheelContactOptions w;
  w.model = ContactModel::Exact;
  w.material = c.material;
  w.friction_coefficient = c.friction_coefficient;
  w.load_tolerance = options.load_tolerance;  // the BEM's own tolerance is min(1e-7, 0.1 of this)
  w.exact_element_size_m = options.element_size_m;
  const PatchSolution s = SolvePatch(problem, w);
  BenchReference out;
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.normal_status = s.normal.status;
  out.tangential_status = s.tangential.status;
  out.converged = s.normal.in_contact && s.normal.status == "ok" &&
                  (s.tangential.status == "ok" || s.tangential.status == "full_slip");
  out.load_iterations = s.load.iterations;
  out.pmax_Pa = s.normal.pmax_Pa;
  out.area_m2 = s.normal.area_m2;
  out.fn_N = s.normal.fn_N;
  out.approach_m = s.approach_m;
  out.alpha_c_deg = s.normal.alpha_c_deg;
  out.contact_at_grid_edge = s.normal.bem.contact_at_grid_edge;
  out.bem_nx = s.normal.bem.grid.nx;
  out.bem_ns = s.normal.bem.grid.ns;
  out.fx_N = s.tangential.fx_N;
  out.fy_N = s.tangential.fy_N;
  out.wear_index_N = s.tangential.frictional_power_W;  // at rolling speed 1: sum |p_t . s| dA
  out.tangential_iterations = s.tangential.iterations;
  out.tangential_residual = s.tangential.residual;
  return out;
}

namespace {

double Relative(double value, double reference) {
  return reference != 0.0 ? value / reference - 1.0 : (value == 0.0 ? 0.0 : 1.0);
}

// Median wall time of f() in microseconds.
template <class F>
double MedianTimeUs(F&& f, const BenchOptions& o) {
  std::vector<double> t;
  double total = 0.0;
  while (static_cast<int>(t.size()) < 5 ||
         (total < o.min_time_per_measurement_s && static_cast<int>(t.size()) < o.max_repeats)) {
    const auto start = std::chrono::steady_clock::now();
    f();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.push_back(s * 1e6);
    total += s;
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

}  // namespace

std::vector<BenchRow> RunBench(const std::vector<BenchCase>& cases, const BenchOptions& options,
                               std::vector<BenchReference>* references) {
  // The exact references first, in parallel (each solve is single-threaded and deterministic; their times are those
  // of one core each), then the timed models one after the other.
  BenchReferenceOptions ref_options;
  ref_options.element_size_m = options.bem_element_size_m;
  ref_options.load_tolerance = options.reference_load_tolerance;
  ref_options.validate();
  std::vector<BenchReference> refs(cases.size());
  std::vector<std::exception_ptr> failed(cases.size());  // an exception must not leave the parallel loop
  ProgressCounter progress(options.on_progress, 2.0 * static_cast<double>(cases.size()));
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < static_cast<int>(cases.size()); ++k) {
    try {
      refs[k] = SolveBenchReference(cases[k], ref_options);
    } catch (...) {
      failed[k] = std::current_exception();
    }
    progress.Finished("reference " + cases[k].name);
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  std::vector<BenchRow> rows;
  for (size_t k = 0; k < cases.size(); ++k) {
    const BenchCase& c = cases[k];
    const BenchReference& ref = refs[k];
    const double ft_ref = std::max(std::hypot(ref.fx_N, ref.fy_N), 1e-9 * c.normal_load_N);
    struct Variant {
      ContactModel model;
      bool variable_epsilon;
      const char* name;
    };
    std::vector<Variant> variants;
    for (ContactModel model : options.models) variants.push_back({model, true, to_string(model)});
    if (options.conformal_eps055) variants.push_back({ContactModel::Conformal, false, "conformal_eps055"});
    for (const Variant& v : variants) {
      for (const BenchGrid& grid : options.grids) {
        PatchSolveOptions o;
        o.model = v.model;
        o.variable_epsilon = v.variable_epsilon;
        o.kp_spin_about_patch_centre = options.kp_spin_about_patch_centre;
        o.kp_local_flexibilities = options.kp_local_flexibilities;
        o.kp_strips = grid.kp_strips;
        o.fastsim_elements = grid.fastsim_elements;
        BenchPatchResult s;
        BenchRow row;
        row.time_us = MedianTimeUs([&] { s = SolveBenchCase(c, o); }, options);
        if (s.in_contact && s.approach_m > 0.0) {
          PatchSolveOptions a = o;
          a.approach_m = s.approach_m;
          BenchPatchResult sa;
          row.time_approach_us = MedianTimeUs([&] { sa = SolveBenchCase(c, a); }, options);
          a.solve_tangential = false;
          row.time_normal_us = MedianTimeUs([&] { sa = SolveBenchCase(c, a); }, options);
        }
        row.model = v.name;
        row.grid = grid.label();
        row.case_name = c.name;
        row.family = c.family;
        row.status = s.normal_status + "/" + s.tangential_status + (ref.contact_at_grid_edge ? "/bem_edge" : "");
        row.reference_status = ref.status();
        row.err_pmax = Relative(s.pmax_Pa, ref.pmax_Pa);
        row.err_area = Relative(s.area_m2, ref.area_m2);
        row.err_fn = Relative(NormalForceAtApproach(c, o, ref.approach_m), ref.fn_N);
        row.err_fx = (s.fx_N - ref.fx_N) / ft_ref;
        row.err_fy = (s.fy_N - ref.fy_N) / ft_ref;
        row.err_wear = Relative(s.wear_index_N, ref.wear_index_N);
        const ContactModel solved = s.model;  // auto: the chosen model, appended to the status
        if (v.model == ContactModel::Auto) row.status += std::string("/") + to_string(solved);
        row.alpha_c_deg = solved == ContactModel::Hertz ? ref.alpha_c_deg : s.alpha_c_deg;
        rows.push_back(row);
      }
    }
    progress.Finished("timed " + c.name);
  }
  if (references) *references = std::move(refs);
  return rows;
}

}  // namespace conforma
