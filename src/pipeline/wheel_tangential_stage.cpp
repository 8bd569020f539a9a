// Stage 2 of one wheel's contact: creepages and the tangential problem patch by patch (wheel_contact_stages.hpp).
#include <algorithm>
#include <cmath>

#include "conforma/contact_plausibility.hpp"
#include "conforma/error.hpp"
#include "conforma/local_creepage.hpp"
#include "wheel_contact_stages.hpp"
#include "wheel_motion.hpp"

namespace conforma {
namespace wheel_contact_detail {

namespace {

// Where a patch sits on the two profiles: patch-lateral s -> rail arc length and the wheel-profile y facing it
// (the wheel point moves laterally with the rail point; exact for a wheelset without roll, O(roll) otherwise).
struct ProfileMapping {
  const Profile* rail = nullptr;
  double rail_s_ref = 0.0, rail_y_ref = 0.0, wheel_y_ref = 0.0;
  ProfileMapping(const Profile& mounted_rail, double rail_s, double wheel_y)
      : rail(&mounted_rail), rail_s_ref(rail_s), rail_y_ref(mounted_rail.position(rail_s).x()), wheel_y_ref(wheel_y) {}
  double rail_s(double s) const { return rail_s_ref + s; }
  double wheel_y(double s) const { return wheel_y_ref + rail->position(rail_s_ref + s).x() - rail_y_ref; }
};

// Cells of a FASTSIM field; dx of element e = area / strip width (strip_width(e)), pressure from the normal solver.
template <class StripWidth, class Pressure>
std::vector<ContactCell> CellsOf(const FastsimResult& f, const ProfileMapping& map, double x_shift, StripWidth strip_width,
                                 Pressure pressure) {
  std::vector<ContactCell> cells(f.x_m.size());
  for (size_t e = 0; e < cells.size(); ++e) {
    ContactCell& c = cells[e];
    c.x_m = f.x_m[e] + x_shift;
    c.s_m = f.y_m[e];
    c.rail_s_m = map.rail_s(c.s_m);
    c.wheel_y_m = map.wheel_y(c.s_m);
    c.area_m2 = f.area_m2[e];
    c.length_x_m = f.area_m2[e] / strip_width(e);
    c.pressure_Pa = pressure(f.x_m[e], f.y_m[e]);
    c.traction_x_Pa = f.px_Pa[e];
    c.traction_s_Pa = f.py_Pa[e];
    c.slip_x = f.sx[e];
    c.slip_s = f.sy[e];
    c.in_slip = f.in_slip[e] != 0;
  }
  return cells;
}

}  // namespace

WheelContactReport SolveTangentialStage(const NormalStage& stage, const WheelsetTrackGeometry& geometry, Side side,
                                      const WheelsetVelocity& velocity, const WheelContactOptions& options) {
  WheelContactReport report = stage.report;
  if (stage.finished) return report;
  const CandidateResult& candidates = stage.candidates;
  const std::vector<RigidContactPoint>& hertz_points = stage.hertz_points;
  const std::vector<ContactModel>& patch_model = stage.patch_model;
  const std::vector<double>& auto_alpha_c_deg = stage.auto_alpha_c_deg;
  const std::vector<PatchFrame>& frames = stage.frames;
  const std::vector<PatchNormalSolution>& normal = stage.normal;
  const size_t n = candidates.candidates.size();
  const RigidBodyMotion motion = WheelMotionInSideFrame(geometry, side, report.pose, velocity);
  const bool kinematics = !options.creepages_given;
  for (size_t j = 0; j < n; ++j) {
    const PatchNormalSolution& s = normal[j];
    if (!s.in_contact) continue;
    const ContactCandidate& c = candidates.candidates[j];
    const ContactModel model = patch_model[j];
    const bool hertz = model == ContactModel::Hertz;
    const RigidContactPoint& point = hertz ? hertz_points[j] : c.reference;
    PatchReport p;
    p.model = model;
    p.auto_alpha_c_deg = auto_alpha_c_deg[j];
    p.normal_status = s.status;
    p.fn_N = s.fn_N;
    p.pmax_Pa = s.pmax_Pa;
    p.p0_Pa = s.p0_Pa;
    p.area_m2 = s.area_m2;
    p.width_m = s.width_m;
    p.length_m = s.length_m;
    p.a_m = s.a_m;
    p.b_m = s.b_m;
    p.alpha_c_deg = s.alpha_c_deg;
    p.is_conformal = s.is_conformal;
    p.normal_iterations = s.bem.iterations;
    p.normal_residual = s.bem.residual;
    p.contact_angle_rad = hertz ? point.contact_angle_rad : c.patch.contact_angle_rad;
    p.y_contact_rail_m = hertz ? point.rail_profile_m.x() : c.patch.reference_point_m.x();
    p.z_contact_rail_m = hertz ? point.rail_profile_m.y() : c.patch.reference_point_m.y();
    p.y_contact_wheel_m = point.wheel_profile_m.x();
    p.reference_s_on_rail_m = hertz ? point.rail_s_m : c.patch.reference_s_on_rail_m;
    p.rolling_radius_m = point.rolling_radius_m;
    p.roller_rolling_radius_m = point.roller_rolling_radius_m;
    p.roller_angle_rad = point.roller_angle_rad;
    p.lead_m = point.lead_m;
    p.approach_m = hertz ? -point.gap_m : c.patch.rigid_approach_m;
    if (!hertz && s.kp.status != KpStatus::NoContact) p.approach_m = s.kp.approach_m;
    Creepages cr = options.creepages;
    if (kinematics) {
      if (velocity.forward_speed_m_s <= 0.0) throw InputError("forward speed must be > 0 to compute creepages");
      cr = ComputeCreepages(geometry, side, report.pose, velocity, point.wheel_point_m, p.contact_angle_rad);
    }
    p.xi = cr.longitudinal;
    p.eta = cr.lateral;
    p.phi_per_m = cr.spin_per_m;
    PatchCreepages creep;
    creep.reference = FastsimCreepages{cr.longitudinal, cr.lateral, cr.spin_per_m};
    if (options.solve_tangential) {
      // with the wheelset kinematics, the models that take it (conformal, exact): the rigid slip of every strip
      const auto strip_creepages = ContactModelSolverOf(model).strip_creepages;
      if (strip_creepages != nullptr && kinematics && creep.any()) {
        PatchReferenceFrame ref;
        ref.point_m = Eigen::Vector3d(0.0, geometry.rail_origin_eta_m(side) + c.patch.reference_point_m.x(),
                                      c.patch.reference_point_m.y());
        ref.tangent = frames[j].tangent;
        ref.normal = frames[j].normal;
        creep.per_strip = strip_creepages(s, motion, ref);
      }
      const PatchTangentialSolution t =
          SolvePatchTangential(model, s, creep, velocity.forward_speed_m_s, options);
      p.tangential_status = t.status;
      if (t.solved) {
        p.fx_N = t.fx_N;
        p.fy_N = t.fy_N;
        p.mz_Nm = t.mz_Nm;
        if (t.has_equivalent_ellipse) {
          p.a_m = t.a_m;
          p.b_m = t.b_m;
        }
        p.adhesion_area_m2 = t.adhesion_area_m2;
        p.slip_area_m2 = t.slip_area_m2;
        p.frictional_power_W = t.frictional_power_W;
        p.tangential_iterations = t.iterations;
        p.tangential_residual = t.residual;
        if (options.keep_fields) {
          const ProfileMapping map(geometry.mounted_rail(side), hertz ? point.rail_s_m : c.patch.reference_s_on_rail_m,
                                   point.wheel_profile_m.x());
          p.cells = CellsOf(t.field, map, hertz ? point.lead_m : 0.0, [&t](size_t e) { return t.element_width_m[e]; },
                            [&s, pressure_at = ContactModelSolverOf(model).pressure_at](double x, double y) {
                              return pressure_at(s, x, y);
                            });
        }
      }
    } else {
      p.tangential_status = "not_solved";
    }
    // resultant on the wheel in the side frame: normal along n0 (+ the KP lateral part along t0), creep force along t0
    Eigen::Vector3d force = (p.fn_N) * frames[j].normal + (s.fs_N + p.fy_N) * frames[j].tangent;
    // on a roller the rolling direction leans by phi: the creep force along it has a vertical part
    if (frames[j].longitudinal.z() != 0.0) force += p.fx_N * frames[j].longitudinal;
    p.vertical_force_N = force.z();
    p.lateral_force_N = force.y();
    report.vertical_force_N += p.vertical_force_N;
    report.pressure_vertical_force_N +=
        hertz ? s.fn_N * frames[j].normal.z() : s.fn_N * frames[j].normal.z() + s.fs_N * frames[j].tangent.z();
    report.lateral_force_N += p.lateral_force_N;
    report.patches.push_back(p);
  }
  if (report.status != WheelContactStatus::NotConverged)
    report.status = report.patches.empty() ? WheelContactStatus::NoContact : WheelContactStatus::Ok;
  return report;
}

WheelContactReport FinishWheelContact(const NormalStage& stage, const WheelsetTrackGeometry& geometry, Side side,
                                      const WheelsetVelocity& velocity, const WheelContactOptions& options) {
  WheelContactReport report =
      stage.coupled ? *stage.coupled : SolveTangentialStage(stage, geometry, side, velocity, options);
  report.warnings = ContactPlausibilityWarnings(report, geometry, options);
  return report;
}

}  // namespace wheel_contact_detail
}  // namespace conforma
