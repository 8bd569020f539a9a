// The `exact` contact model on one patch (patch_solver.hpp), tangential part: Kalker's exact steady-rolling theory on
// the BEM grid of the normal solution (exact_tangential.hpp; docs/physics-reference.md §14), with the Blanco-Lorenzo
// coefficients on a curved patch and the model's friction law. The normal part is the reference BEM
// (patch_model_reference.cpp).
#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "conforma/error.hpp"
#include "conforma/exact_tangential.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/local_creepage.hpp"
#include "patch_models.hpp"

namespace conforma {

namespace {

// The columns of an exact patch's BEM grid as strips (centre s, normal angle, centre of the column's pressure along x,
// position on the rail surface in (t0, n0) components from the reference point at s = 0), for the per-column rigid
// slip (local_creepage.hpp). The position integrates the unit tangent t = (cos alpha, -sin alpha) (patch.hpp) with the
// mean angle of neighbouring columns.
KpResult ColumnsAsStrips(const BemResult& bem) {
  const BemGrid& g = bem.grid;
  KpResult out;
  out.strips.resize(static_cast<size_t>(std::max(g.ns, 0)));
  if (g.ns < 1) return out;
  auto tangent = [](double alpha) { return Eigen::Vector2d(std::cos(alpha), -std::sin(alpha)); };
  int origin = 0;  // the column nearest to s = 0
  for (int j = 1; j < g.ns; ++j)
    if (std::fabs(g.s_centre_m(j)) < std::fabs(g.s_centre_m(origin))) origin = j;
  for (int j = 0; j < g.ns; ++j) {
    KpStrip& strip = out.strips[static_cast<size_t>(j)];
    strip.s_m = g.s_centre_m(j);
    strip.ds_m = g.ds_m;
    strip.alpha_rad = g.alpha(j);
    double weight = 0.0, moment = 0.0;
    for (int i = 0; i < g.nx; ++i) {
      weight += bem.pressure_Pa(i, j);
      moment += bem.pressure_Pa(i, j) * g.x_centre_m(i);
    }
    strip.x_centre_m = weight > 0.0 ? moment / weight : g.x_centre_m(g.nx / 2);
  }
  out.strips[static_cast<size_t>(origin)].position_m = g.s_centre_m(origin) * tangent(g.alpha(origin));
  for (int j = origin + 1; j < g.ns; ++j)
    out.strips[static_cast<size_t>(j)].position_m =
        out.strips[static_cast<size_t>(j - 1)].position_m + g.ds_m * tangent(0.5 * (g.alpha(j) + g.alpha(j - 1)));
  for (int j = origin - 1; j >= 0; --j)
    out.strips[static_cast<size_t>(j)].position_m =
        out.strips[static_cast<size_t>(j + 1)].position_m - g.ds_m * tangent(0.5 * (g.alpha(j) + g.alpha(j + 1)));
  return out;
}

}  // namespace

PatchTangentialSolution SolveExactPatchTangential(ContactModel, const PatchNormalSolution& normal,
                                                  const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                                  const WheelContactOptions& options) {
  const BemGrid& grid = normal.bem.grid;
  if (grid.nx < 1 || normal.bem.pressure_Pa.size() == 0)
    throw InputError("exact model: the tangential problem needs the BEM normal solution of the patch");
  ExactTangentialOptions o;
  o.influence = BemInfluence::Blanco;
  o.rolling_speed_m_per_s = rolling_speed_m_per_s;
  const FrictionLaw law = options.effective_friction_law();
  o.friction_coefficient = law.static_value();
  if (!law.is_constant()) o.friction = [law](double gamma) { return law(gamma); };
  // per-column creepages (the rigid slip of every BEM column from the wheelset kinematics) or the reference ones
  const RigidSlipField w = creepages.per_strip.size() == static_cast<size_t>(grid.ns)
                               ? RigidSlipFromColumnCreepages(grid, creepages.per_strip)
                               : RigidSlipFromCreepages(grid, creepages.reference);
  const ExactTangentialResult t = SolveExactTangential(grid, normal.bem.pressure_Pa, w, options.material, o);

  PatchTangentialSolution out;
  out.solved = true;
  const bool any_adhesion = (t.state.array() == 1).any();
  out.status = t.status == ExactTangentialStatus::Converged ? (any_adhesion ? "ok" : "full_slip")
               : t.status == ExactTangentialStatus::NoContact ? "no_contact"
                                                              : "not_converged";
  out.iterations = t.sweeps;
  out.residual = t.residual;
  // the element field in FASTSIM's form (x, y = s, traction, slip), for the cell export and the wear distribution
  FastsimResult& f = out.field;
  f.status = out.status == "full_slip" ? FastsimStatus::FullSlip
             : t.status == ExactTangentialStatus::NoContact ? FastsimStatus::NoContact
                                                             : FastsimStatus::Ok;
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      if (t.state(i, j) == 0) continue;
      f.x_m.push_back(grid.x_centre_m(i));
      f.y_m.push_back(grid.s_centre_m(j));
      f.area_m2.push_back(grid.element_area_m2());
      f.px_Pa.push_back(t.px_Pa(i, j));
      f.py_Pa.push_back(t.ps_Pa(i, j));
      f.sx.push_back(t.sx(i, j));
      f.sy.push_back(t.ss(i, j));
      f.in_slip.push_back(t.state(i, j) == 2 ? 1 : 0);
      out.element_width_m.push_back(grid.ds_m);
    }
  f.fx_N = t.fx_N;
  f.fy_N = t.fy_N;
  f.mz_Nm = t.mz_Nm;
  f.adhesion_area_m2 = t.adhesion_area_m2;
  f.slip_area_m2 = t.slip_area_m2;
  f.frictional_power_W = t.frictional_power_W;
  CopyFieldTotals(out);
  return out;
}

// Piecewise-constant BEM pressure of the element containing (x, s); 0 outside the grid.
double ExactPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m) {
  const BemGrid& g = normal.bem.grid;
  if (g.nx < 1 || normal.bem.pressure_Pa.size() == 0) return 0.0;
  const double fi = (x_m - g.x_first_m) / g.dx_m + 0.5, fj = (s_m - g.s_first_m) / g.ds_m + 0.5;
  if (!(fi >= 0.0) || !(fj >= 0.0) || fi >= g.nx || fj >= g.ns) return 0.0;
  return normal.bem.pressure_Pa(static_cast<int>(fi), static_cast<int>(fj));
}

std::vector<FastsimCreepages> ExactColumnCreepages(const PatchNormalSolution& normal, const RigidBodyMotion& motion,
                                                   const PatchReferenceFrame& reference) {
  return StripCreepagesFromKinematics(motion, reference, ColumnsAsStrips(normal.bem));
}

}  // namespace conforma
