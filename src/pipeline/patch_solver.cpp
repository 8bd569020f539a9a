// The one patch solver (patch_solver.hpp): the model registry and the dispatch of every patch solve.
#include "conforma/patch_solver.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "conforma/error.hpp"
#include "conforma/model_selection.hpp"
#include "patch_models.hpp"

namespace conforma {

namespace {

constexpr double kFirstBracketFraction = 0.1;  // SolvePatch, load given: first bracket size / first-guess approach

// The registry: one entry per model, in the order of ContactModel (auto has none: it chooses one of these per
// patch). Adding a model: docs/adding-a-model.md.
const std::array<ContactModelSolver, 5> kSolvers = {{
    {ContactModel::Hertz, false, true, &SolveHertzPatchNormal, &SolveHertzPatchTangential, &HertzPatchPressureAt,
     nullptr},
    {ContactModel::Kp, true, true, &SolveKpPatchNormal, &SolveKpPatchTangential, &KpPatchPressureAt, nullptr},
    {ContactModel::Kpec, true, true, &SolveKpPatchNormal, &SolveKpPatchTangential, &KpPatchPressureAt, nullptr},
    {ContactModel::Conformal, true, true, &SolveKpPatchNormal, &SolveKpPatchTangential, &KpPatchPressureAt,
     &KpStripCreepages},
    {ContactModel::Exact, true, true, &SolveReferencePatchNormal, &SolveExactPatchTangential, &ExactPatchPressureAt,
     &ExactColumnCreepages},
}};

}  // namespace

const ContactModelSolver& ContactModelSolverOf(ContactModel model) {
  for (const ContactModelSolver& solver : kSolvers)
    if (solver.model == model) return solver;
  throw InputError(std::string("model '") + to_string(model) + "' has no patch solver (auto chooses one per patch)");
}

ModelSelection ChoosePatchModel(ContactModel model, const PatchInput& input, double approach_m,
                                const ModelSelectionOptions& options) {
  if (model != ContactModel::Auto) {
    ModelSelection fixed;
    fixed.model = model;
    return fixed;
  }
  if (input.patch == nullptr) throw InputError("auto model: the patch has no geometry");
  return SelectContactModel(*input.patch, approach_m, input.point, options);
}

PatchNormalSolution SolvePatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                     const WheelContactOptions& options) {
  return ContactModelSolverOf(model).normal(model, input, approach_m, options);
}

PatchTangentialSolution SolvePatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                             const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                             const WheelContactOptions& options) {
  const ContactModelSolver& solver = ContactModelSolverOf(model);
  PatchTangentialSolution out;
  if (!creepages.any()) {  // FASTSIM gives exactly zero traction and slip: nothing to solve
    out.status = "no_creepage";
    return out;
  }
  if (!solver.has_tangential) return out;  // "not_solved"
  return solver.tangential(model, normal, creepages, rolling_speed_m_per_s, options);
}

void CopyFieldTotals(PatchTangentialSolution& out) {
  const FastsimResult& f = out.field;
  out.fx_N = f.fx_N;
  out.fy_N = f.fy_N;
  out.mz_Nm = f.mz_Nm;
  out.adhesion_area_m2 = f.adhesion_area_m2;
  out.slip_area_m2 = f.slip_area_m2;
  out.frictional_power_W = f.frictional_power_W;
}

double PatchPressureAt(ContactModel model, const PatchNormalSolution& normal, double x_m, double s_m) {
  const ContactModelSolver& solver = ContactModelSolverOf(model);
  if (solver.pressure_at == nullptr) throw InputError(std::string("model '") + to_string(model) + "' keeps no field");
  return solver.pressure_at(normal, x_m, s_m);
}

PatchSolution SolvePatch(const PatchProblem& problem, const WheelContactOptions& options) {
  options.validate();
  const bool load_given = !(problem.approach_m > 0.0);
  if (load_given) {
    require_positive(problem.normal_load_N, "normal_load_N");
    require_positive(problem.first_guess_approach_m, "first_guess_approach_m");
  }
  PatchSolution out;
  const double guess = load_given ? problem.first_guess_approach_m : problem.approach_m;
  const double selection_approach = problem.selection_approach_m > 0.0 ? problem.selection_approach_m : guess;
  out.model = ChoosePatchModel(problem.model, problem.input, selection_approach, options.auto_selection).model;
  const ContactModelSolver& solver = ContactModelSolverOf(out.model);
  if (!load_given) {
    out.approach_m = problem.approach_m;
    out.normal = solver.normal(out.model, problem.input, out.approach_m, options);
  } else {
    // the one load control over the approach; its last evaluation is at the solution
    auto carried = [&](double push) {
      out.approach_m = guess + push;
      out.normal = solver.normal(out.model, problem.input, out.approach_m, options);
      return out.normal.fn_N;
    };
    // first bracket [0.9, 1.025] x the first guess: a Hertz guess is within a few per cent of the KP answers
    // (docs/physics-reference.md §3.6), and the bracket expands where it is not
    out.load = SolveLoadControl(carried, problem.normal_load_N, kFirstBracketFraction * guess, options.load_tolerance,
                                LoadResponse::HertzPower);
    if (out.load.status != LoadControlStatus::Ok) {
      out.normal.in_contact = false;
      out.normal.status = to_string(out.load.status);
    }
  }
  if (problem.solve_tangential && out.normal.in_contact) {
    WheelContactOptions with_field = options;  // a patch solution always carries its element field
    with_field.keep_fields = true;
    out.tangential = SolvePatchTangential(out.model, out.normal, problem.creepages, problem.rolling_speed_m_per_s,
                                          with_field);
  }
  return out;
}

}  // namespace conforma
