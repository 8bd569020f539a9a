// The `hertz` contact model on one patch (patch_solver.hpp): Hertz at the rigid contact point
// (docs/physics-reference.md §1.2, multi-Hertz §1.5), FASTSIM with Kalker's three flexibilities (§2.4).
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/hertz.hpp"
#include "patch_models.hpp"

namespace conforma {

PatchNormalSolution SolveHertzPatchNormal(ContactModel, const PatchInput& input, double approach_m,
                                          const WheelContactOptions& options) {
  PatchNormalSolution out;
  if (input.point == nullptr) throw InputError("hertz model: the patch has no rigid contact point");
  const RigidContactPoint& point = *input.point;
  if (approach_m <= 0.0) { out.status = "no_contact"; return out; }
  // Near-conformal points (flange root against the gauge corner) have a relative lateral curvature B <= 0,
  // where Hertz has no solution. Dropping such a point would make the wheel's forces jump as the point's B
  // crosses zero; instead B is raised to kMinLateralCurvatureRatio * A (semi-axis ratio b/a ~ 3.6) and the
  // patch is flagged "hertz_regularised". The conformal models treat these patches properly.
  constexpr double kMinLateralCurvatureRatio = 0.1;
  const double B_min = kMinLateralCurvatureRatio * point.hertz_A_per_m;
  const bool regularised = point.hertz_A_per_m > 0.0 && point.hertz_B_per_m < B_min;
  const HertzResult h = SolveHertzForApproach(point.hertz_A_per_m, regularised ? B_min : point.hertz_B_per_m,
                                              approach_m, options.material);
  out.status = regularised && h.status == HertzStatus::Ok ? "hertz_regularised" : to_string(h.status);
  if (h.status != HertzStatus::Ok) return out;
  out.in_contact = true;
  out.hertz = h;
  out.fn_N = h.normal_force_N;
  out.pmax_Pa = out.p0_Pa = h.p0_Pa;
  out.a_m = h.a_m;
  out.b_m = h.b_m;
  out.area_m2 = M_PI * h.a_m * h.b_m;
  out.width_m = 2.0 * h.b_m;
  out.length_m = 2.0 * h.a_m;
  return out;
}

PatchTangentialSolution SolveHertzPatchTangential(ContactModel, const PatchNormalSolution& normal,
                                                  const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                                  const WheelContactOptions& options) {
  FastsimHertzInput in;
  in.a_m = normal.a_m;
  in.b_m = normal.b_m;
  in.normal_force_N = normal.fn_N;
  in.creepages = creepages.reference;
  in.friction_coefficient = options.effective_friction_law().static_value();
  in.material = options.material;
  in.nx = in.ny = options.fastsim_elements;
  in.rolling_speed_m_per_s = rolling_speed_m_per_s;
  PatchTangentialSolution out;
  if (options.friction_law.is_constant()) {
    out.field = SolveFastsimHertz(in, options.fastsim);
  } else {
    // slip-dependent friction (docs/physics-reference.md §7.4): the Hertz mesh and flexibilities of
    // SolveFastsimHertz (blended at the law's static value), the variable-friction kernel on them
    FastsimPatch patch;
    BuildFastsimHertzPatch(in, options.fastsim, &patch);
    if (patch.strips.empty()) {
      out.field = SolveFastsimHertz(in, options.fastsim);  // N = 0: the NoContact result
    } else {
      SolveFastsimStripsWithLaw(patch, FastsimHertzFlexibilities(in, options.fastsim), in.creepages,
                                options.friction_law, rolling_speed_m_per_s, options.fastsim, &out.field);
    }
  }
  const FastsimResult& t = out.field;
  out.solved = true;
  out.status = to_string(t.status);
  CopyFieldTotals(out);
  out.element_width_m.assign(t.x_m.size(), 2.0 * normal.b_m / in.ny);
  return out;
}

double HertzPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m) {
  return HertzPressure(normal.hertz, x_m, s_m);
}

}  // namespace conforma
