// EN 13674 rail heads (60E1, 54E1, 50E6, 50E4) from the arc definitions of docs/profiles-and-formats.md §1.2:
// crown arc R1 (centre (0,-R1)) to |y| = w1/2, arc R2 tangent to it to |y| = w2/2, arc R3 = 13 mm tangent to
// that until the surface heading is 1:20 (direction (-1,-20)), then the straight 1:20 head flank.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {

namespace {

struct RailHeadArcs {
  double R1, w1, R2, w2, R3;  // [mm]
};

RailHeadArcs arcs_of(RailSection section) {
  switch (section) {
    case RailSection::R60E1: return {300.0, 20.456, 80.0, 52.053, 13.0};
    case RailSection::R54E1: return {300.0, 20.024, 80.0, 49.727, 13.0};
    case RailSection::R50E4: return {300.0, 20.025, 80.0, 49.727, 13.0};
    case RailSection::R50E6: return {200.0, 30.942, 60.0, 43.838, 13.0};
  }
  throw InputError("MakeRail: unknown rail section");
}

constexpr double kMaxChord = 0.02;     // mm, sampling of the exact curve
constexpr double kFlankDepth = 30.0;   // mm below the top (uninclined) where the generated flank ends

// Appends points of the arc centre c, radius R, from angle a0 to a1 (exclusive of the start point).
void append_arc(std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& c, double R, double a0, double a1) {
  const int n = std::max(2, static_cast<int>(std::ceil(std::abs(a1 - a0) * R / kMaxChord)));
  for (int i = 1; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    pts.emplace_back(c.x() + R * std::cos(a), c.y() + R * std::sin(a));
  }
}

// Gauge-side (negative y) half of the vertical head, from the top (0,0) down the flank, in mm, z up.
std::vector<Eigen::Vector2d> half_head(const RailHeadArcs& g) {
  std::vector<Eigen::Vector2d> pts{{0.0, 0.0}};
  const Eigen::Vector2d c1(0.0, -g.R1);
  const Eigen::Vector2d t1(-g.w1 / 2, -g.R1 + std::sqrt(g.R1 * g.R1 - g.w1 * g.w1 / 4));
  const Eigen::Vector2d u1 = (t1 - c1) / g.R1;
  append_arc(pts, c1, g.R1, M_PI / 2, std::atan2(u1.y(), u1.x()));
  const Eigen::Vector2d c2 = c1 + (g.R1 - g.R2) * u1;  // internally tangent at t1
  const double dy2 = -g.w2 / 2 - c2.x();
  const Eigen::Vector2d t2(-g.w2 / 2, c2.y() + std::sqrt(g.R2 * g.R2 - dy2 * dy2));
  const Eigen::Vector2d u2 = (t2 - c2) / g.R2;
  append_arc(pts, c2, g.R2, std::atan2(u1.y(), u1.x()), std::atan2(u2.y(), u2.x()));
  const Eigen::Vector2d c3 = c2 + (g.R2 - g.R3) * u2;
  const Eigen::Vector2d n3 = Eigen::Vector2d(-20.0, 1.0).normalized();  // outward normal of the 1:20 flank
  append_arc(pts, c3, g.R3, std::atan2(u2.y(), u2.x()), std::atan2(n3.y(), n3.x()));
  const Eigen::Vector2d t3 = c3 + g.R3 * n3;
  const Eigen::Vector2d d = Eigen::Vector2d(-1.0, -20.0).normalized();
  const double len = (t3.y() + kFlankDepth) / -d.y();
  const int n = static_cast<int>(std::ceil(len / kMaxChord));
  for (int i = 1; i <= n; ++i) pts.push_back(t3 + d * (len * i / n));
  return pts;
}

}  // namespace

const char* to_string(RailSection section) {
  switch (section) {
    case RailSection::R60E1: return "60E1";
    case RailSection::R54E1: return "54E1";
    case RailSection::R50E6: return "50E6";
    case RailSection::R50E4: return "50E4";
  }
  return "?";
}

Profile MakeRail(RailSection section, double inclination_rad, const ProfileFitOptions& options) {
  require_finite(inclination_rad, "inclination_rad");
  if (std::abs(inclination_rad) > 0.2) throw InputError("MakeRail: inclination_rad must be within +-0.2 rad");
  const auto half = half_head(arcs_of(section));
  std::vector<Eigen::Vector2d> pts;  // gauge side (reversed half) then field side (mirrored half)
  for (auto it = half.rbegin(); it != half.rend(); ++it) pts.push_back(*it);
  for (size_t i = 1; i < half.size(); ++i) pts.emplace_back(-half[i].x(), half[i].y());
  // Cant towards the track centre (-y): rotate counter-clockwise in (y, z) so the crown normal leans to -y.
  const double c = std::cos(inclination_rad), s = std::sin(inclination_rad);
  for (auto& p : pts) p = Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  // Highest point (parabolic refinement through the three densest samples around the maximum).
  size_t k = std::max_element(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.y() < b.y(); }) - pts.begin();
  Eigen::Vector2d top = pts[k];
  if (k > 0 && k + 1 < pts.size()) {
    const Eigen::Vector2d &a = pts[k - 1], &b = pts[k], &e = pts[k + 1];
    // vertex of the parabola z(y) through a, b, e
    const double d1 = (b.y() - a.y()) / (b.x() - a.x()), d2 = (e.y() - b.y()) / (e.x() - b.x());
    const double curv = (d2 - d1) / (e.x() - a.x());
    if (curv < 0) {  // Newton form z(y) = a_z + d1 (y - a_y) + curv (y - a_y)(y - b_y)
      const double yv = 0.5 * (a.x() + b.x()) - d1 / (2 * curv);
      top = Eigen::Vector2d(yv, a.y() + d1 * (yv - a.x()) + curv * (yv - a.x()) * (yv - b.x()));
    }
  }
  for (auto& p : pts) p = (p - top) * 1e-3;
  ProfileFitOptions fit = options;
  fit.function_of_y = false;  // already in curve order
  std::ostringstream name;
  name << to_string(section) << " rail (EN 13674), inclination " << std::setprecision(10) << inclination_rad << " rad";
  return Profile::FromPoints(std::move(pts), ProfileKind::Rail, fit, name.str());
}

}  // namespace conforma
