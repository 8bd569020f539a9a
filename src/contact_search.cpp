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

// Local minima of the vertical gap z_wheel(eta) - z_rail(eta) along the wheel silhouette.
static void vertical_minima(const WheelsetTrackGeometry& g, Side side, const WheelsetTrackGeometry::Frame& f,
                            std::vector<VerticalMinimum>* out) {
  out->clear();
  const double y_begin = g.WheelTableBegin(side), y_end = g.WheelTableEnd(side);
  const double eta_lo = g.RailTableBegin(side), eta_hi = g.RailTableEnd(side);
  const double step = g.options().scan_spacing_m;
  const int n = static_cast<int>(std::floor((y_end - y_begin) / step)) + 1;
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
  const int i_lo = std::max(0, static_cast<int>(std::floor((eta_lo - shift - margin - y_begin) / step)));
  const int i_hi = std::min(n - 1, static_cast<int>(std::ceil((eta_hi - shift + margin - y_begin) / step)));
  if (i_hi - i_lo < 2) return;
  double prev2 = inf, prev1 = inf;
  for (int i = i_lo; i <= i_hi + 1; ++i) {
    const double cur = (i <= i_hi) ? vgap(y_begin + i * step, nullptr) : inf;
    // i-1 is a local minimum when it is finite and not above its neighbours (strictly below the left one)
    if (i - 1 >= i_lo && std::isfinite(prev1) && prev1 < prev2 && prev1 <= cur) {
      const double yc = y_begin + (i - 1) * step;
      const double a = std::max(y_begin, yc - step), b = std::min(y_end, yc + step);
      auto fb = [&](double y) { return vgap(y, nullptr); };
      auto [ym, gm] = geometry_detail::brent_minimize(fb, a, b, 1e-10);
      VerticalMinimum m;
      m.y_w = ym;
      m.gap = vgap(ym, &m.eta);
      if (std::isfinite(m.gap)) out->push_back(m);
    }
    prev2 = prev1;
    prev1 = cur;
  }
}

std::vector<WheelsetTrackGeometry::VerticalGapMinimum> WheelsetTrackGeometry::VerticalGapMinima(
    Side side, const Frame& frame) const {
  std::vector<VerticalMinimum> minima;
  vertical_minima(*this, side, frame, &minima);
  std::vector<VerticalGapMinimum> out(minima.size());
  for (size_t i = 0; i < minima.size(); ++i) out[i] = {minima[i].y_w, minima[i].gap, minima[i].eta};
  return out;
}

bool WheelsetTrackGeometry::MinimumVerticalGap(Side side, const WheelsetPose& pose, double* gap_m,
                                               double* track_y_m) const {
  const Frame f = SideFrame(side, pose);
  std::vector<VerticalMinimum> minima;
  vertical_minima(*this, side, f, &minima);
  if (minima.empty()) return false;
  const auto best = std::min_element(minima.begin(), minima.end(),
                                     [](const auto& a, const auto& b) { return a.gap < b.gap; });
  *gap_m = best->gap;
  *track_y_m = side_sign(side) * best->eta;
  return true;
}

WheelContactResult WheelsetTrackGeometry::RigidContact(Side side, const WheelsetPose& pose) const {
  WheelContactResult result;
  const Frame f = SideFrame(side, pose);
  std::vector<VerticalMinimum> minima;
  vertical_minima(*this, side, f, &minima);
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
    auto normal_gap = [&](double eta) {
      double gap, yg = y_guess;
      if (!NormalGap(side, f, eta, &yg, &gap)) return std::numeric_limits<double>::infinity();
      y_guess = yg;
      return gap;
    };
    double eta_best = m.eta, gap_best = m.gap * std::sqrt(1 - sd * sd), y_best = m.y_w;
    if (b > a) {
      auto [eta_n, gap_n] = geometry_detail::brent_minimize(normal_gap, a, b, 1e-10);
      double yg = m.y_w, gap_check;
      if (std::isfinite(gap_n) && NormalGap(side, f, eta_n, &yg, &gap_check)) {
        eta_best = eta_n;
        gap_best = gap_check;
        y_best = yg;
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
