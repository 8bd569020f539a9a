// The Kik-Piotrowski contact models on one patch (patch_solver.hpp): `kp` (planar, eps = 0.55), `kpec` (CONTACT's
// variable eps) and `conformal` (extended KP in curvilinear rail coordinates with Blanco-Lorenzo coefficients;
// docs/physics-reference.md §3, §4, §5.1). Tangential: FASTSIM on the SDEC of the KP patch (kp, kpec; §6) or the
// curved-patch FASTSIM with per-strip rigid slip (conformal; §5.2).
#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/local_creepage.hpp"
#include "patch_models.hpp"

namespace conforma {

KpOptions KpOptionsForModel(ContactModel model, const Material& material, bool conformal_variable_penetration,
                            int strips) {
  KpOptions k;
  switch (model) {
    case ContactModel::Kp: k = PlanarKpOptions(material); break;
    case ContactModel::Kpec: k = KpecOptions(material); break;
    case ContactModel::Conformal:
      k = conformal_variable_penetration ? ConformalKpecOptions(material) : ConformalKpOptions(material);
      break;
    default: throw InputError(std::string("model '") + to_string(model) + "' is not a Kik-Piotrowski model");
  }
  k.strips_across_contact = strips;
  return k;
}

PatchNormalSolution SolveKpPatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                       const WheelContactOptions& options) {
  PatchNormalSolution out;
  if (input.patch == nullptr) throw InputError(std::string(to_string(model)) + " model: the patch has no geometry");
  if (approach_m <= 0.0) { out.status = "no_contact"; return out; }
  KpOptions kp_options =
      KpOptionsForModel(model, options.material, options.conformal_variable_penetration, options.kp_strips);
  kp_options.conformity_threshold_deg = options.conformity_threshold_deg;
  out.kp = SolveKikPiotrowskiForApproach(*input.patch, approach_m, kp_options);
  const KpResult& r = out.kp;
  out.status = to_string(r.status);
  if (r.status != KpStatus::Ok && r.status != KpStatus::ContactAtPatchBoundary) return out;
  out.in_contact = r.fn_N > 0.0;
  out.fn_N = r.force_on_wheel_N.y();
  out.fs_N = r.force_on_wheel_N.x();
  out.pmax_Pa = r.pmax_Pa;
  out.p0_Pa = r.p0_Pa;
  out.area_m2 = r.area_m2;
  out.width_m = r.width_m;
  out.length_m = r.length_m;
  out.alpha_c_deg = r.alpha_c_deg;
  out.is_conformal = r.is_conformal;
  return out;
}

PatchTangentialSolution SolveKpPatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                               const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                               const WheelContactOptions& options) {
  CurvedFastsimOptions co;
  co.elements_per_strip = options.fastsim_elements;
  co.marching = options.fastsim.marching;
  co.load_N = normal.kp.fn_surface_N;
  co.spin_about_patch_centre = options.kp_spin_about_patch_centre;  // curved_fastsim.hpp, off by default
  co.local_flexibilities = options.kp_local_flexibilities;
  // kp, kpec: FASTSIM with the SDEC flexibilities over the KP patch with the reference creepages (what
  // SolveFastsimOnKpPatch does), called directly to pass the rolling speed for the frictional power; conformal:
  // the per-strip rigid slip
  CurvedFastsimInput in;
  in.friction = options.effective_friction_law();
  in.material = options.material;
  in.rolling_speed_m_per_s = rolling_speed_m_per_s;
  in.strip_creepages = model == ContactModel::Conformal && !creepages.per_strip.empty()
                           ? creepages.per_strip
                           : std::vector<FastsimCreepages>{creepages.reference};
  // The FASTSIM buffers are reused from call to call on this thread (a wheel's load control solves the tangential
  // problem at every evaluation; fresh ones cost an allocation and a zero fill of every element array each time).
  // Deterministic: SolveCurvedFastsim overwrites every element and total of both before it reads them, so what a
  // previous call left in them never reaches a result (bit-identical to fresh buffers).
  thread_local CurvedFastsimWorkspace workspace;
  thread_local CurvedFastsimResult t;
  SolveCurvedFastsim(normal.kp, in, co, &workspace, &t);
  PatchTangentialSolution out;
  out.solved = true;
  out.status = to_string(t.status);
  out.fx_N = t.force_reference_N.x();
  out.fy_N = t.force_reference_N.y();
  out.mz_Nm = t.moment_reference_Nm.z();
  out.has_equivalent_ellipse = true;
  out.a_m = t.sdec.a_m;
  out.b_m = t.sdec.b_m;
  out.adhesion_area_m2 = t.adhesion_area_m2;
  out.slip_area_m2 = t.slip_area_m2;
  out.frictional_power_W = t.frictional_power_W;
  if (!options.keep_fields) return out;  // the totals are all the caller reads
  out.element_width_m.assign(t.field.x_m.size(), 0.0);
  const std::vector<KpStrip>& strips = normal.kp.strips;
  for (size_t k = 0; k < strips.size() && k < t.strip_first_element.size(); ++k) {
    const size_t end = k + 1 < t.strip_first_element.size() ? t.strip_first_element[k + 1] : out.element_width_m.size();
    for (size_t e = t.strip_first_element[k]; e < end; ++e) out.element_width_m[e] = strips[k].ds_m;
  }
  out.field = std::move(t.field);  // (the next call on this thread allocates the field anew)
  return out;
}

double KpPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m) {
  return KpPressureAt(normal.kp, x_m, s_m);
}

std::vector<FastsimCreepages> KpStripCreepages(const PatchNormalSolution& normal, const RigidBodyMotion& motion,
                                               const PatchReferenceFrame& reference) {
  return StripCreepagesFromKinematics(motion, reference, normal.kp);
}

}  // namespace conforma
