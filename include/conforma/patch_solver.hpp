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

#include "conforma/contact_candidates.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/patch.hpp"
#include "conforma/wheel_contact_options.hpp"

namespace conforma {

// What a patch is solved on: the curved patch (kp, kpec, conformal, reference) and/or the rigid contact point with
// its Hertz curvatures A, B (hertz). Not owned; both must outlive the call.
struct PatchInput {
  const PatchGeometry* patch = nullptr;
  const RigidContactPoint* point = nullptr;
};

// The normal solution of one patch at one approach, whatever the model.
struct PatchNormalSolution {
  bool in_contact = false;
  std::string status;             // the model's status ("ok", "no_contact", "hertz_regularised", ...)
  double fn_N = 0.0, fs_N = 0.0;  // on the wheel, along n0 and t0 (the KP models' lateral pressure resultant)
  double pmax_Pa = 0.0, p0_Pa = 0.0, area_m2 = 0.0, width_m = 0.0, length_m = 0.0;
  double a_m = 0.0, b_m = 0.0;    // Hertz semi-axes (hertz only)
  double alpha_c_deg = 0.0;       // conformity index (docs/physics-reference.md §9.1; KP models and reference)
  bool is_conformal = false;
  KpResult kp;                    // KP models: strips and pressure
  HertzResult hertz;              // hertz
};

// Creepages of a patch: at the reference point, and for the conformal model optionally one set per KP strip (the
// rigid slip of each strip from the wheelset kinematics, local_creepage.hpp).
struct PatchCreepages {
  FastsimCreepages reference;
  std::vector<FastsimCreepages> per_strip;  // empty: `reference` on every strip
  bool any() const { return reference.xi != 0.0 || reference.eta != 0.0 || reference.phi_per_m != 0.0; }
};

struct PatchTangentialSolution {
  bool solved = false;
  std::string status = "not_solved";
  double fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0;  // on the wheel, patch reference frame (x, t0, n0)
  bool has_equivalent_ellipse = false;         // KP models: a_m, b_m of the SDEC (kbtnh)
  double a_m = 0.0, b_m = 0.0;
  double adhesion_area_m2 = 0.0, slip_area_m2 = 0.0, frictional_power_W = 0.0;
  FastsimResult field;                         // element traction and slip
  std::vector<double> element_width_m;         // lateral width of each element of `field`
  double field_x_offset_m = 0.0;               // x of the field's origin relative to the patch reference point
};

// Registry entry of one contact model.
struct ContactModelSolver {
  ContactModel model;
  bool needs_patch_geometry;  // false: solved on the rigid contact point alone (Hertz curvatures)
  bool has_tangential;        // false: normal problem only (reference)
  PatchNormalSolution (*normal)(ContactModel model, const PatchInput& input, double approach_m,
                                const WheelContactOptions& options);
  PatchTangentialSolution (*tangential)(ContactModel model, const PatchNormalSolution& normal,
                                        const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                        const WheelContactOptions& options);
  double (*pressure_at)(const PatchNormalSolution& normal, double x_m, double s_m);  // on a solved normal problem
};
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
// model's "not_solved" when it has no tangential part.
PatchTangentialSolution SolvePatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                             const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                             const WheelContactOptions& options);
// Pressure of a solved normal problem at (x, s) of the patch frame.
double PatchPressureAt(ContactModel model, const PatchNormalSolution& normal, double x_m, double s_m);

// One patch alone, normal and tangential.
struct PatchProblem {
  ContactModel model = ContactModel::Conformal;  // auto: ChoosePatchModel at the first-guess approach
  PatchInput input;
  // > 0: approach given (one normal solve); otherwise load given: the normal force along the reference normal
  // equals normal_load_N (the one load control, load_control.hpp), starting from first_guess_approach_m.
  double approach_m = 0.0;
  double normal_load_N = 0.0;
  double first_guess_approach_m = 0.0;
  double selection_approach_m = 0.0;  // auto: the approach at which the model is chosen (0: first_guess_approach_m)
  PatchCreepages creepages;
  double rolling_speed_m_per_s = 1.0;
  bool solve_tangential = true;
};
struct PatchSolution {
  ContactModel model = ContactModel::Hertz;  // the model that solved it (auto: the chosen one)
  double approach_m = 0.0;
  LoadControlResult load;                    // load given only
  PatchNormalSolution normal;
  PatchTangentialSolution tangential;
};
PatchSolution SolvePatch(const PatchProblem& problem, const WheelContactOptions& options);

// The Kik-Piotrowski options of a KP-type model (kp, kpec, conformal; conformal: variable or constant virtual
// penetration) with `strips` strips across the contact. InputError for hertz / reference.
KpOptions KpOptionsForModel(ContactModel model, const Material& material, bool conformal_variable_penetration,
                            int strips);

}  // namespace conforma
