// Rigid wheel-rail contact search with yaw and roll (geometry.hpp): coarse scan of the vertical separation
// between the wheel silhouette and the rail, Brent refinement of every local minimum, then refinement to the
// minimum of the gap along the local rail normal.
#include <algorithm>
#include <cmath>
#include <limits>

#include "conforma/geometry.hpp"
#include "geometry_internal.hpp"

namespace conforma {

namespace {
struct VerticalMinimum {
  double y_w = 0.0, gap = 0.0, eta = 0.0;
};
}  // namespace

double WheelsetTrackGeometry::VerticalGapAt(Side side, const Frame& f, double y_w, double* eta) const {
  Eigen::Vector3d p;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!SilhouettePoint(side, f, y_w, &p)) return inf;
  double zr;
  if (!RailHeight(side, p(1), &zr, nullptr)) return inf;
  if (eta) *eta = p(1);
  return p(2) - zr;
}

// Vertical gap at the rail point where the gauge corner's contact angle reaches `angle` (the first such point
// from the rail head towards the gauge side), with the silhouette's y_w and eta there. False when the rail
// never gets that steep or the silhouette does not reach the point.
bool WheelsetTrackGeometry::LimitAngleGap(Side side, const Frame& f, double angle, double* gap, double* y_w,
                                          double* eta) const {
  const GraphTable& rt = RailTable(side);
  const double slope = std::tan(angle);
  // rail head top: the highest node; the gauge side is towards smaller eta (positive slope)
  const size_t top = static_cast<size_t>(std::max_element(rt.z.begin(), rt.z.end()) - rt.z.begin());
  double eta_b = std::numeric_limits<double>::quiet_NaN();
  for (size_t i = top; i > 0; --i) {
    if (rt.dz[i - 1] >= slope && rt.dz[i] < slope) {
      const double t = (slope - rt.dz[i]) / (rt.dz[i - 1] - rt.dz[i]);
      eta_b = rt.y0 + rt.h * (static_cast<double>(i) - t);
      break;
    }
  }
  if (!std::isfinite(eta_b)) return false;
  // silhouette point facing eta_b: eta(y_w) ~ centre + wheel origin + y_w (+ small roll and yaw terms), secant
  double y0 = eta_b - f.centre(1) - wheel_origin_eta_, e0 = 0.0;
  double g0 = VerticalGapAt(side, f, y0, &e0);
  if (!std::isfinite(g0)) return false;
  double y1 = y0 - (e0 - eta_b), e1 = 0.0;
  for (int it = 0; it < 20; ++it) {
    const double g1 = VerticalGapAt(side, f, y1, &e1);
    if (!std::isfinite(g1)) return false;
    if (std::abs(e1 - eta_b) < 1e-12 || e1 == e0) {
      *gap = g1;
      *y_w = y1;
      *eta = e1;
      return std::abs(e1 - eta_b) < 1e-9;
    }
    const double y2 = y1 - (e1 - eta_b) * (y1 - y0) / (e1 - e0);
    y0 = y1, e0 = e1, y1 = y2;
  }
  return false;
}

// Local minima of the vertical gap z_wheel(eta) - z_rail(eta) along the wheel silhouette.
static void vertical_minima(const WheelsetTrackGeometry& g, Side side, const WheelsetTrackGeometry::Frame& f,
                            double window, std::vector<VerticalMinimum>* out) {
  out->clear();
  const double y_begin = g.WheelTableBegin(side), y_end = g.WheelTableEnd(side);
  const double eta_lo = g.RailTableBegin(side), eta_hi = g.RailTableEnd(side);
  const double table_h = g.WheelTable(side).h;
  const double step = table_h * std::max(1L, std::lround(g.options().scan_spacing_m / table_h));
  const int n = static_cast<int>(std::floor((y_end - y_begin) / step + 1e-9)) + 1;
  constexpr double inf = std::numeric_limits<double>::infinity();
  auto vgap = [&](double y_w, double* eta) {
    Eigen::Vector3d p;
    if (!g.SilhouettePoint(side, f, y_w, &p)) return inf;
    double zr;
    if (p(1) < eta_lo || p(1) > eta_hi || !g.RailHeight(side, p(1), &zr, nullptr)) return inf;
    if (eta) *eta = p(1);
    return p(2) - zr;
  };
  // Only the part of the wheel that can face the rail head: the silhouette eta is ~ centre + b + y_w.
  const double shift = f.centre(1) + g.wheel_origin_eta_m();
  const double margin = 5e-3 + 0.6 * std::abs(f.rotation(2, 1)) + 0.8 * f.rotation(1, 0) * f.rotation(1, 0);
  // (clamped before the conversion: a pose far off the rail, e.g. y = 1e300 m, gives indices beyond int, whose
  // conversion is undefined; an index range of fewer than 2 nodes returns below as before)
  auto node_index = [n](double index) { return static_cast<int>(std::min(double(n), std::max(-1.0, index))); };
  const int i_lo = std::max(0, node_index(std::floor((eta_lo - shift - margin - y_begin) / step)));
  const int i_hi = std::min(n - 1, node_index(std::ceil((eta_hi - shift + margin - y_begin) / step)));
  if (i_hi - i_lo < 2) return;
  // coarse scan: local minima of the sampled vertical gap
  struct Coarse { int i; double gap; };
  std::vector<Coarse> coarse;
  double coarse_min = inf;
  // fast evaluation at the scan nodes: table node values directly, only eta and z of the silhouette
  const WheelsetTrackGeometry::GraphTable& wt = g.WheelTable(side);
  const WheelsetTrackGeometry::GraphTable& rt = g.RailTable(side);
  const int stride = std::max(1, static_cast<int>(std::lround(step / wt.h)));
  const double r0 = g.NominalRadius(side), b_origin = g.wheel_origin_eta_m();
  const double inv_rh = 1.0 / rt.h, rail_last = static_cast<double>(rt.size() - 1);
  const Eigen::Matrix3d& R = f.rotation;
  const double k_gamma = R(0, 1) / f.rho;
  auto node_gap = [&](int i) {
    const size_t k = static_cast<size_t>(i) * stride;
    if (k >= wt.size()) return inf;
    const double r = r0 + wt.z[k], sin_gamma = k_gamma * wt.dz[k];
    if (!(std::abs(sin_gamma) < 1.0)) return inf;
    const double cos_gamma = std::sqrt(1.0 - sin_gamma * sin_gamma);
    const double st = f.sin_beta * cos_gamma + f.cos_beta * sin_gamma;
    const double ct = f.cos_beta * cos_gamma - f.sin_beta * sin_gamma;
    const double q0 = r * st, q1 = b_origin + wt.y0 + static_cast<double>(k) * wt.h, q2 = -r * ct;
    const double eta = f.centre(1) + R(1, 0) * q0 + R(1, 1) * q1 + R(1, 2) * q2;
    const double z = f.centre(2) + R(2, 0) * q0 + R(2, 1) * q1 + R(2, 2) * q2;
    const double u = (eta - rt.y0) * inv_rh;
    if (!(u >= 0.0) || u > rail_last) return inf;
    const size_t j = std::min(static_cast<size_t>(u), rt.size() - 2);
    const double t = u - static_cast<double>(j), t2 = t * t, t3 = t2 * t;
    const double zr = (2 * t3 - 3 * t2 + 1) * rt.z[j] + (t3 - 2 * t2 + t) * rt.h * rt.dz[j] +
                      (-2 * t3 + 3 * t2) * rt.z[j + 1] + (t3 - t2) * rt.h * rt.dz[j + 1];
    return z - zr;
  };
  // on a roller the silhouette needs a Newton solve per point (geometry.hpp WHEEL ON ROLLER): the general path
  const bool roller = g.RollerRadius(side) > 0.0;
  auto scan_gap = [&](int i) {
    if (!roller) return node_gap(i);
    const size_t k = static_cast<size_t>(i) * stride;
    return k < wt.size() ? vgap(wt.y0 + static_cast<double>(k) * wt.h, nullptr) : inf;
  };
  double prev2 = inf, prev1 = inf;
  for (int i = i_lo; i <= i_hi + 1; ++i) {
    const double cur = (i <= i_hi) ? scan_gap(i) : inf;
    // i-1 is a local minimum when it is finite and not above its neighbours (strictly below the left one)
    if (i - 1 >= i_lo && std::isfinite(prev1) && prev1 < prev2 && prev1 <= cur) {
      coarse.push_back({i - 1, prev1});
      coarse_min = std::min(coarse_min, prev1);
    }
    prev2 = prev1;
    prev1 = cur;
  }
  // Brent refinement of the minima that can be within `window` of the smallest one (the coarse samples
  // overestimate a minimum by at most ~ curvature * step^2 / 8: 20 um covers 10 mm relative radii)
  const double limit = coarse_min + window + 20e-6;
  for (const Coarse& c : coarse) {
    if (c.gap > limit) continue;
    const double yc = y_begin + c.i * step;
    const double a = std::max(y_begin, yc - step), b = std::min(y_end, yc + step);
    auto fb = [&](double y) { return vgap(y, nullptr); };
    auto [ym, gm] = geometry_detail::brent_minimize(fb, a, b, 1e-10);
    (void)gm;
    VerticalMinimum m;
    m.y_w = ym;
    m.gap = vgap(ym, &m.eta);
    if (std::isfinite(m.gap)) out->push_back(m);
  }
}

std::vector<WheelsetTrackGeometry::VerticalGapMinimum> WheelsetTrackGeometry::VerticalGapMinima(
    Side side, const Frame& frame) const {
  std::vector<VerticalMinimum> minima;
  vertical_minima(*this, side, frame, std::numeric_limits<double>::infinity(), &minima);
  std::vector<VerticalGapMinimum> out(minima.size());
  for (size_t i = 0; i < minima.size(); ++i) out[i] = {minima[i].y_w, minima[i].gap, minima[i].eta};
  return out;
}

bool WheelsetTrackGeometry::MinimumVerticalGap(Side side, const WheelsetPose& pose, double* gap_m,
                                               double* track_y_m, double max_contact_angle_rad) const {
  if (!(RollerRadius(side) > 0.0)) return MinimumGapOnce(side, pose, gap_m, track_y_m, max_contact_angle_rad);
  // Roller: the smallest meridian gap shrinks by about cos(phi) dz when the wheelset is lowered by dz (phi: the
  // contact point's angle about the roller axis, ~ lead / R_r), so the lowering that makes the wheel touch is found
  // by repeated lowering; each step leaves ~ (1 - cos(phi)) of the gap (~1e-5): 2-4 steps to round-off.
  WheelsetPose p = pose;
  double lowered = 0.0, gap = 0.0;
  for (int it = 0; it < 20; ++it) {
    if (!MinimumGapOnce(side, p, &gap, track_y_m, max_contact_angle_rad)) return false;
    // a remaining gap below round-off is not added (contact on the roller's top line, phi = 0: the first lowering is
    // exact, and the result is the rail's bit for bit)
    if (it > 0 && std::abs(gap) <= 1e-15 + 1e-13 * std::abs(lowered)) break;
    lowered += gap;
    p.vertical_m = pose.vertical_m - lowered;
  }
  *gap_m = lowered;
  return true;
}

bool WheelsetTrackGeometry::MinimumGapOnce(Side side, const WheelsetPose& pose, double* gap_m, double* track_y_m,
                                           double max_contact_angle_rad) const {
  const Frame f = SideFrame(side, pose);
  std::vector<VerticalMinimum> minima;
  const bool elastic_flange = max_contact_angle_rad < kAllContactAngles;
  // with the angle filter every minimum is refined: the one that counts need not be the deepest
  vertical_minima(*this, side, f, elastic_flange ? std::numeric_limits<double>::infinity() : 0.0, &minima);
  if (minima.empty()) return false;
  auto deeper = [](const auto& a, const auto& b) { return a.gap < b.gap; };
  auto best = std::min_element(minima.begin(), minima.end(), deeper);
  if (elastic_flange) {
    // Smallest vertical gap over the part of the rail with a contact angle up to the limit: its local minima
    // there and its boundary, where the gauge corner reaches the limit angle. The boundary keeps the minimum
    // continuous in the pose when a minimum of the allowed part merges into the flange's region.
    auto best_touching = minima.end();
    for (auto m = minima.begin(); m != minima.end(); ++m) {
      double zr, mr;
      if (!RailHeight(side, m->eta, &zr, &mr) || std::atan(mr) > max_contact_angle_rad) continue;
      if (best_touching == minima.end() || m->gap < best_touching->gap) best_touching = m;
    }
    VerticalMinimum boundary;
    const bool has_boundary = LimitAngleGap(side, f, max_contact_angle_rad, &boundary.gap, &boundary.y_w, &boundary.eta);
    if (best_touching != minima.end() && (!has_boundary || best_touching->gap <= boundary.gap)) {
      best = best_touching;
    } else if (has_boundary) {
      minima.push_back(boundary);
      best = minima.end() - 1;
    }
  }
  *gap_m = best->gap;
  *track_y_m = side_sign(side) * best->eta;
  return true;
}

WheelContactResult WheelsetTrackGeometry::RigidContact(Side side, const WheelsetPose& pose) const {
  WheelContactResult result;
  const Frame f = SideFrame(side, pose);
  std::vector<VerticalMinimum> minima;
  vertical_minima(*this, side, f, options_.candidate_window_m, &minima);
  if (minima.empty()) return result;
  double g_min = std::numeric_limits<double>::infinity();
  for (const auto& m : minima) g_min = std::min(g_min, m.gap);
  for (const auto& m : minima) {
    if (m.gap > g_min + options_.candidate_window_m) continue;
    // Minimum of the gap along the rail normal near the vertical minimum. For locally parallel surfaces at
    // contact angle delta the foot of the normal moves by about gap * sin(delta) cos(delta).
    double zr, mr;
    RailHeight(side, m.eta, &zr, &mr);
    const double sd = std::abs(mr) / std::sqrt(1 + mr * mr);
    const double half = 0.3e-3 + 2.0 * std::abs(m.gap) * sd;
    const double a = std::max(RailTableBegin(side), m.eta - half), b = std::min(RailTableEnd(side), m.eta + half);
    double y_guess = m.y_w;
    NormalGapWork work;  // each call starts at the last one's solution: its silhouette point is kept
    auto normal_gap = [&](double eta, double* y_w_out) {
      double gap, yg = y_guess;
      if (eta < a || eta > b || !NormalGap(side, f, eta, &yg, &gap, nullptr, &work))
        return std::numeric_limits<double>::infinity();
      y_guess = yg;
      if (y_w_out) *y_w_out = yg;
      return gap;
    };
    // minimum of the normal gap: parabolic (Newton) steps on three points with a shrinking spacing,
    // started at the vertical-gap minimum (Brent's method as a fallback when a step does not go down)
    double eta_best = m.eta, y_best = m.y_w;
    double gap_best = normal_gap(eta_best, &y_best);
    bool ok = std::isfinite(gap_best);
    double h = 0.05e-3;
    for (int it = 0; ok && it < 8 && h > 1e-9; ++it) {
      const double gm = normal_gap(eta_best - h, nullptr), gp = normal_gap(eta_best + h, nullptr);
      const double curv = gm + gp - 2 * gap_best;
      if (!std::isfinite(gm) || !std::isfinite(gp) || !(curv > 0)) { ok = false; break; }
      const double step = std::clamp(0.5 * h * (gm - gp) / curv, -4 * h, 4 * h);
      double y_new = y_best;
      const double g_new = normal_gap(eta_best + step, &y_new);
      if (!(g_new <= gap_best + 1e-15)) { ok = false; break; }
      eta_best += step;
      gap_best = g_new;
      y_best = y_new;
      h = std::max(std::min(h, 2 * std::abs(step)), 1e-9) * 0.3;
      if (std::abs(step) < 1e-9) break;
    }
    if (!ok && b > a) {
      auto fb = [&](double eta) { return normal_gap(eta, nullptr); };
      auto [eta_n, gap_n] = geometry_detail::brent_minimize(fb, a, b, 1e-10);
      double yg = m.y_w, gap_check;
      if (std::isfinite(gap_n) && NormalGap(side, f, eta_n, &yg, &gap_check)) {
        eta_best = eta_n;
        gap_best = gap_check;
        y_best = yg;
      } else {
        eta_best = m.eta;
        gap_best = m.gap * std::sqrt(1 - sd * sd);
        y_best = m.y_w;
      }
    }
    result.points.push_back(MakeContactPoint(side, f, pose, y_best, eta_best, gap_best, m.gap));
  }
  std::sort(result.points.begin(), result.points.end(), [](const auto& p, const auto& q) { return p.gap_m < q.gap_m; });
  result.status = result.points.empty() ? ContactStatus::NoOverlap : ContactStatus::Ok;
  if (!result.points.empty()) {
    const double g0 = result.points.front().gap_m;
    for (const auto& p : result.points)
      if (p.gap_m <= g0 + options_.contact_tolerance_m) ++result.contact_count;
  }
  return result;
}

WheelsetContactResult WheelsetTrackGeometry::RigidContacts(const WheelsetPose& pose) const {
  WheelsetContactResult r;
  r.wheel[0] = RigidContact(Side::Left, pose);
  r.wheel[1] = RigidContact(Side::Right, pose);
  return r;
}

}  // namespace conforma
