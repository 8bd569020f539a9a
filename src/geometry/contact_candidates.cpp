// Elastic contact candidates: interpenetration regions of one wheel as PatchGeometry (contact_candidates.hpp).
#include "conforma/contact_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(CandidateStatus status) {
  switch (status) {
    case CandidateStatus::Ok: return "ok";
    case CandidateStatus::NoContact: return "no_contact";
    default: return "no_overlap";
  }
}

namespace {

// Intersection of the silhouette with the rail between y_in (gap < 0) and y_out (gap >= 0 or outside): the
// Illinois variant of regula falsi on the bracket (superlinear; the end that stays has its gap halved), a
// bisection step where the gap at y_out is not finite (outside the tables) or the false-position point does not
// fall strictly inside. Stops when the bracket is below kCrossingTolerance or adjacent doubles.
constexpr double kCrossingTolerance = 1e-15;  // m of y_w: the gap's own round-off (~1e-17 m) over slopes >= ~0.01
double bisect_crossing(const WheelsetTrackGeometry& g, Side side, const WheelsetTrackGeometry::Frame& f, double y_in,
                       double y_out) {
  double g_in = g.VerticalGapAt(side, f, y_in), g_out = g.VerticalGapAt(side, f, y_out);
  int kept = 0;  // +1: y_in stayed in the last step, -1: y_out stayed
  for (int it = 0; it < 100; ++it) {
    if (std::abs(y_out - y_in) <= kCrossingTolerance) break;
    const double mid = 0.5 * (y_in + y_out);
    if (mid == y_in || mid == y_out) break;  // adjacent doubles
    double next = mid;
    if (std::isfinite(g_out) && g_in < 0.0 && g_out > g_in) {
      const double falsi = y_in + (y_out - y_in) * (g_in / (g_in - g_out));
      if ((falsi - y_in) * (falsi - y_out) < 0.0) next = falsi;
    }
    const double g_next = g.VerticalGapAt(side, f, next);
    if (g_next < 0.0) {
      y_in = next, g_in = g_next;
      if (kept == -1) g_out *= 0.5;  // Illinois: y_out stays twice in a row
      kept = -1;
    } else {
      y_out = next, g_out = g_next;
      if (kept == +1) g_in *= 0.5;
      kept = +1;
    }
  }
  return 0.5 * (y_in + y_out);
}

// s_ref: the reference point's arc length (the middle of the region; of a merged group, see FindContactCandidates)
ContactCandidate build_patch(const WheelsetTrackGeometry& g, Side side, const WheelsetTrackGeometry::Frame& f,
                             const WheelsetPose& pose, double eta_a, double eta_b, double s_ref, double y_w_seed,
                             const CandidateOptions& o) {
  ContactCandidate c;
  const double s_a = g.RailArcLength(side, eta_a), s_b = g.RailArcLength(side, eta_b);
  c.region_start_s_m = s_a;
  c.region_end_s_m = s_b;
  const double eta_ref = g.RailEtaAtArcLength(side, s_ref);
  double z_ref, m_ref;
  g.RailHeight(side, eta_ref, &z_ref, &m_ref);
  const double n_len = std::sqrt(1 + m_ref * m_ref);
  const Eigen::Vector2d n_ref(-m_ref / n_len, 1.0 / n_len), t_ref(1.0 / n_len, m_ref / n_len);
  double y_w = y_w_seed, gap_ref = 0.0;
  g.NormalGap(side, f, eta_ref, &y_w, &gap_ref);
  c.reference = g.MakeContactPoint(side, f, pose, y_w, eta_ref, gap_ref, gap_ref);

  PatchGeometry& p = c.patch;
  const double ds = o.strip_width_m;
  const double width = s_b - s_a;
  const double margin = std::max(o.min_margin_strips * ds, o.margin_fraction * width);
  const double s_lo = std::max(g.RailArcLength(side, g.RailTableBegin(side)), s_a - margin);
  const double s_hi = std::min(g.RailArcLength(side, g.RailTableEnd(side)), s_b + margin);
  const int n = std::max(1, static_cast<int>(std::ceil((s_hi - s_lo) / ds)));
  const double s_start = 0.5 * (s_lo + s_hi) - 0.5 * n * ds;
  p.ds_m = ds;
  p.reference_point_m = c.reference.rail_profile_m;
  p.reference_normal = n_ref;
  p.reference_s_on_rail_m = s_ref;
  p.contact_angle_rad = c.reference.contact_angle_rad;
  double gap_min = std::numeric_limits<double>::infinity();
  y_w = y_w_seed;
  for (std::vector<double>* v : {&p.s_m, &p.gap_m, &p.longitudinal_curvature_per_m, &p.wheel_radius_m, &p.alpha_rad,
                                 &p.x_offset_m})
    v->reserve(n);
  // each strip's Newton starts at the previous strip's solution, whose silhouette point `work` keeps; it also returns
  // the rail slope at eta and the wheel's radius r0 + z_w and slope at y_w (NormalGap evaluated them there)
  WheelsetTrackGeometry::NormalGapWork work;
  size_t rail_node = 0;  // RailEtaAtArcLength's search: from the previous strip's node
  for (int j = 0; j < n; ++j) {
    const double s = s_start + (j + 0.5) * ds;
    const double eta = g.RailEtaAtArcLength(side, s, &rail_node);
    double gap;
    Eigen::Vector3d wp;
    if (!o.strip_geometry && p.s_m.size() >= 2) break;  // the region yields a patch: enough for the caller
    if (!g.NormalGap(side, f, eta, &y_w, &gap, &wp, &work)) continue;  // silhouette not reachable: strip left out
    const double m_r = work.rail_slope;
    const double nl = std::sqrt(1 + m_r * m_r);
    const Eigen::Vector2d n_loc(-m_r / nl, 1.0 / nl);
    const double slope = work.wheel_slope, radius = work.wheel_radius_m;
    double kappa;
    g.WheelProfileAt(side, y_w, nullptr, nullptr, &kappa);
    p.s_m.push_back(s - s_ref);
    p.gap_m.push_back(gap);
    // docs/physics-reference.md §1.1: rolling curvature of the wheel in the tilted plane, cos(alpha_w) / r; on a
    // roller plus the roller's, cos(delta(s)) / R_r(s) (§1.7)
    const double roller_radius = g.RollerRollingRadius(side, eta);
    p.longitudinal_curvature_per_m.push_back(LongitudinalRelativeCurvature(slope, radius, m_r, roller_radius));
    p.wheel_radius_m.push_back(radius);
    if (roller_radius > 0.0) p.roller_radius_m.push_back(roller_radius);
    p.alpha_rad.push_back(std::atan2(n_loc.dot(t_ref), n_loc.dot(n_ref)));
    // lead of the silhouette point relative to the wheel's vertical diametral plane (yaw lead)
    const Eigen::Vector3d circle_centre =
        f.centre + f.rotation * Eigen::Vector3d(0.0, g.wheel_origin_eta_m() + y_w, 0.0);
    p.x_offset_m.push_back(wp(0) - circle_centre(0));
    gap_min = std::min(gap_min, gap);
  }
  if (std::isfinite(gap_min)) {
    for (double& gj : p.gap_m) gj -= gap_min;
    p.rigid_approach_m = std::max(0.0, -gap_min);
  }
  if (!o.strip_geometry) p.rigid_approach_m = std::numeric_limits<double>::quiet_NaN();  // not the region's
  return c;
}

}  // namespace

CandidateResult FindContactCandidates(const WheelsetTrackGeometry& g, Side side, const WheelsetPose& pose,
                                      const CandidateOptions& o) {
  require_positive(o.strip_width_m, "CandidateOptions.strip_width_m");
  require_non_negative(o.margin_fraction, "CandidateOptions.margin_fraction");
  require_non_negative(o.combine_distance_m, "CandidateOptions.combine_distance_m");
  CandidateResult out;
  out.pose = pose;
  const WheelsetTrackGeometry::Frame f = g.SideFrame(side, pose);
  const auto minima = g.VerticalGapMinima(side, f);
  if (minima.empty()) return out;
  out.status = CandidateStatus::NoContact;
  const double step = g.options().scan_spacing_m * 0.5;
  const double y_lo = g.WheelTableBegin(side), y_hi = g.WheelTableEnd(side);
  std::vector<std::pair<double, double>> regions;  // (y_w start, y_w end)
  std::vector<WheelsetTrackGeometry::VerticalGapMinimum> seeds;  // each region's minimum
  for (const auto& m : minima) {
    if (!(m.gap_m < 0.0)) continue;
    double a = m.y_w, b = m.y_w;
    while (a - step > y_lo && g.VerticalGapAt(side, f, a - step) < 0.0) a -= step;
    const double ya = (a - step > y_lo) ? bisect_crossing(g, side, f, a, a - step) : a;
    while (b + step < y_hi && g.VerticalGapAt(side, f, b + step) < 0.0) b += step;
    const double yb = (b + step < y_hi) ? bisect_crossing(g, side, f, b, b + step) : b;
    bool duplicate = false;
    for (const auto& r : regions) duplicate |= std::abs(r.first - ya) < 1e-9;
    if (duplicate) continue;
    regions.emplace_back(ya, yb);
    seeds.push_back(m);
  }
  // weight: the region's interpenetration area, ~ width x depth (a parabolic lobe: 2/3 of it; the factor cancels)
  struct Region { double eta_a, eta_b, s_a, s_b, seed, seed_gap, s_ref, weight; };
  std::vector<Region> rs;
  for (size_t k = 0; k < regions.size(); ++k) {
    double eta_a = 0, eta_b = 0;
    g.VerticalGapAt(side, f, regions[k].first, &eta_a);
    g.VerticalGapAt(side, f, regions[k].second, &eta_b);
    // the minimum's gap is VerticalGapAt(side, f, y_w) (VerticalGapMinima evaluates it there; finite)
    const double seed_gap = seeds[k].gap_m;
    if (!(eta_b > eta_a)) continue;
    const double s_a = g.RailArcLength(side, eta_a), s_b = g.RailArcLength(side, eta_b);
    rs.push_back({eta_a, eta_b, s_a, s_b, seeds[k].y_w, seed_gap, 0.5 * (s_a + s_b), (s_b - s_a) * std::max(0.0, -seed_gap)});
  }
  std::sort(rs.begin(), rs.end(), [](const auto& p, const auto& q) { return p.s_a < q.s_a; });
  std::vector<Region> merged;
  for (const Region& r : rs) {
    if (!merged.empty() && r.s_a - merged.back().s_b < o.combine_distance_m) {
      Region& m = merged.back();
      if (r.s_b > m.s_b) { m.s_b = r.s_b; m.eta_b = r.eta_b; }
      // reference point of the merged patch: the regions' middles weighted by their interpenetration areas (the
      // middle of the merged span may lie in the gap, far from where the load is: Manchester at y = 0, a
      // shallow second region 11 mm out; two equal regions: the centre)
      if (m.weight + r.weight > 0.0) m.s_ref = (m.weight * m.s_ref + r.weight * r.s_ref) / (m.weight + r.weight);
      m.weight += r.weight;
      if (r.seed_gap < m.seed_gap) { m.seed = r.seed; m.seed_gap = r.seed_gap; }
    } else {
      merged.push_back(r);
    }
  }
  for (const Region& r : merged) {
    ContactCandidate c = build_patch(g, side, f, pose, r.eta_a, r.eta_b, r.s_ref, r.seed, o);
    // a region whose strips the silhouette cannot reach along the rail normals (a flange pressed deep into the
    // gauge face, elastic flange) gives no patch geometry: left out rather than passed on empty
    if (c.patch.s_m.size() >= 2) out.candidates.push_back(std::move(c));
  }
  std::sort(out.candidates.begin(), out.candidates.end(),
            [](const auto& p, const auto& q) { return p.region_start_s_m < q.region_start_s_m; });
  if (!out.candidates.empty()) out.status = CandidateStatus::Ok;
  return out;
}

CandidateResult FindContactCandidatesForLoad(const WheelsetTrackGeometry& g, Side side, const WheelsetPose& pose_in,
                                             double vertical_load_N, const Material& material,
                                             const CandidateOptions& o) {
  require_non_negative(vertical_load_N, "vertical_load_N");
  material.validate();
  WheelsetPose pose = pose_in;
  double gap, y_contact;
  if (!g.MinimumVerticalGap(side, pose, &gap, &y_contact, o.max_touching_contact_angle_rad)) {
    CandidateResult none;
    none.pose = pose;
    return none;
  }
  pose.vertical_m -= gap;  // touching
  const WheelsetPose touching = pose;
  const bool elastic_flange = o.max_touching_contact_angle_rad < WheelsetTrackGeometry::kAllContactAngles;
  WheelContactResult rigid = g.RigidContact(side, pose);
  struct Point { double vertical_gap, cos_delta, A, B; };
  std::vector<Point> pts;
  for (const auto& c : rigid.points) {
    // B <= 0 (conformal): the Hertz estimate of the approach uses a small positive B instead
    const double B = std::max(c.hertz_B_per_m, 1e-3 * c.hertz_A_per_m);
    // (a flange pressed against the rail with the elastic-flange reference: negative vertical gap)
    pts.push_back({elastic_flange ? c.vertical_gap_m : std::max(0.0, c.vertical_gap_m), NormalVerticalCosine(c),
                   c.hertz_A_per_m, B});
  }
  // Hertz: N = C_H delta^(3/2) with C_H fixed by A, B and the material (hertz.hpp); one solve per point
  std::vector<double> stiffness(pts.size(), 0.0);
  for (size_t i = 0; i < pts.size(); ++i) {
    const HertzResult h = SolveHertzForApproach(pts[i].A, pts[i].B, 1e-5, material);
    if (h.status == HertzStatus::Ok) stiffness[i] = h.stiffness_N_per_m15;
  }
  auto vertical_force = [&](double dz, std::vector<double>* forces) {
    double total = 0.0;
    if (forces) forces->assign(pts.size(), 0.0);
    for (size_t i = 0; i < pts.size(); ++i) {
      const double approach = (dz - pts[i].vertical_gap) * pts[i].cos_delta;
      if (approach <= 0.0) continue;
      const double normal_force = stiffness[i] * approach * std::sqrt(approach);
      total += normal_force * pts[i].cos_delta;
      if (forces) (*forces)[i] = normal_force;
    }
    return total;
  };
  // below every point's vertical gap nothing touches: the push-down lies above (negative: a lift)
  double lo = 0.0;
  for (const Point& p : pts) lo = std::min(lo, p.vertical_gap);
  double step = 1e-4, hi = lo + step;
  while (vertical_force(hi, nullptr) < vertical_load_N && step < 0.05) step *= 2.0, hi = lo + step;
  for (int it = 0; it < 100 && (hi - lo) > o.load_tolerance * std::max(std::fabs(hi), std::fabs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    if (vertical_force(mid, nullptr) < vertical_load_N) lo = mid; else hi = mid;
  }
  const double dz = vertical_load_N > 0.0 ? 0.5 * (lo + hi) : std::min(0.0, lo);
  std::vector<double> forces;
  vertical_force(dz, &forces);
  require_positive(o.penetration_factor, "CandidateOptions.penetration_factor");
  pose.vertical_m -= o.penetration_factor * dz;
  CandidateResult out = FindContactCandidates(g, side, pose, o);
  // attach the Hertz estimate of each rigid point to the region containing it
  for (size_t i = 0; i < rigid.points.size(); ++i)
    for (auto& c : out.candidates)
      if (rigid.points[i].rail_s_m >= c.region_start_s_m - 1e-6 && rigid.points[i].rail_s_m <= c.region_end_s_m + 1e-6)
        c.normal_force_estimate_N += forces[i];
  out.has_touching = true;
  out.touching_pose = touching;
  out.touching_contact = std::move(rigid);
  return out;
}

}  // namespace conforma
