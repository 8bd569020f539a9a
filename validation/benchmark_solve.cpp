// One model on one bench case, the reference BEM, and the timed run over models x grids x cases
// (benchmark_cases.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "conforma/bem_reference.hpp"
#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/model_selection.hpp"

namespace conforma {

void PatchSolveOptions::validate() const {
  if (model == ContactModel::Reference) throw InputError("bench: the reference model is not a benchmarked model");
  if (kp_strips < 3) throw InputError("bench: kp_strips must be >= 3");
  if (fastsim_elements < 2) throw InputError("bench: fastsim_elements must be >= 2");
  require_positive(load_tolerance, "load_tolerance");
  require_non_negative(approach_m, "approach_m");
}

std::string BenchGrid::label() const { return "s" + std::to_string(kp_strips) + "e" + std::to_string(fastsim_elements); }

std::vector<BenchGrid> DefaultBenchGrids() { return {{11, 10}, {21, 20}, {31, 30}, {61, 50}}; }

namespace {

KpOptions KpOptionsFor(const PatchSolveOptions& o, const Material& material) {
  return KpOptionsForModel(o.model, material, o.variable_epsilon, o.kp_strips);
}

PatchSolution SolveHertzModel(const BenchCase& c, const PatchSolveOptions& o) {
  PatchSolution out;
  const HertzResult h = o.approach_m > 0.0
                            ? SolveHertzForApproach(c.hertz_A_per_m, c.hertz_B_per_m, o.approach_m, c.material)
                            : SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, c.normal_load_N, c.material);
  out.normal_status = to_string(h.status);
  if (h.status != HertzStatus::Ok) return out;
  out.in_contact = true;
  out.pmax_Pa = h.p0_Pa;
  out.area_m2 = M_PI * h.a_m * h.b_m;
  out.fn_N = h.normal_force_N;
  out.approach_m = h.approach_m;
  if (!o.solve_tangential) return out;
  FastsimHertzInput in;
  in.a_m = h.a_m;
  in.b_m = h.b_m;
  in.normal_force_N = h.normal_force_N;
  in.creepages = c.creepages;
  in.friction_coefficient = c.friction_coefficient;
  in.material = c.material;
  in.nx = in.ny = o.fastsim_elements;
  in.rolling_speed_m_per_s = 1.0;  // frictional power per unit speed = wear index
  const FastsimResult t = SolveFastsimHertz(in, FastsimOptions{});
  out.tangential_status = to_string(t.status);
  out.fx_N = t.fx_N;
  out.fy_N = t.fy_N;
  out.wear_index_N = t.frictional_power_W;
  return out;
}

// `auto`: the model chosen for the case's patch (model_selection.hpp) at its rigid approach, or, for a patch built
// touching (rigid_approach_m = 0, e.g. the analytic grooves), at the Hertz approach for the case's load.
ContactModel ResolveModel(const BenchCase& c, const PatchSolveOptions& o) {
  if (o.model != ContactModel::Auto) return o.model;
  RigidContactPoint point;
  point.hertz_A_per_m = c.hertz_A_per_m;
  point.hertz_B_per_m = c.hertz_B_per_m;
  double approach = c.patch.rigid_approach_m;
  if (!(approach > 0.0)) {
    const HertzResult h = SolveHertzForLoad(c.hertz_A_per_m, c.hertz_B_per_m, c.normal_load_N, c.material);
    approach = h.status == HertzStatus::Ok ? h.approach_m : 0.0;
  }
  return SelectContactModel(c.patch, approach, &point).model;
}

}  // namespace

PatchSolution SolveBenchPatch(const BenchCase& c, const PatchSolveOptions& options) {
  options.validate();
  PatchSolveOptions o = options;
  o.model = ResolveModel(c, options);  // auto: the per-patch choice, then that model's solve
  if (o.model == ContactModel::Hertz) return SolveHertzModel(c, o);
  PatchSolution out;
  LoadControlOptions lo;
  lo.kp = KpOptionsFor(o, c.material);
  lo.relative_tolerance = o.load_tolerance;
  const KpResult kp = o.approach_m > 0.0 ? SolveKikPiotrowskiForApproach(c.patch, o.approach_m, lo.kp)
                                         : SolveKikPiotrowskiForLoad(c.patch, c.normal_load_N, lo);
  out.normal_status = to_string(kp.status);
  if ((kp.status != KpStatus::Ok && kp.status != KpStatus::ContactAtPatchBoundary) || !(kp.fn_N > 0.0)) return out;
  out.in_contact = true;
  out.pmax_Pa = kp.pmax_Pa;
  out.area_m2 = kp.area_m2;
  out.fn_N = kp.fn_N;
  out.approach_m = kp.approach_m;
  out.alpha_c_deg = kp.alpha_c_deg;
  if (!o.solve_tangential) return out;
  CurvedFastsimOptions co;
  co.elements_per_strip = o.fastsim_elements;
  co.load_N = kp.fn_surface_N;
  CurvedFastsimResult t;
  if (o.model == ContactModel::Conformal) {
    CurvedFastsimInput in;
    in.strip_creepages = {c.creepages};
    in.friction = FrictionLaw::Constant(c.friction_coefficient);
    in.material = c.material;
    in.rolling_speed_m_per_s = 1.0;
    t = SolveCurvedFastsim(kp, in, co);
  } else {
    t = SolveFastsimOnKpPatch(kp, c.creepages, FrictionLaw::Constant(c.friction_coefficient), c.material, co);
  }
  out.tangential_status = to_string(t.status);
  out.fx_N = t.force_reference_N.x();
  out.fy_N = t.force_reference_N.y();
  // sum |p . s| dA (the KP-patch FASTSIM reports the frictional power only with a rolling speed; compute it here
  // from the field so that both variants are the same sum)
  double wear = 0.0;
  const FastsimResult& f = t.field;
  for (size_t e = 0; e < f.area_m2.size(); ++e) wear += std::fabs(f.px_Pa[e] * f.sx[e] + f.py_Pa[e] * f.sy[e]) * f.area_m2[e];
  out.wear_index_N = wear;
  return out;
}

double NormalForceAtApproach(const BenchCase& c, const PatchSolveOptions& options, double approach_m) {
  options.validate();
  PatchSolveOptions o = options;
  o.model = ResolveModel(c, options);
  if (!(approach_m > 0.0)) return 0.0;
  if (o.model == ContactModel::Hertz) {
    const HertzResult h = SolveHertzForApproach(c.hertz_A_per_m, c.hertz_B_per_m, approach_m, c.material);
    return h.status == HertzStatus::Ok ? h.normal_force_N : 0.0;
  }
  const KpResult kp = SolveKikPiotrowskiForApproach(c.patch, approach_m, KpOptionsFor(o, c.material));
  return kp.fn_N;
}

BemReferenceSolution SolveBenchReference(const BenchCase& c, int bem_x_elements) {
  BemOptions b;
  b.influence = BemInfluence::Blanco;
  b.control = BemLoadControl::NormalForce;
  b.normal_force_N = c.normal_load_N;
  b.force_measure = BemForceMeasure::ReferenceNormal;
  b.x_elements = bem_x_elements;
  b.tolerance = 1e-9;
  const BemResult r = SolveBemNormal(c.patch, c.material, b);
  BemReferenceSolution out;
  out.status = to_string(r.status);
  out.pmax_Pa = r.max_pressure_Pa;
  out.area_m2 = r.contact_area_m2;
  out.fn_N = r.normal_force_reference_N;
  out.approach_m = r.approach_m;
  out.contact_at_grid_edge = r.contact_at_grid_edge;
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

std::vector<BenchRow> RunBench(const std::vector<BenchCase>& cases, const BenchOptions& options) {
  std::vector<BenchRow> rows;
  for (const BenchCase& c : cases) {
    const BemReferenceSolution bem = SolveBenchReference(c, options.bem_x_elements);
    PatchSolveOptions ref_options;
    ref_options.model = ContactModel::Conformal;
    ref_options.kp_strips = options.tangential_reference.kp_strips;
    ref_options.fastsim_elements = options.tangential_reference.fastsim_elements;
    ref_options.load_tolerance = 1e-10;
    const PatchSolution tangential = SolveBenchPatch(c, ref_options);
    const double ft_ref = std::max(std::hypot(tangential.fx_N, tangential.fy_N), 1e-9 * c.normal_load_N);
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
        o.kp_strips = grid.kp_strips;
        o.fastsim_elements = grid.fastsim_elements;
        PatchSolution s;
        BenchRow row;
        row.time_us = MedianTimeUs([&] { s = SolveBenchPatch(c, o); }, options);
        if (s.in_contact && s.approach_m > 0.0) {
          PatchSolveOptions a = o;
          a.approach_m = s.approach_m;
          PatchSolution sa;
          row.time_approach_us = MedianTimeUs([&] { sa = SolveBenchPatch(c, a); }, options);
          a.solve_tangential = false;
          row.time_normal_us = MedianTimeUs([&] { sa = SolveBenchPatch(c, a); }, options);
        }
        row.model = v.name;
        row.grid = grid.label();
        row.case_name = c.name;
        row.family = c.family;
        row.status = s.normal_status + "/" + s.tangential_status + (bem.contact_at_grid_edge ? "/bem_edge" : "");
        row.err_pmax = Relative(s.pmax_Pa, bem.pmax_Pa);
        row.err_area = Relative(s.area_m2, bem.area_m2);
        row.err_fn = Relative(NormalForceAtApproach(c, o, bem.approach_m), bem.fn_N);
        row.err_fx = (s.fx_N - tangential.fx_N) / ft_ref;
        row.err_fy = (s.fy_N - tangential.fy_N) / ft_ref;
        row.err_wear = Relative(s.wear_index_N, tangential.wear_index_N);
        const ContactModel solved = ResolveModel(c, o);  // auto: the chosen model, appended to the status
        if (v.model == ContactModel::Auto) row.status += std::string("/") + to_string(solved);
        row.alpha_c_deg = solved == ContactModel::Hertz ? tangential.alpha_c_deg : s.alpha_c_deg;
        rows.push_back(row);
      }
    }
  }
  return rows;
}

}  // namespace conforma
