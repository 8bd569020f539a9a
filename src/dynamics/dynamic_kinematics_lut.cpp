// The `dynamic` kinematics provider with a contact look-up table (dynamic_kinematics_lut.hpp).
#include "conforma/dynamic_kinematics_lut.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "conforma/contact_lut_grid.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"

namespace conforma {

namespace {

// The first query the table refused and how many; one per class run (the run is single-threaded). Beyond that, what
// a wider table would answer: the largest |y| and |psi| of the queries outside the table's lateral or yaw axis (0:
// none; the provider's axes hold 0, so a query outside has |y| > 0 or |psi| > 0), and whether any refusal was of
// another kind (`other`: the load axis, a non-finite patch).
struct LutRefusals {
  long count = 0;
  std::string first;
  bool other = false;
  double outside_lateral_abs_m = 0.0, outside_yaw_abs_rad = 0.0;
  void add(const std::string& what) {
    if (count++ == 0) first = what;
  }
  // a query at (y, psi) refused with an InputError: outside the grid's lateral or yaw axis, or another refusal
  void classify(const ContactLutGrid& grid, double y, double psi) {
    const bool y_out = y < grid.lateral_m.front() || y > grid.lateral_m.back();
    const bool psi_out = psi < grid.yaw_rad.front() || psi > grid.yaw_rad.back();
    other |= !y_out && !psi_out;
    if (y_out) outside_lateral_abs_m = std::max(outside_lateral_abs_m, std::fabs(y));
    if (psi_out) outside_yaw_abs_rad = std::max(outside_yaw_abs_rad, std::fabs(psi));
  }
  // every refusal was outside the lateral or yaw axis: a wider table answers them
  bool only_outside() const { return !other && (outside_lateral_abs_m > 0.0 || outside_yaw_abs_rad > 0.0); }
};

// Every force, position and angle of the wheel's patches and sums finite.
bool FiniteReport(const WheelContactReport& r) {
  for (const PatchReport& p : r.patches)
    for (double x : {p.fn_N, p.fx_N, p.fy_N, p.mz_Nm, p.contact_angle_rad, p.y_contact_rail_m, p.z_contact_rail_m,
                     p.y_contact_wheel_m, p.rolling_radius_m, p.lead_m, p.vertical_force_N, p.lateral_force_N})
      if (!std::isfinite(x)) return false;
  return std::isfinite(r.vertical_force_N) && std::isfinite(r.lateral_force_N);
}

}  // namespace

ContactLutGrid DynamicKinematicsLutGrid(const Scenario& sc, const WheelsetTrackGeometry& g, ContactModel model) {
  const QuasiStaticOptions qo = ScenarioQuasiStaticOptions(sc, model);
  const VehicleParameters& v = sc.vehicle;
  // lateral: up to the flange contact of either wheel + 3 mm
  const double y_flange = std::max(std::fabs(FlangeContactShift(g, 1.0, qo.flange_contact_angle_rad)),
                                   std::fabs(FlangeContactShift(g, -1.0, qo.flange_contact_angle_rad)));
  // yaw and loads over the classes: a |c| + 8 mrad (5 mrad let the R 400 m class of the default scenario's worn
  // wheel reach -8.7 and 8.9 mrad, outside the table: class fallbacks, docs/physics-reference.md §16.7); Q0 -/+ the
  // largest load transfer
  const double Q0 = v.static_wheel_load_N(qo.gravity_m_s2);
  double c_max = 0.0, dQ_max = 0.0;
  for (const TrackClass& tc : sc.classes) {
    c_max = std::max(c_max, std::fabs(TrackClassCurvature(tc)));
    const double a_nc = TrackClassUnbalancedAcceleration(tc, qo.gravity_m_s2, qo.cant_base_m);
    dQ_max = std::max(dQ_max, std::fabs(WheelLoadTransferN(v, a_nc)));
  }
  if (!(Q0 - dQ_max > 0.0))
    throw InputError("dynamic provider with contact: lut: a wheel is unloaded by the load transfer of a class");
  return CoverContactLutGrid(DefaultContactLutGrid(), y_flange + 3e-3, 0.5 * v.wheelbase_m * c_max + 8e-3,
                             0.5 * (Q0 - dQ_max), 1.5 * (Q0 + dQ_max));
}

std::shared_ptr<const ContactLut> BuildDynamicKinematicsLut(const Scenario& sc, const WheelsetTrackGeometry& g,
                                                            ContactModel model) {
  return BuildDynamicKinematicsLutOnGrid(sc, g, model, DynamicKinematicsLutGrid(sc, g, model));
}

std::shared_ptr<const ContactLut> BuildDynamicKinematicsLutOnGrid(const Scenario& sc, const WheelsetTrackGeometry& g,
                                                                  ContactModel model, const ContactLutGrid& grid) {
  ContactLutBuildOptions o;
  o.grid = grid;
  o.contact = ScenarioQuasiStaticOptions(sc, model).contact;
  o.wheel_profile = "wear-step wheel of " + sc.source;
  o.rail_profile = "rail of " + sc.source;
  o.track = "kinematics provider dynamic";
  return std::make_shared<const ContactLut>(BuildContactLut(g, o));
}

namespace {

// SimulateClassKinematicsWithLut, its refusals in `refusals`.
DynamicClassKinematics RunClassOnTable(const Scenario& sc, const WheelsetTrackGeometry& g, const TrackClass& tc,
                                       ContactModel model, std::shared_ptr<const ContactLut> table,
                                       const std::shared_ptr<LutRefusals>& refusals) {
  if (!table) throw InputError("dynamic provider with contact: lut: no table");
  LutEvaluationOptions evaluation;
  evaluation.creep_force = ParseLutCreepForce(sc.kinematics.dynamic.lut_creep);
  const LutContactFunction lut_contact = MakeLutContactFunction(table, evaluation);
  const LutPoseFunction lut_pose = MakeLutPoseFunction(table);
  // a refused query is recorded and answered "not converged": never used (dynamic_kinematics_lut.hpp)
  const WheelContactFunction contact = [lut_contact, refusals, table](const WheelsetTrackGeometry& geometry, Side side,
                                                                       const WheelsetPose& pose,
                                                                       const WheelsetVelocity& velocity,
                                                                       const WheelContactOptions& options) {
    WheelContactReport r;
    try {
      r = lut_contact(geometry, side, pose, velocity, options);
    } catch (const InputError& e) {
      refusals->add(std::string(to_string(side)) + " wheel: " + e.what());
      refusals->classify(table->grid, pose.lateral_m, pose.yaw_rad);
      r = WheelContactReport{};
      r.status = WheelContactStatus::NotConverged;
      return r;
    }
    if (!FiniteReport(r)) {  // never used: a refusal as well, named with its query
      char b[200];
      std::snprintf(b, sizeof b, "%s wheel: a non-finite patch from the table at y = %.6g mm, psi = %.6g mrad, Q = %.6g N",
                    to_string(side), 1e3 * pose.lateral_m, 1e3 * pose.yaw_rad, options.vertical_load_N);
      refusals->add(b);
      refusals->other = true;
      r = WheelContactReport{};
      r.status = WheelContactStatus::NotConverged;
    }
    return r;
  };
  const RigidPoseFunction pose = [lut_pose, refusals, table](const WheelsetTrackGeometry& geometry, double y,
                                                             double psi, const EquilibriumOptions& options) {
    try {
      return lut_pose(geometry, y, psi, options);
    } catch (const InputError& e) {
      refusals->add(std::string("rigid pose: ") + e.what());
      refusals->classify(table->grid, y, psi);
      EquilibriumResult r;
      r.status = EquilibriumStatus::NotConverged;
      return r;
    }
  };
  DynamicClassKinematics out = SimulateClassKinematics(sc, g, tc, model, contact, pose);
  char b[160];
  std::snprintf(b, sizeof b, ", contact look-up table %zu x %zu x %zu of the %s model (built in %.2f s), %s creep forces",
                table->grid.lateral_m.size(), table->grid.yaw_rad.size(), table->grid.load_N.size(),
                to_string(table->header.model), table->header.generation_s, sc.kinematics.dynamic.lut_creep.c_str());
  out.series.source += b;
  if (refusals->count > 0) {
    out.failure = "contact look-up table refused " + std::to_string(refusals->count) + " queries, the first: " +
                  refusals->first + (out.failure.empty() ? std::string() : "; " + out.failure);
    out.series.samples.clear();
  }
  return out;
}

}  // namespace

DynamicClassKinematics SimulateClassKinematicsWithLut(const Scenario& sc, const WheelsetTrackGeometry& g,
                                                      const TrackClass& tc, ContactModel model,
                                                      std::shared_ptr<const ContactLut> table) {
  return RunClassOnTable(sc, g, tc, model, std::move(table), std::make_shared<LutRefusals>());
}

DynamicClassKinematics SimulateClassKinematicsCoveringLut(const Scenario& sc, const WheelsetTrackGeometry& g,
                                                          const TrackClass& tc, ContactModel model,
                                                          std::shared_ptr<const ContactLut> table,
                                                          std::shared_ptr<const ContactLut>* last_table) {
  std::string widened;  // what the widenings did, for the series' source
  for (int widening = 0;; ++widening) {
    auto refusals = std::make_shared<LutRefusals>();
    DynamicClassKinematics out = RunClassOnTable(sc, g, tc, model, table, refusals);
    if (out.failure.empty() || !refusals->only_outside() || widening == kMaxLutWidenings) {
      if (last_table) *last_table = table;
      if (!widened.empty()) {
        out.series.source += widened;
        if (!out.failure.empty()) out.failure += " (after" + widened + ")";
      }
      return out;
    }
    // a grid covering every refused query with a margin (CoverContactLutGrid continues the axes' end spacing)
    const ContactLutGrid& now = table->grid;
    const double lateral_abs = std::max({std::fabs(now.lateral_m.front()), std::fabs(now.lateral_m.back()),
                                         refusals->outside_lateral_abs_m + kLutWideningLateralMarginM});
    const double yaw_abs = std::max({std::fabs(now.yaw_rad.front()), std::fabs(now.yaw_rad.back()),
                                     refusals->outside_yaw_abs_rad + kLutWideningYawMarginRad});
    const ContactLutGrid grid =
        CoverContactLutGrid(now, lateral_abs, yaw_abs, now.load_N.front(), now.load_N.back());
    table = BuildDynamicKinematicsLutOnGrid(sc, g, model, grid);
    char b[240];
    std::snprintf(b, sizeof b, "%s table widened for the class to |y| <= %.2f mm, |psi| <= %.1f mrad (%ld queries "
                  "refused, outside up to", widened.empty() ? ";" : ",",
                  1e3 * std::max(-grid.lateral_m.front(), grid.lateral_m.back()),
                  1e3 * std::max(-grid.yaw_rad.front(), grid.yaw_rad.back()), refusals->count);
    widened += b;
    if (refusals->outside_lateral_abs_m > 0.0) {
      std::snprintf(b, sizeof b, " |y| %.2f mm", 1e3 * refusals->outside_lateral_abs_m);
      widened += b;
    }
    if (refusals->outside_yaw_abs_rad > 0.0) {
      std::snprintf(b, sizeof b, " |psi| %.2f mrad", 1e3 * refusals->outside_yaw_abs_rad);
      widened += b;
    }
    widened += ")";
  }
}

std::shared_ptr<const ContactLut> DynamicKinematicsLutCache::get(const Scenario& sc, const WheelsetTrackGeometry& g,
                                                                 ContactModel model, bool* built) {
  std::vector<double> key = GeometryFingerprint(g);  // equal keys, equal geometry
  std::lock_guard<std::mutex> lock(mutex_);
  if (built) *built = false;
  if (!table_ || key != key_) {
    table_ = BuildDynamicKinematicsLut(sc, g, model);
    key_ = std::move(key);
    if (built) *built = true;
  }
  return table_;
}

}  // namespace conforma
