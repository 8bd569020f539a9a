// Track set-up and the prepared wheelset-track geometry: mounted rails, uniform profile tables, the side
// frames of a pose and the wheel silhouette (frames and conventions: include/conforma/geometry.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "geometry_internal.hpp"

namespace conforma {

const char* to_string(Side side) { return side == Side::Left ? "left" : "right"; }
const char* to_string(ContactStatus status) { return status == ContactStatus::Ok ? "ok" : "no_overlap"; }
const char* to_string(EquilibriumStatus status) {
  switch (status) {
    case EquilibriumStatus::Converged: return "converged";
    case EquilibriumStatus::NotConverged: return "not_converged";
    default: return "no_contact";
  }
}

namespace {
constexpr double kMinTrackGauge_m = 0.1;  // (a 1:5 scaled roller rig: 287 mm)
constexpr double kMaxTrackGauge_m = 1.8;
}  // namespace

void TrackSetup::validate() const {
  require_positive(gauge_m, "TrackSetup.gauge_m");
  require_non_negative(gauge_height_m, "TrackSetup.gauge_height_m");
  require_positive(flange_back_distance_m, "TrackSetup.flange_back_distance_m");
  // a gauge in mm was accepted and failed later as "no rigid contact" (fuzzing, session 25): 381 mm (the narrowest
  // public gauge) ... 1.8 m (broad gauges reach 1.676 m)
  const std::pair<double, const char*> lengths[] = {{gauge_m, "TrackSetup.gauge_m"},
                                                    {flange_back_distance_m, "TrackSetup.flange_back_distance_m"}};
  for (const auto& [value, name] : lengths)
    if (value < kMinTrackGauge_m || value > kMaxTrackGauge_m) {
      char text[240];
      std::snprintf(text, sizeof text, "%s = %g m is outside %g ... %g m: not a railway track (unit?)", name, value,
                    kMinTrackGauge_m, kMaxTrackGauge_m);
      throw InputError(text);
    }
  require_finite(flange_back_position_m, "TrackSetup.flange_back_position_m");
  for (int k = 0; k < 2; ++k) {
    const std::string name = std::string("TrackSetup.nominal_radius_m[") + (k == 0 ? "left" : "right") + "]";
    require_positive(nominal_radius_m[k], name.c_str());
    // a wheel radius of 1 pm or 355 m gave a contact with exit 0 (fuzzing, session 25); scaled roller rigs (1:10)
    // run ~46 mm, locomotive wheels ~0.63 m
    if (nominal_radius_m[k] < kMinWheelRadius_m || nominal_radius_m[k] > kMaxWheelRadius_m) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "the nominal (taping-line) wheel radius %s = %.6g m (command line: --r0-mm; scenario: "
                    "profiles.wheel_radius_mm) is not a railway wheel's (%.3g ... %.3g m): unit?",
                    name.c_str(), nominal_radius_m[k], kMinWheelRadius_m, kMaxWheelRadius_m);
      throw InputError(text);
    }
  }
  require_finite(rail_inclination_rad, "TrackSetup.rail_inclination_rad");
  if (std::abs(rail_inclination_rad) > 0.2) throw InputError("TrackSetup.rail_inclination_rad must be within +-0.2 rad");
  require_non_negative(roller_radius_m[0], "TrackSetup.roller_radius_m[left]");
  require_non_negative(roller_radius_m[1], "TrackSetup.roller_radius_m[right]");
  for (int k = 0; k < 2; ++k) {
    const char* side = k == 0 ? "left" : "right";
    if (wheel[k].empty()) throw InputError(std::string("TrackSetup.wheel[") + side + "] is empty");
    if (rail[k].empty()) throw InputError(std::string("TrackSetup.rail[") + side + "] is empty");
    if (wheel[k].kind() != ProfileKind::Wheel)
      throw InputError(std::string("TrackSetup.wheel[") + side + "] is a rail profile (" + wheel[k].source() + ")");
    if (rail[k].kind() != ProfileKind::Rail)
      throw InputError(std::string("TrackSetup.rail[") + side + "] is a wheel profile (" + rail[k].source() + ")");
  }
}

void RequireWheelsetYaw(double yaw_rad, const std::string& name) {
  if (std::isfinite(yaw_rad) && std::abs(yaw_rad) <= kMaxWheelsetYaw_rad) return;
  char text[240];
  std::snprintf(text, sizeof text, "%s = %g mrad: a wheelset yaw on track is within +-%g mrad (unit?)", name.c_str(),
                yaw_rad * 1e3, kMaxWheelsetYaw_rad * 1e3);
  throw InputError(text);
}

TrackSetup MakeSymmetricTrack(const Profile& wheel, const Profile& rail, double rail_inclination_rad) {
  TrackSetup t;
  t.wheel = {wheel, wheel};
  t.rail = {rail, rail};
  t.rail_inclination_rad = rail_inclination_rad;
  return t;
}

namespace geometry_detail {

// Table node k (y = y0_profile + k h, profile coordinates) of p: Newton on y(s) from *s (the previous node's arc
// length, or a nearby start), clamped to [s_a, s_b]; *s becomes the node's arc length.
void tabulate_node(const Profile& p, GraphTable& t, int k, double y0_profile, double s_a, double s_b, double* s) {
  const double y = y0_profile + k * t.h;
  for (int it = 0; it < 30; ++it) {
    const double dy = p.position(*s).x() - y;
    if (std::abs(dy) < 1e-13) break;
    *s = std::clamp(*s - dy / std::max(p.tangent(*s).x(), 1e-3), s_a, s_b);
  }
  const Eigen::Vector2d q = p.position(*s), tg = p.tangent(*s);
  t.z[k] = q.y();
  t.dz[k] = tg.y() / tg.x();
  t.arc_slope[k] = std::sqrt(1 + t.dz[k] * t.dz[k]);
  t.kappa[k] = p.curvature(*s);
  t.s[k] = *s;
}

bool function_like(const Profile& p, double s, double max_slope) {
  const Eigen::Vector2d t = p.tangent(s);
  return t.x() > 0 && std::abs(t.y()) <= max_slope * t.x();
}

// Uniform table of the longest function-like part (tangent towards +y, |slope| <= max_slope) of a profile, in the
// profile's own y (the caller shifts y0). Nodes are found by Newton on y(s) along the spline (profile.hpp).
GraphTable build_table(const Profile& p, double spacing, double max_slope, const char* what) {
  const double hs = p.spacing();
  const int n = static_cast<int>(std::round(p.length() / hs)) + 1;
  int best_a = 0, best_b = -1, a = -1;
  for (int i = 0; i <= n; ++i) {
    const bool good = i < n && function_like(p, std::min(i * hs, p.length()), max_slope);
    if (good && a < 0) a = i;
    if (!good && a >= 0) {
      if (i - 1 - a > best_b - best_a) { best_a = a; best_b = i - 1; }
      a = -1;
    }
  }
  if (best_b - best_a < 4)
    throw InputError(std::string(what) + " (" + p.source() + ") has no function-like part to tabulate");
  const double s_a = best_a * hs, s_b = std::min(best_b * hs, p.length());
  const double y_a = p.position(s_a).x(), y_b = p.position(s_b).x();
  GraphTable t;
  t.h = spacing;
  t.y0 = std::ceil(y_a / spacing) * spacing;  // nodes on a global multiple of the spacing
  const int m = static_cast<int>(std::floor((y_b - t.y0) / spacing + 1e-9)) + 1;
  if (m < 4) throw InputError(std::string(what) + " (" + p.source() + ") is too narrow to tabulate");
  t.z.resize(m);
  t.dz.resize(m);
  t.kappa.resize(m);
  t.s.resize(m);
  t.arc_slope.resize(m);
  t.s_first = s_a;
  t.s_last = s_b;
  double s = s_a;
  for (int k = 0; k < m; ++k) tabulate_node(p, t, k, t.y0, s_a, s_b, &s);
  return t;
}

}  // namespace geometry_detail

namespace geometry_detail {

namespace {

// Highest point of the parabola through the highest sample b and its neighbours a, c (b itself when not concave).
Eigen::Vector2d refine_top(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double d1 = (b.y() - a.y()) / (b.x() - a.x()), d2 = (c.y() - b.y()) / (c.x() - b.x());
  const double curv = (d2 - d1) / (c.x() - a.x());
  if (curv < 0 && std::isfinite(curv)) {
    const double yv = 0.5 * (a.x() + b.x()) - d1 / (2 * curv);
    return Eigen::Vector2d(yv, a.y() + d1 * (yv - a.x()) + curv * (yv - a.x()) * (yv - b.x()));
  }
  return b;
}

}  // namespace

// Highest point of a rail curve (parabolic refinement on the samples).
Eigen::Vector2d highest_point(const std::vector<Eigen::Vector2d>& pts) {
  size_t k = std::max_element(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.y() < b.y(); }) - pts.begin();
  if (k > 0 && k + 1 < pts.size()) return refine_top(pts[k - 1], pts[k], pts[k + 1]);
  return pts[k];
}

int highest_sample(const Profile& p) {
  int top = 0;
  for (int i = 1; i < static_cast<int>(p.sample_count()); ++i)
    if (p.sample_at(i).y() > p.sample_at(top).y()) top = i;
  return top;
}

// The point subtracted from an uninclined rail's samples to mount it: its highest point at y = 0; zero when that
// point is within 1e-12 m of z = 0 (the rail is taken as it is). As mount_rail, on the stored samples.
Eigen::Vector2d uninclined_mount_shift(const Profile& rail, int top_sample) {
  const size_t k = static_cast<size_t>(top_sample);
  Eigen::Vector2d top = k > 0 && k + 1 < rail.sample_count()
                            ? refine_top(rail.sample_at(k - 1), rail.sample_at(k), rail.sample_at(k + 1))
                            : rail.sample_at(k);
  top.x() = 0.0;
  return std::abs(top.y()) < 1e-12 ? Eigen::Vector2d::Zero() : top;
}

// Mounted rail: inclined by `inclination` (cant towards the track centre, -y) and re-referenced so that its
// highest point is at z = 0 (and at y = 0 when an inclination is applied, as standard_profiles.hpp does).
// *shift: the point subtracted from the inclined samples (zero when the rail is returned as it is). The samples are
// refitted (Profile::FromPoints), also when the rail is only translated (inclination 0) unless refit_uninclined is
// false (GeometryOptions::refit_uninclined_rail): then it is translated exactly (Profile::Translated).
Profile mount_rail(const Profile& rail, double inclination, bool refit_uninclined, Eigen::Vector2d* shift) {
  if (inclination == 0.0 && !refit_uninclined) {
    *shift = uninclined_mount_shift(rail, highest_sample(rail));
    return shift->isZero() ? rail : rail.Translated(-shift->x(), -shift->y(), rail.source() + " (mounted)");
  }
  std::vector<Eigen::Vector2d> pts = rail.samples();
  const double c = std::cos(inclination), s = std::sin(inclination);
  for (auto& p : pts) p = Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  Eigen::Vector2d top = highest_point(pts);
  if (inclination == 0.0) top.x() = 0.0;
  *shift = Eigen::Vector2d::Zero();
  if (inclination == 0.0 && std::abs(top.y()) < 1e-12) return rail;
  *shift = top;
  for (auto& p : pts) p -= top;
  ProfileFitOptions fit;
  fit.function_of_y = false;
  fit.sample_spacing_m = rail.spacing();
  return Profile::FromPoints(std::move(pts), ProfileKind::Rail, fit, rail.source() + " (mounted)");
}

// Gauge-side point gauge_height below the top of the mounted rail: y of the first crossing of that level
// walking from the sample `top` (the highest) towards the gauge side (s decreasing).
double gauge_point_y(const Profile& rail, double gauge_height, int top) {
  const double level = -gauge_height;
  const double hs = rail.spacing();
  for (int i = top; i > 0; --i) {
    if (rail.position((i - 1) * hs).y() <= level) {
      double lo = (i - 1) * hs, hi = i * hs;  // z(lo) <= level < z(hi)
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (rail.position(mid).y() <= level) lo = mid; else hi = mid;
      }
      return rail.position(0.5 * (lo + hi)).x();
    }
  }
  std::ostringstream m;
  m << "rail profile (" << rail.source() << ") does not reach " << gauge_height * 1e3
    << " mm below its top on the gauge side: the gauge cannot be measured";
  throw InputError(m.str());
}

double gauge_point_y(const Profile& rail, double gauge_height) {
  const double hs = rail.spacing();
  const int n = static_cast<int>(std::round(rail.length() / hs));
  int top = 0;
  for (int i = 0; i <= n; ++i)
    if (rail.position(i * hs).y() > rail.position(top * hs).y()) top = i;
  return gauge_point_y(rail, gauge_height, top);
}

// R_r > depth of the roller's profile below its top (every profile point above the roller axis).
void check_roller_radius(double roller_radius, const GraphTable& rail, int k, const Profile& profile) {
  if (!(roller_radius > 0.0)) return;
  const double depth = -*std::min_element(rail.z.begin(), rail.z.end());
  if (!(roller_radius > depth)) {
    std::ostringstream m;
    m << "TrackSetup.roller_radius_m[" << (k == 0 ? "left" : "right") << "] = " << roller_radius
      << " m is not larger than the depth of the roller's profile (" << profile.source() << "), " << depth
      << " m below its top";
    throw InputError(m.str());
  }
}

}  // namespace geometry_detail

namespace {
using namespace geometry_detail;
}  // namespace

WheelsetTrackGeometry::WheelsetTrackGeometry(TrackSetup setup, const GeometryOptions& options)
    : setup_(std::move(setup)), options_(options) {
  setup_.validate();
  require_positive(options_.table_spacing_m, "GeometryOptions.table_spacing_m");
  require_positive(options_.scan_spacing_m, "GeometryOptions.scan_spacing_m");
  require_positive(options_.max_slope, "GeometryOptions.max_slope");
  require_non_negative(options_.candidate_window_m, "GeometryOptions.candidate_window_m");
  require_non_negative(options_.contact_tolerance_m, "GeometryOptions.contact_tolerance_m");
  wheel_origin_eta_ = 0.5 * setup_.flange_back_distance_m - setup_.flange_back_position_m;
  mean_radius_ = 0.5 * (setup_.nominal_radius_m[0] + setup_.nominal_radius_m[1]);
  for (int k = 0; k < 2; ++k) BuildSide(k);
}

void WheelsetTrackGeometry::BuildSide(int k) {
  SideData& d = sides_[k];
  d.nominal_radius = setup_.nominal_radius_m[k];
  d.roller_radius = setup_.roller_radius_m[k];
  BuildRail(k);
  d.wheel = build_table(setup_.wheel[k], options_.table_spacing_m, options_.max_slope, "wheel");
  check_roller_radius(d.roller_radius, d.rail, k, setup_.rail[k]);
}

void WheelsetTrackGeometry::BuildRail(int k) {
  SideData& d = sides_[k];
  d.mounted_rail =
      mount_rail(setup_.rail[k], setup_.rail_inclination_rad, options_.refit_uninclined_rail, &d.mount_shift);
  d.rail_origin_eta = 0.5 * setup_.gauge_m - gauge_point_y(d.mounted_rail, setup_.gauge_height_m);
  d.rail = build_table(d.mounted_rail, options_.table_spacing_m, options_.max_slope, "rail");
  d.rail_table_y0 = d.rail.y0;
  d.rail.y0 += d.rail_origin_eta;
}

WheelsetTrackGeometry::Frame WheelsetTrackGeometry::SideFrame(Side side, const WheelsetPose& pose) const {
  const double sigma = side_sign(side);
  const double psi = sigma * pose.yaw_rad, phi = sigma * pose.roll_rad;
  const double cp = std::cos(psi), sp = std::sin(psi), cf = std::cos(phi), sf = std::sin(phi);
  Frame f;
  // R = Rz(psi) Rx(phi)
  f.rotation << cp, -sp * cf, sp * sf,
                sp, cp * cf, -cp * sf,
                0.0, sf, cf;
  f.centre = Eigen::Vector3d(0.0, sigma * pose.lateral_m, mean_radius_ + pose.vertical_m);
  const double a = f.rotation(0, 0), c = f.rotation(0, 2);
  f.rho = std::hypot(a, c);
  f.cos_beta = a / f.rho;
  f.sin_beta = c / f.rho;
  return f;
}

namespace {

// Wheel on roller (geometry.hpp WHEEL ON ROLLER, docs/physics-reference.md §1.7): the wheel point P(theta) =
// c + R (r sin, b + y_w, -r cos) whose outward normal n = R (sin, -r', -cos) is orthogonal to the roller's
// circumferential direction at P, e_phi ~ (P_z + R_r, 0, -P_x):
//   g(theta) = n_x - n_z P_x / (P_z + R_r) = 0,
// solved by Newton from the rail's solution theta0 (g -> n_x, the rail's condition, for R_r -> infinity), with
// dP/dtheta = r dn/dtheta, dn/dtheta = R (cos, 0, sin). Returns false when Newton does not converge.
bool roller_silhouette_theta(const Eigen::Matrix3d& R, const Eigen::Vector3d& c, double r, double r_slope, double q1,
                             double roller_radius, double* sin_theta, double* cos_theta) {
  const double th0 = std::atan2(*sin_theta, *cos_theta);
  double th = th0;
  for (int it = 0; it < 30; ++it) {
    const double st = std::sin(th), ct = std::cos(th);
    const Eigen::Vector3d n = R * Eigen::Vector3d(st, -r_slope, -ct), dn = R * Eigen::Vector3d(ct, 0.0, st);
    const Eigen::Vector3d P = c + R * Eigen::Vector3d(r * st, q1, -r * ct);
    const double zc = P(2) + roller_radius;  // distance of P's height from the axis (> 0 near the roller top)
    if (!(zc > 0.0)) return false;
    const double g = n(0) - n(2) * P(0) / zc;
    const double dg = dn(0) - (dn(2) * P(0) + n(2) * r * dn(0)) / zc + n(2) * P(0) * r * dn(2) / (zc * zc);
    if (!(std::abs(dg) > 1e-12)) return false;
    const double step = std::clamp(g / dg, -0.1, 0.1);
    // converged: the step is below round-off of theta (not applied, so that R_r -> infinity keeps the rail's theta0
    // bit for bit)
    if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(th))) break;
    th -= step;
    if (it == 29) return false;
  }
  if (th != th0) {
    *sin_theta = std::sin(th);
    *cos_theta = std::cos(th);
  }
  return true;
}

}  // namespace

bool WheelsetTrackGeometry::SilhouettePoint(Side side, const Frame& f, double y_w, Eigen::Vector3d* point,
                                            double* theta, double* radius, double* slope) const {
  if (!SilhouettePointInSideFrame(side, f, y_w, point, theta, radius, slope)) return false;
  const double R_r = sides_[side_index(side)].roller_radius;
  if (R_r > 0.0) {
    // meridian coordinate zeta = |P - axis| - R_r = z + x^2 / (|P - axis| + z + R_r) (no cancellation for large R_r)
    Eigen::Vector3d& p = *point;
    const double zc = p(2) + R_r;
    p(2) += p(0) * p(0) / (std::hypot(p(0), zc) + zc);
  }
  return true;
}

double WheelsetTrackGeometry::RollerRollingRadius(Side side, double eta) const {
  const SideData& d = sides_[side_index(side)];
  double zr;
  if (!(d.roller_radius > 0.0) || !d.rail.eval(eta, &zr, nullptr)) return 0.0;
  return d.roller_radius + zr;
}

bool WheelsetTrackGeometry::SilhouettePointInSideFrame(Side side, const Frame& f, double y_w, Eigen::Vector3d* point,
                                                       double* theta, double* radius, double* slope) const {
  const SideData& d = sides_[side_index(side)];
  double z_w, r_slope;
  if (!d.wheel.eval(y_w, &z_w, &r_slope)) return false;
  const double r = d.nominal_radius + z_w;
  // paper 001 eqs. (4)-(6): R00 sin(theta) - R02 cos(theta) = R01 r'  ->  theta = beta + asin(R01 r' / rho)
  const double sin_gamma = f.rotation(0, 1) * r_slope / f.rho;
  if (!(std::abs(sin_gamma) < 1.0)) return false;
  const double cos_gamma = std::sqrt(1.0 - sin_gamma * sin_gamma);
  double sin_theta = f.sin_beta * cos_gamma + f.cos_beta * sin_gamma;
  double cos_theta = f.cos_beta * cos_gamma - f.sin_beta * sin_gamma;
  if (d.roller_radius > 0.0 && !roller_silhouette_theta(f.rotation, f.centre, r, r_slope, wheel_origin_eta_ + y_w,
                                                        d.roller_radius, &sin_theta, &cos_theta))
    return false;
  const Eigen::Vector3d q(r * sin_theta, wheel_origin_eta_ + y_w, -r * cos_theta);
  *point = f.centre + f.rotation * q;
  if (theta) *theta = std::atan2(sin_theta, cos_theta);
  if (radius) *radius = r;
  if (slope) *slope = r_slope;
  return true;
}

bool WheelsetTrackGeometry::RailHeight(Side side, double eta, double* z, double* slope) const {
  return sides_[side_index(side)].rail.eval(eta, z, slope);
}

bool WheelsetTrackGeometry::WheelProfileAt(Side side, double y_w, double* z_w, double* slope, double* curvature) const {
  const GraphTable& t = sides_[side_index(side)].wheel;
  if (!t.eval(y_w, z_w, slope)) return false;
  if (curvature) {
    const double u = std::clamp((y_w - t.y0) / t.h, 0.0, static_cast<double>(t.size() - 1));
    const size_t i = std::min(static_cast<size_t>(u), t.size() - 2);
    const double w = u - static_cast<double>(i);
    *curvature = (1 - w) * t.kappa[i] + w * t.kappa[i + 1];
  }
  return true;
}

double WheelsetTrackGeometry::RailArcLength(Side side, double eta) const {
  const GraphTable& t = sides_[side_index(side)].rail;
  const double u = std::clamp((eta - t.y0) / t.h, 0.0, static_cast<double>(t.size() - 1));
  const size_t i = std::min(static_cast<size_t>(u), t.size() - 2);
  const double w = u - static_cast<double>(i);
  // ds/deta = sqrt(1 + z'^2) (tabulated): Hermite on s with that slope keeps it accurate between the nodes
  const double g0 = t.arc_slope[i], g1 = t.arc_slope[i + 1];
  const double w2 = w * w, w3 = w2 * w;
  return (2 * w3 - 3 * w2 + 1) * t.s[i] + (w3 - 2 * w2 + w) * t.h * g0 + (-2 * w3 + 3 * w2) * t.s[i + 1] +
         (w3 - w2) * t.h * g1;
}

double WheelsetTrackGeometry::RailEtaAtArcLength(Side side, double s, size_t* node_hint) const {
  const GraphTable& t = sides_[side_index(side)].rail;
  if (s <= t.s.front()) return t.y0;
  if (s >= t.s.back()) return t.y_end();
  // k: the first node beyond s (std::upper_bound); from the hint, a walk to the same node (the nodes' s never decrease)
  size_t k;
  if (node_hint && *node_hint > 0 && *node_hint < t.size() && !std::isnan(s)) {
    k = *node_hint;
    while (t.s[k] <= s) ++k;  // ends before t.size(): s < t.s.back()
    while (k > 0 && t.s[k - 1] > s) --k;
    *node_hint = k;
  } else {
    k = std::upper_bound(t.s.begin(), t.s.end(), s) - t.s.begin();
    if (node_hint) *node_hint = k;
  }
  const size_t i = std::clamp<size_t>(k, 1, t.size() - 1) - 1;
  double lo = t.y0 + i * t.h, hi = lo + t.h;
  // Newton on s(eta) = s with ds/deta = sqrt(1 + z'^2), kept inside the bracketing node interval
  double eta = lo + (s - t.s[i]) / (t.s[i + 1] - t.s[i]) * t.h;
  for (int it = 0; it < 20; ++it) {
    const double f = RailArcLength(side, eta) - s;
    if (std::abs(f) < 1e-13) break;
    if (f > 0) hi = eta; else lo = eta;
    double slope = 0.0;
    t.eval(eta, nullptr, &slope);
    double next = eta - f / std::sqrt(1 + slope * slope);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    eta = next;
  }
  return eta;
}

bool WheelsetTrackGeometry::NormalGap(Side side, const Frame& f, double eta, double* y_w_guess, double* gap_m,
                                      Eigen::Vector3d* wheel_point, NormalGapWork* work) const {
  double zr, mr;
  if (!RailHeight(side, eta, &zr, &mr)) return false;
  const double nn = std::sqrt(1 + mr * mr);
  const double n_eta = -mr / nn, n_z = 1.0 / nn;
  // intersection of the rail normal line with the silhouette: f(y_w) = (p - P) x n = 0. Newton with the
  // derivative of the untilted wheel, dp/dy_w ~ (1, -r') in (eta, z): exact up to the (small) roll and yaw,
  // so the iteration converges linearly with a tiny factor; secant fallback when it stalls.
  auto cross_of = [&](const Eigen::Vector3d& p) { return (p(1) - eta) * n_z - (p(2) - zr) * n_eta; };
  auto cross = [&](double y_w, Eigen::Vector3d* p, double* r_slope, double* radius) {
    if (!SilhouettePoint(side, f, y_w, p, nullptr, radius, r_slope)) return std::nan("");
    return cross_of(*p);
  };
  Eigen::Vector3d p1;
  double y1 = *y_w_guess, r_slope = 0.0, radius = 0.0;
  double f1;
  if (work && work->has_sample && work->y_w == y1 && std::signbit(work->y_w) == std::signbit(y1)) {
    // the start is where the previous call ended: the same silhouette point (a function of side, frame and y_w)
    p1 = work->point, r_slope = work->wheel_slope, radius = work->wheel_radius_m;
    f1 = cross_of(p1);
  } else {
    f1 = cross(y1, &p1, &r_slope, &radius);
  }
  if (!std::isfinite(f1)) return false;
  for (int it = 0; it < 40 && std::abs(f1) > 1e-13; ++it) {
    double d = n_z + r_slope * n_eta;
    if (std::abs(d) < 0.05) d = d < 0 ? -0.05 : 0.05;
    const double y2 = y1 - std::clamp(f1 / d, -5e-3, 5e-3);
    Eigen::Vector3d p2;
    double s2, r2;
    const double f2 = cross(y2, &p2, &s2, &r2);
    if (!std::isfinite(f2)) return false;
    y1 = y2; f1 = f2; p1 = p2; r_slope = s2; radius = r2;
  }
  if (std::abs(f1) > 1e-9) return false;
  *y_w_guess = y1;
  *gap_m = (p1(1) - eta) * n_eta + (p1(2) - zr) * n_z;
  if (wheel_point) *wheel_point = p1;
  if (work) *work = {true, y1, p1, radius, r_slope, zr, mr};
  return true;
}

RigidContactPoint WheelsetTrackGeometry::MakeContactPoint(Side side, const Frame& f, const WheelsetPose& pose,
                                                          double y_w, double eta_rail, double gap_m,
                                                          double vertical_gap_m) const {
  (void)pose;
  const SideData& d = sides_[side_index(side)];
  const double sigma = side_sign(side);
  RigidContactPoint c;
  c.gap_m = gap_m;
  c.vertical_gap_m = vertical_gap_m;
  Eigen::Vector3d pw;
  double theta = 0, radius = d.nominal_radius, slope = 0;
  SilhouettePointInSideFrame(side, f, y_w, &pw, &theta, &radius, &slope);
  double zr = 0, mr = 0;
  RailHeight(side, eta_rail, &zr, &mr);
  c.wheel_point_m = Eigen::Vector3d(pw(0), sigma * pw(1), pw(2));
  c.rail_point_m = Eigen::Vector3d(pw(0), sigma * eta_rail, zr);
  if (d.roller_radius > 0.0) {
    // the roller point in the meridian plane through the wheel point, at R_r(y) = R_r + z_r from the axis:
    // (R_r(y) sin(phi), eta, R_r(y) cos(phi) - R_r), phi the angle of the wheel point about the axis
    const double rho = d.roller_radius + zr, zc = pw(2) + d.roller_radius, dist = std::hypot(pw(0), zc);
    const double sin_phi = pw(0) / dist, cos_phi = zc / dist;
    c.roller_rolling_radius_m = rho;
    c.roller_angle_rad = std::atan2(pw(0), zc);
    c.rail_point_m = Eigen::Vector3d(rho * sin_phi, sigma * eta_rail, zr - rho * sin_phi * sin_phi / (1.0 + cos_phi));
    // the vertical gap: the meridian gap shrinks by cos(phi) per unit of vertical lowering
    c.vertical_gap_m = vertical_gap_m / cos_phi;
  }
  c.rail_profile_m = Eigen::Vector2d(eta_rail - d.rail_origin_eta, zr);
  c.rail_s_m = RailArcLength(side, eta_rail);
  double z_w = 0, wslope = 0, wkappa = 0;
  WheelProfileAt(side, y_w, &z_w, &wslope, &wkappa);
  c.wheel_profile_m = Eigen::Vector2d(y_w, z_w);
  c.contact_angle_rad = std::atan(mr);  // rail normal (-z', 1): leans to -eta (gauge side) when z' > 0
  c.rolling_radius_m = radius;
  // lead relative to the wheel's own vertical diametral plane: x of R (r sin(theta), 0, -r cos(theta))
  c.lead_m = radius * (f.rotation(0, 0) * std::sin(theta) - f.rotation(0, 2) * std::cos(theta));
  c.wheel_theta_rad = theta;
  c.wheel_lateral_curvature_per_m = wkappa;
  const GraphTable& rt = d.rail;
  const double u = std::clamp((eta_rail - rt.y0) / rt.h, 0.0, static_cast<double>(rt.size() - 1));
  const size_t i = std::min(static_cast<size_t>(u), rt.size() - 2);
  const double w = u - static_cast<double>(i);
  c.rail_lateral_curvature_per_m = (1 - w) * rt.kappa[i] + w * rt.kappa[i + 1];
  // docs/physics-reference.md §1.1: A = cos(alpha_w) / (2 r) (wheel rolling curvature in the tilted plane; rail
  // straight; on a roller + cos(delta) / (2 R_r(y)), §1.7), B = (1/R_y^w + 1/R_y^r) / 2 with convex curvatures positive
  c.hertz_A_per_m = LongitudinalRelativeCurvature(wslope, radius, mr, c.roller_rolling_radius_m);
  c.hertz_B_per_m = 0.5 * (c.wheel_lateral_curvature_per_m + c.rail_lateral_curvature_per_m);
  return c;
}

}  // namespace conforma
