// The geometry of worn profiles from the geometry of the profiles they were worn from (geometry.hpp): only the table
// nodes where the profiles changed are solved again (real-time roller-rig updates, docs/physics-reference.md §18.3).
#include <algorithm>
#include <cmath>
#include <utility>

#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "geometry_internal.hpp"

namespace conforma {

namespace {

using namespace geometry_detail;

// Everything of a track set-up but its profiles.
bool SameTrackConstants(const TrackSetup& a, const TrackSetup& b) {
  return a.gauge_m == b.gauge_m && a.gauge_height_m == b.gauge_height_m &&
         a.flange_back_distance_m == b.flange_back_distance_m &&
         a.flange_back_position_m == b.flange_back_position_m && a.nominal_radius_m == b.nominal_radius_m &&
         a.rail_inclination_rad == b.rail_inclination_rad && a.roller_radius_m == b.roller_radius_m;
}

// The nodes of t from the first whose y (profile coordinates: y0_profile + k h) lies in `changed` solved again on p
// as the full constructor solves them, Newton continued from the previous node, up to the first node beyond the
// interval whose arc length comes out bit for bit as before (the nodes after it would be solved from the same start
// on the same curve). False when the interval reaches a table end or a new node is not function-like: the caller
// builds the table anew.
bool Retabulate(const Profile& p, GraphTable& t, double y0_profile, const LateralInterval& changed, double max_slope) {
  if (changed.empty()) return true;
  const int m = static_cast<int>(t.size());
  const double k_lo = std::ceil((changed.lo_m - y0_profile) / t.h), k_hi = std::floor((changed.hi_m - y0_profile) / t.h);
  if (!(k_lo >= 1.0) || !(k_hi <= m - 2.0)) return false;
  double s = t.s[static_cast<int>(k_lo) - 1];
  for (int k = static_cast<int>(k_lo); k < m; ++k) {
    const double before = t.s[k];
    tabulate_node(p, t, k, y0_profile, t.s_first, t.s_last, &s);
    if (k <= k_hi && !function_like(p, s, max_slope)) return false;
    if (k > k_hi && s == before) break;
  }
  return true;
}

}  // namespace

WheelsetTrackGeometry::WheelsetTrackGeometry(const WheelsetTrackGeometry& previous, TrackSetup worn,
                                             const std::array<LateralInterval, 2>& changed_wheel,
                                             const std::array<LateralInterval, 2>& changed_rail)
    : setup_(std::move(worn)), options_(previous.options_), wheel_origin_eta_(previous.wheel_origin_eta_),
      mean_radius_(previous.mean_radius_) {
  setup_.validate();
  if (!SameTrackConstants(setup_, previous.setup_)) {
    *this = WheelsetTrackGeometry(std::move(setup_), options_);
    return;
  }
  for (int k = 0; k < 2; ++k) {
    SideData& d = sides_[k];
    const SideData& p = previous.sides_[k];
    d.nominal_radius = p.nominal_radius;
    d.roller_radius = p.roller_radius;
    d.wheel = p.wheel;
    if (!Retabulate(setup_.wheel[k], d.wheel, d.wheel.y0, changed_wheel[k], options_.max_slope)) {
      BuildSide(k);
      continue;
    }
    d.rail = p.rail;
    d.rail_table_y0 = p.rail_table_y0;
    if (changed_rail[k].empty()) {
      d.mounted_rail = p.mounted_rail;
      d.mount_shift = p.mount_shift;
      d.rail_origin_eta = p.rail_origin_eta;
      continue;
    }
    // an uninclined rail is mounted by translation (the rail itself while its top stays at z = 0); mounting refits
    // an inclined one, and an uninclined one off z = 0 with refit_uninclined_rail
    const Profile& rail = setup_.rail[k];
    const int top = highest_sample(rail);
    const Eigen::Vector2d shift = uninclined_mount_shift(rail, top);
    if (setup_.rail_inclination_rad != 0.0 ||
        (options_.refit_uninclined_rail && (!p.mount_shift.isZero() || !shift.isZero()))) {
      BuildSide(k);
      continue;
    }
    if (shift != p.mount_shift) {  // translated to a new top: every node's values change in rounding, solved anew
      BuildRail(k);
      check_roller_radius(d.roller_radius, d.rail, k, rail);
      continue;
    }
    d.mounted_rail = shift.isZero() ? rail : rail.Translated(-shift.x(), -shift.y(), rail.source() + " (mounted)");
    d.mount_shift = shift;
    d.rail_origin_eta = 0.5 * setup_.gauge_m - gauge_point_y(d.mounted_rail, setup_.gauge_height_m, top);
    d.rail.y0 = d.rail_table_y0 + d.rail_origin_eta;
    if (!Retabulate(d.mounted_rail, d.rail, d.rail_table_y0, changed_rail[k], options_.max_slope)) {
      BuildSide(k);
      continue;
    }
    check_roller_radius(d.roller_radius, d.rail, k, rail);
  }
}

}  // namespace conforma
