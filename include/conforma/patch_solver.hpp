#pragma once
// The one patch solver: every contact model solves one contact patch through these functions, whoever calls
// (the wheel pipeline wheel_contact.hpp, the benchmark, `auto`, the C and Python interfaces through the pipeline).
//
//   normal      SolvePatchNormal(model, input, approach)    -> PatchNormalSolution (forces, pressure field)
//   tangential  SolvePatchTangential(model, normal, creep)  -> PatchTangentialSolution (creep forces, FASTSIM field)
//   both        SolvePatch(problem)                         -> PatchSolution, approach given or load given (the
//                                                              one load control, load_control.hpp)
//
// Each model is one entry of the registry (ContactModelSolverOf): its normal and tangential solve functions,
// each in its own file (src/pipeline/patch_model_*.cpp). Adding a model: docs/adding-a-model.md.
//
// Frames: forces ON THE WHEEL in the patch's reference frame (n0 = outward rail normal at the reference point,
// t0 = n0 turned by -90 deg in the rail-profile plane, + towards the field side; x along the track).
#include <string>
#include <vector>

#include "conforma/bem_reference.hpp"
#include "conforma/contact_candidates.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/local_creepage.hpp"
#include "conforma/patch.hpp"
#include "conforma/wheel_contact_options.hpp"

namespace conforma {

// What a patch is solved on: the curved patch (kp, kpec, conformal, exact) and/or the rigid contact point with
// its Hertz curvatures A, B (hertz). Not owned; both must outlive the call.
struct PatchInput {
  const PatchGeometry* patch = nullptr;      // kp, kpec, conformal, exact and auto: required (InputError if null)
  const RigidContactPoint* point = nullptr;  // hertz: required; auto: optional (its Hertz A, B for the choice)
};

// The normal solution of one patch at one approach, whatever the model. The numbers are filled when the model found
// contact (KP models: also with status "contact_at_patch_boundary"), 0 otherwise; SolvePatch keeps the last iterate's
// numbers when its load control fails.
struct PatchNormalSolution {
  // The patch carries load: hertz: a Hertz solution; KP models: fn_N > 0; exact: normal force > 0. SolvePatch sets
  // it false when its load control fails.
  bool in_contact = false;
  // The model's status: hertz "ok" / "hertz_regularised" (B raised to 0.1 A) / HertzStatus; KP models: KpStatus;
  // exact "ok" / "no_contact" / "not_converged"; "no_contact" for approach <= 0; SolvePatch, load given: the
  // LoadControlStatus ("no_bracket", "not_converged") when the load control fails.
  std::string status;
  // N, on the wheel, along n0 and t0 (fs_N: the KP and exact models' lateral pressure resultant; 0 for hertz)
  double fn_N = 0.0, fs_N = 0.0;
  // Pa, Pa, m^2, m, m: maximum pressure; the model's p0 (hertz and exact: = pmax); contact area; extent along s^r
  // (hertz: 2 b) and along x^r (hertz: 2 a)
  double pmax_Pa = 0.0, p0_Pa = 0.0, area_m2 = 0.0, width_m = 0.0, length_m = 0.0;
  double a_m = 0.0, b_m = 0.0;    // Hertz semi-axes, m (hertz only; 0 for the other models)
  double alpha_c_deg = 0.0;       // conformity index, deg (docs/physics-reference.md §9.1; KP models and exact)
  bool is_conformal = false;      // alpha_c_deg > WheelContactOptions::conformity_threshold_deg (KP models, exact)
  KpResult kp;                    // KP models: strips and pressure (default otherwise)
  HertzResult hertz;              // hertz (default otherwise)
  BemResult bem;                  // exact: the BEM grid and pressure field (default otherwise)
};

// Creepages of a patch: at the reference point, and for the conformal model optionally one set per KP strip or BEM column (the
// rigid slip of each strip from the wheelset kinematics, local_creepage.hpp).
struct PatchCreepages {
  FastsimCreepages reference;               // xi, eta (-), phi (1/m) at the patch reference point (contact frame)
  std::vector<FastsimCreepages> per_strip;  // empty: `reference` on every strip; else one per KP strip (conformal) or per BEM column (exact)
  bool any() const { return reference.xi != 0.0 || reference.eta != 0.0 || reference.phi_per_m != 0.0; }
};

// The tangential solution of one patch. Every number is 0 (and the vectors empty) unless `solved`.
struct PatchTangentialSolution {
  bool solved = false;  // a model's FASTSIM ran (false: no creepage, or a model without a tangential part)
  // "not_solved" (no tangential part, or not asked for), "no_creepage" (all three creepages 0), else the FASTSIM
  // status of the field ("ok", "full_slip", "no_contact"; fastsim.hpp); exact: the same or "not_converged"
  std::string status = "not_solved";
  double fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0;  // on the wheel, patch reference frame (x, t0, n0); N, N, N m
  bool has_equivalent_ellipse = false;         // KP models: a_m, b_m of the SDEC (kbtnh)
  double a_m = 0.0, b_m = 0.0;                 // SDEC semi-axes, m (has_equivalent_ellipse only)
  // m^2, m^2, W. frictional_power_W: sum |p . s| V dA at the wheelset's forward speed, every model
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
  FastsimResult field;                         // element traction and slip
  std::vector<double> element_width_m;         // lateral width of each element of `field`, m (hertz: 2b / ny)
  // exact: Gauss-Seidel sweeps and the last relative traction change (exact_tangential.hpp); 0 for the FASTSIM models
  int iterations = 0;
  double residual = 0.0;
};

// Registry entry of one contact model.
struct ContactModelSolver {
  ContactModel model;         // the model of this entry
  bool needs_patch_geometry;  // false: solved on the rigid contact point alone (Hertz curvatures)
  bool has_tangential;        // false: normal problem only (none today)
  PatchNormalSolution (*normal)(ContactModel model, const PatchInput& input, double approach_m,
                                const WheelContactOptions& options);
  PatchTangentialSolution (*tangential)(ContactModel model, const PatchNormalSolution& normal,
                                        const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                        const WheelContactOptions& options);
  double (*pressure_at)(const PatchNormalSolution& normal, double x_m, double s_m);  // on a solved normal problem
  std::vector<FastsimCreepages> (*strip_creepages)(const PatchNormalSolution& normal, const RigidBodyMotion& motion,
                                                   const PatchReferenceFrame& reference);
};
// normal: the model's normal solve at an approach (m); tangential: its FASTSIM (null without a tangential part);
// pressure_at: pressure in Pa at (x, s) in m of the patch frame (every model keeps one); strip_creepages: the rigid
// slip of every strip of the solution from the wheelset kinematics (local_creepage.hpp), for
// PatchCreepages::per_strip (null: the model takes the reference point's creepages only).
// The solver of `model` (InputError for auto, which is resolved per patch first: ChoosePatchModel).
const ContactModelSolver& ContactModelSolverOf(ContactModel model);

// `auto`: the model of one patch from its undeformed geometry at approach_m (model_selection.hpp); other models
// are returned as they are (alpha_c_deg 0).
ModelSelection ChoosePatchModel(ContactModel model, const PatchInput& input, double approach_m,
                                const ModelSelectionOptions& options);

// Normal problem of one patch at its approach along the reference normal (hertz: along the point's normal).
PatchNormalSolution SolvePatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                     const WheelContactOptions& options);
// Tangential problem on a solved normal problem; status "no_creepage" without creepage (nothing solved), the
// model's "not_solved" when it has no tangential part. Without options.keep_fields a model may leave `field` and
// `element_width_m` empty (the KP models do; the totals are the same either way).
PatchTangentialSolution SolvePatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                             const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                             const WheelContactOptions& options);
// Pressure of a solved normal problem at (x, s) of the patch frame.
double PatchPressureAt(ContactModel model, const PatchNormalSolution& normal, double x_m, double s_m);

// One patch alone, normal and tangential.
struct PatchProblem {
  ContactModel model = ContactModel::Conformal;  // auto: ChoosePatchModel at the first-guess approach
  PatchInput input;                              // the geometry the model needs (see PatchInput)
  // > 0: approach given (one normal solve); otherwise load given: the normal force along the reference normal
  // equals normal_load_N (the one load control, load_control.hpp), starting from first_guess_approach_m.
  double approach_m = 0.0;              // m; default 0: load given
  double normal_load_N = 0.0;           // N, > 0 when load given (InputError otherwise)
  // m, > 0 when load given (InputError otherwise): start of the load control, its first bracket is 0.1x this
  double first_guess_approach_m = 0.0;
  double selection_approach_m = 0.0;  // auto: the approach at which the model is chosen (0: first_guess_approach_m)
  PatchCreepages creepages;            // all 0 (default): tangential status "no_creepage"
  double rolling_speed_m_per_s = 1.0;  // V, m/s, for the frictional power (default 1: power per unit speed)
  bool solve_tangential = true;        // false: normal problem only
};
struct PatchSolution {
  ContactModel model = ContactModel::Hertz;  // the model that solved it (auto: the chosen one)
  double approach_m = 0.0;                   // the approach solved at, m (load given: the last iterate)
  LoadControlResult load;                    // load given only
  PatchNormalSolution normal;                // at approach_m
  PatchTangentialSolution tangential;        // only when solve_tangential and normal.in_contact
};
PatchSolution SolvePatch(const PatchProblem& problem, const WheelContactOptions& options);

// The Kik-Piotrowski options of a KP-type model (kp, kpec, conformal; conformal: variable or constant virtual
// penetration) with `strips` strips across the contact. InputError for hertz / exact.
KpOptions KpOptionsForModel(ContactModel model, const Material& material, bool conformal_variable_penetration,
                            int strips);

}  // namespace conforma
