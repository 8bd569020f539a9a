#include "conforma/profile_update.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(ProfileUpdateStatus status) {
  switch (status) {
    case ProfileUpdateStatus::Updated: return "updated";
    case ProfileUpdateStatus::NoWear: return "no wear";
    case ProfileUpdateStatus::InvalidProfile: return "invalid profile";
  }
  return "?";
}

namespace {

// A profile through points in the arc-length order of the profile they came from (not sorted by y).
Profile RefitInArcLengthOrder(std::vector<Eigen::Vector2d> points, ProfileKind kind, double spacing_m,
                              double smoothing_rms_m, const std::string& context) {
  ProfileFitOptions fit;
  fit.smoothing_rms_m = smoothing_rms_m;
  fit.sample_spacing_m = spacing_m;
  fit.function_of_y = false;
  return Profile::FromPoints(std::move(points), kind, fit, context);
}

}  // namespace

// paper 003 eqs. 18-19, paper 001 eq. 30: P_new(s) = P(s) - d(s) n(s), then arc-length re-parametrisation
Profile RemoveAlongNormal(const Profile& profile, const WearDistribution& depth, double output_spacing_m,
                          const std::string& context) {
  if (profile.empty()) throw InputError(context + ": the profile is empty");
  require_non_negative(output_spacing_m, "output_spacing_m");
  if (depth.size() < 2 || std::abs(depth.length_m() - profile.length()) > 1e-9 + 1e-9 * profile.length()) {
    std::ostringstream m;
    m << context << ": depth grid length " << depth.length_m() * 1e3 << " mm does not match the profile arc length "
      << profile.length() * 1e3 << " mm";
    throw InputError(m.str());
  }
  std::vector<Eigen::Vector2d> points(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) {
    const double s = depth.s(i), d = depth.depth_m[i];
    if (!std::isfinite(d)) throw InputError(context + ": depth at node " + std::to_string(i) + " is not finite");
    points[i] = profile.position(s) - d * profile.normal(s);
  }
  return RefitInArcLengthOrder(std::move(points), profile.kind(),
                               output_spacing_m > 0.0 ? output_spacing_m : profile.spacing(), 0.0, context);
}

// Radius of the rounding of the corners an overhang cut leaves [m]: the profile validity allows |curvature| up to
// 1/(1 mm) (ProfileValidityOptions::max_curvature_1_m); 1.25 mm keeps the refitted spline clear of it.
constexpr double kOverhangCutRoundingRadius = 1.25e-3;

double CutOverhangs(std::vector<Eigen::Vector2d>* points) {
  std::vector<Eigen::Vector2d>& p = *points;
  double area = 0.0, running_min = std::numeric_limits<double>::infinity();
  for (size_t k = p.size(); k-- > 0;) {
    if (p[k].x() > running_min) {
      // horizontal strip between the old and the new point, over the segment's height (trapezoid in z)
      const double dz = k + 1 < p.size() ? std::abs(p[k + 1].y() - p[k].y()) : 0.0;
      area += (p[k].x() - running_min) * dz;
      p[k].x() = running_min;
    }
    running_min = std::min(running_min, p[k].x());
  }
  return area;
}

namespace {

// Rounds the convex corners an overhang cut leaves at the top of each cut face, removing material only.
// `uncut` and `cut` are the same samples before and after CutOverhangs. Around each run of moved samples, from up to
// 2 R above it (while |dy/dz| <= 1) down to its foot, where z strictly decreases along s (the curve is a graph
// y = f(z) there, material towards -y), the body {y <= f(z)} is replaced by its morphological opening with a disc of
// radius R (the union of the discs of radius R inside it; J. Serra, Image Analysis and Mathematical Morphology, 1982). For a hypograph that is the grey-scale opening with the half-disc
// b(u) = sqrt(R^2 - u^2) - R, |u| <= R (a disc lies under f iff its upper half does):
//   e(z) = min_|u|<=R [f(z + u) - b(u)],   o(z) = max_|u|<=R [e(z - u) + b(u)]   (over the samples z_j),
// o <= f at every sample (the rounding only removes material); o = f wherever a disc of radius R touches from inside
// (the rest of the face, any rounding of radius >= R, whatever its slope), and a convex corner becomes an arc of
// radius R. A window cut short (by the reach or where z stops decreasing) only drops constraints: o stays <= f and
// touches f at least where the full opening does. Only the rounding connected to the run is kept.
void RoundCutCorners(const std::vector<Eigen::Vector2d>& uncut, std::vector<Eigen::Vector2d>* cut, double radius) {
  std::vector<Eigen::Vector2d>& p = *cut;
  const size_t n = p.size();
  const double reach = 2.0 * radius;
  auto cap = [radius](double u) { return std::sqrt(std::max(0.0, radius * radius - u * u)) - radius; };  // b(u)
  for (size_t a = 0; a < n;) {
    if (p[a].x() == uncut[a].x()) {
      ++a;
      continue;
    }
    size_t b = a;  // run of moved samples [a, b]
    while (b + 1 < n && p[b + 1].x() != uncut[b + 1].x()) ++b;
    // window: the face above the run (z strictly decreasing along s, |dy/dz| <= 1, within `reach`) down to the
    // sample after the run (the foot of the cut face, y equal to the face's). A window ending lower would end on a
    // boundary maximum of f, which an opening cuts; where the graph is steeper, a disc touches f near the end of its
    // half-disc, whose slope is unbounded there, and the discrete dilation below would lose accuracy.
    size_t lo = a, hi = std::min(b + 1, n - 1);
    while (lo > 0 && p[lo - 1].y() > p[lo].y() && p[lo].x() - p[lo - 1].x() <= p[lo - 1].y() - p[lo].y() &&
           p[lo - 1].y() - p[a].y() <= reach)
      --lo;
    bool graph = true;  // the run itself must be a graph over z (a cut face descending along s)
    for (size_t i = lo; i < hi && graph; ++i) graph = p[i + 1].y() < p[i].y();
    if (graph && hi > lo) {
      // the graph densified (kDense points per segment, linear): a disc touching f between two samples of a steep
      // stretch is then seen, so the opening of a stretch whose radius is >= R leaves it (to a few nm)
      constexpr int kDense = 8;
      const size_t m = (hi - lo) * kDense + 1;
      std::vector<double> z(m), f(m), e(m);
      for (size_t k = 0; k < m; ++k) {
        const size_t i = lo + k / kDense;
        const double t = static_cast<double>(k % kDense) / kDense;
        const Eigen::Vector2d q = t == 0.0 ? p[i] : (1.0 - t) * p[i] + t * p[i + 1];
        z[k] = q.y();
        f[k] = q.x();
      }
      // z decreases with k: the points within R of z[k] are a contiguous range [first, last]
      size_t first = 0, last = 0;
      for (size_t k = 0; k < m; ++k) {
        while (z[first] - z[k] > radius) ++first;
        while (last + 1 < m && z[k] - z[last + 1] <= radius) ++last;
        double v = std::numeric_limits<double>::infinity();
        for (size_t j = first; j <= last; ++j) v = std::min(v, f[j] - cap(z[j] - z[k]));
        e[k] = v;
      }
      std::vector<double> o(hi - lo + 1);
      first = last = 0;
      for (size_t i = lo; i <= hi; ++i) {
        const size_t k = (i - lo) * kDense;
        while (z[first] - z[k] > radius) ++first;
        while (last + 1 < m && z[k] - z[last + 1] <= radius) ++last;
        double v = -std::numeric_limits<double>::infinity();
        for (size_t j = first; j <= last; ++j) v = std::max(v, e[j] + cap(z[k] - z[j]));
        o[i - lo] = std::min(v, p[i].x());  // <= f already up to rounding; keep it exact
      }
      // keep the rounding of this corner only: from the run up to the first sample above it that the opening leaves
      // (to 1 nm)
      size_t top = a;
      while (top > lo && o[top - 1 - lo] < p[top - 1].x() - 1e-9) --top;
      for (size_t i = top; i <= hi; ++i) p[i].x() = o[i - lo];
    }
    a = b + 1;
  }
}

// Area enclosed between two polylines with the same end points, `outer` followed by `inner` reversed (shoelace),
// positive when `inner` lies towards the material of `outer` (to the right of its direction) [m^2].
double area_between(const std::vector<Eigen::Vector2d>& outer, const std::vector<Eigen::Vector2d>& inner) {
  std::vector<Eigen::Vector2d> loop = outer;
  loop.insert(loop.end(), inner.rbegin(), inner.rend());
  double twice = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d& q = loop[(i + 1) % loop.size()];
    twice += loop[i].x() * q.y() - q.x() * loop[i].y();
  }
  return -0.5 * twice;  // clockwise loop (material to the right of `outer`) has a negative signed area
}

// Reversals of the lateral coordinate y along the polyline (a profile single-valued in y has none), with
// hysteresis: a reversal counts only once y has moved back by more than `tolerance` from its running extreme in the
// current direction. Sub-tolerance wiggles of a vertical face (a measured profile's noise, say) are not folds; a face
// leaning back by more than the tolerance is, however gently it leans.
int count_y_folds(const std::vector<Eigen::Vector2d>& p, double tolerance) {
  if (p.empty()) return 0;
  int folds = 0, direction = 0;  // +1: y increasing, -1: decreasing, 0: not yet moved beyond the tolerance
  double low = p[0].x(), high = p[0].x();  // running extremes since the last reversal
  for (size_t i = 1; i < p.size(); ++i) {
    const double y = p[i].x();
    low = std::min(low, y);
    high = std::max(high, y);
    if (direction >= 0 && y < high - tolerance) {  // moved back from the maximum
      if (direction > 0) ++folds;
      direction = -1;
      low = high = y;
    } else if (direction <= 0 && y > low + tolerance) {  // moved back from the minimum
      if (direction < 0) ++folds;
      direction = 1;
      low = high = y;
    }
  }
  return folds;
}

}  // namespace

ProfileValidity CheckProfileValidity(const Profile& updated, const Profile& previous, const ProfileValidityOptions& o) {
  require_positive(o.max_curvature_1_m, "max_curvature_1_m");
  require_positive(o.fold_tolerance_m, "fold_tolerance_m");
  ProfileValidity v;
  const auto pts = updated.samples();
  for (const auto& p : pts)
    if (!p.allFinite()) {
      v.valid = false;
      v.reason = "the profile has non-finite points";
      return v;
    }
  if (auto hit = find_self_intersection(pts)) {
    std::ostringstream m;
    m << "the profile self-intersects near y = " << pts[hit->first].x() * 1e3 << " mm and y = "
      << pts[hit->second].x() * 1e3 << " mm";
    v.valid = false;
    v.reason = m.str();
    return v;
  }
  v.y_folds_before = count_y_folds(previous.samples(), o.fold_tolerance_m);
  v.y_folds_after = count_y_folds(pts, o.fold_tolerance_m);
  if (v.y_folds_after > v.y_folds_before) {
    v.valid = false;
    v.reason = "the profile is no longer single-valued in y: " + std::to_string(v.y_folds_after) +
               " folds, the previous profile had " + std::to_string(v.y_folds_before);
    return v;
  }
  // curvature: sampled at the new profile's nodes; old curvature near the corresponding arc length
  const double h = updated.spacing(), ratio = previous.length() / updated.length(), window = 2e-3;
  const double hp = previous.spacing();
  for (size_t i = 0; i < pts.size(); ++i) {
    const double s = h * i;
    const double kappa = std::abs(updated.curvature(s));
    v.max_abs_curvature_1_m = std::max(v.max_abs_curvature_1_m, kappa);
    if (kappa <= o.max_curvature_1_m) continue;
    double old_max = 0.0;
    for (double so = s * ratio - window; so <= s * ratio + window; so += hp)
      old_max = std::max(old_max, std::abs(previous.curvature(so)));
    if (kappa > o.max_curvature_1_m && (old_max <= o.max_curvature_1_m || kappa > 1.2 * old_max)) {
      std::ostringstream m;
      m << "kink: |curvature| = " << kappa << " 1/m (radius " << 1e3 / kappa << " mm) at s = " << s * 1e3
        << " mm, y = " << pts[i].x() * 1e3 << " mm exceeds the limit " << o.max_curvature_1_m
        << " 1/m (previous profile there: " << old_max << " 1/m)";
      v.valid = false;
      v.reason = m.str();
    }
  }
  return v;
}

namespace {

// Removal along the normal, validity, and (ProfileUpdateOptions::cut_overhangs) the overhang cut of a profile that
// folds after the removal. cut_s_min_m / cut_s_max_m: the old profile's arc length of the first and last sample
// the cut moved (mapped by the ratio of the arc lengths).
struct CutOutcome {
  Profile profile;
  ProfileValidity validity;
  double cut_area_m2 = 0.0, cut_s_min_m = 0.0, cut_s_max_m = 0.0;
};
CutOutcome RemoveAndCut(const Profile& profile, const WearDistribution& depth, const ProfileUpdateOptions& o,
                        const std::string& step) {
  CutOutcome out;
  out.profile = RemoveAlongNormal(profile, depth, o.output_spacing_m, step);
  out.validity = CheckProfileValidity(out.profile, profile, o.validity);
  if (!out.validity.valid && o.cut_overhangs && out.validity.y_folds_before == 0 &&
      out.validity.y_folds_after > out.validity.y_folds_before) {
    // Cut, round the cut's corners (material removed only), refit (interpolating) at the old spacing, and cut the
    // refitted samples again: the spline between the nodes of the refit is not monotone where the curvature jumps,
    // so its samples may step back in y by a little (nm); the second cut moves them by that little only, far below
    // the spacing, and the samples are kept as the new profile's nodes as they are, single-valued in y by
    // construction (the Aosta run stopped on 1.2-1.3 um steps back the earlier smoothing-spline rounding left).
    const std::vector<Eigen::Vector2d> uncut = out.profile.samples();
    std::vector<Eigen::Vector2d> points = uncut;
    CutOverhangs(&points);
    RoundCutCorners(uncut, &points, kOverhangCutRoundingRadius);
    const double h = out.profile.spacing(), ratio = profile.length() / out.profile.length();
    bool any = false;
    for (size_t i = 0; i < points.size(); ++i) {
      if (points[i] == uncut[i]) continue;
      const double s_old = h * static_cast<double>(i) * ratio;
      if (!any) out.cut_s_min_m = s_old;
      out.cut_s_max_m = s_old, any = true;
    }
    try {
      std::vector<Eigen::Vector2d> refit =
          RefitInArcLengthOrder(std::move(points), profile.kind(), out.profile.spacing(), 0.0, step).samples();
      CutOverhangs(&refit);
      out.profile = Profile::FromArcLengthSamples(refit, profile.kind(), step);
      out.cut_area_m2 = area_between(uncut, out.profile.samples());
      out.validity = CheckProfileValidity(out.profile, profile, o.validity);
    } catch (const InputError& e) {
      out.validity.valid = false;
      out.validity.reason = std::string("after cutting the overhang: ") + e.what();
    }
  }
  return out;
}

// ProfileUpdateOptions::cut_conserves_area (docs/physics-reference.md §8.7): the lip the cut removes is flange-face
// wear the contact would have done there instead of on the band below it, so the face keeps the step's wear area.
// The depth r->removed_depth is scaled by 1 - (1 - k) w(s), k in [0, 1], with a window w = 1 over the cut (along the
// old profile) tapering to 0 as a half cosine over `reach` on either side (two smoothing lengths, at least 5 mm; a
// step in the scaled depth would leave a step in the profile), so that the area the removal and the cut take together
// equals the removal's area at k = 1: k = 0 removes nothing over the cut and cuts nothing (the old profile was
// single-valued), k = 1 exceeds it by the cut; bisection on the area (its own loop: a trial whose removal fails or
// whose profile is invalid only moves the bracket, and the best valid trial is kept). When the window does not hold
// the band that makes the overhang (no k balances the areas), the taper is doubled. Balanced: *outcome, the removed
// depth, its maximum and area and cut_area_scale are replaced; otherwise left as they are (the lip cut on top of the
// wear) and r->cut_area_conserved = false.
void ConserveAreaAroundCut(const Profile& profile, const ProfileUpdateOptions& o, const std::string& step,
                           CutOutcome* outcome, ProfileUpdateResult* r) {
  const double target = r->removed_area_m2, tolerance = 1e-3 * target;
  double reach = std::max(2.0 * o.smoothing.cutoff_wavelength_m, 5e-3);
  for (int widen = 0; widen < 4; ++widen, reach *= 2.0) {
    std::vector<double> window(r->removed_depth.size());
    for (size_t i = 0; i < window.size(); ++i) {
      const double s = r->removed_depth.s(i);
      const double outside = std::max(outcome->cut_s_min_m - s, s - outcome->cut_s_max_m);
      window[i] = outside <= 0.0 ? 1.0 : outside >= reach ? 0.0 : 0.5 + 0.5 * std::cos(M_PI * outside / reach);
    }
    double lo = 0.0, hi = 1.0, best_miss = std::numeric_limits<double>::infinity(), best_k = 1.0;
    CutOutcome best;
    WearDistribution best_depth;
    for (int it = 0; it < 40 && hi - lo > 1e-7; ++it) {
      const double k = 0.5 * (lo + hi);
      WearDistribution d = r->removed_depth;
      for (size_t i = 0; i < d.size(); ++i) d.depth_m[i] *= 1.0 - (1.0 - k) * window[i];
      CutOutcome c;
      try {
        c = RemoveAndCut(profile, d, o, step);
      } catch (const InputError&) {
        hi = k;
        continue;
      }
      const double total = d.area_m2() + c.cut_area_m2;
      (total > target ? hi : lo) = k;
      if (c.validity.valid && std::fabs(total - target) < best_miss)
        best_miss = std::fabs(total - target), best_k = k, best = std::move(c), best_depth = std::move(d);
    }
    if (!(best_miss <= tolerance)) continue;
    *outcome = std::move(best);
    r->removed_depth = std::move(best_depth);
    r->cut_area_scale = best_k;
    r->max_depth_m = r->removed_depth.max_depth_m();
    r->removed_area_m2 = r->removed_depth.area_m2();
    return;
  }
  r->cut_area_conserved = false;  // the lip is cut on top of the wear (as wear_off), reported
}

}  // namespace

ProfileUpdateResult UpdateProfile(const Profile& profile, const WearDistribution& accumulated,
                                  double distance_represented_m, const ProfileUpdateOptions& o) {
  require_positive(distance_represented_m, "distance_represented_m");
  require_positive(o.max_depth_per_step_m, "max_depth_per_step_m");
  if (!(o.max_distance_step_m > 0.0)) throw InputError("max_distance_step_m must be > 0");
  const std::string step = "wear step " + std::to_string(o.step_index) + " (" + to_string(profile.kind()) + ")";
  if (profile.empty()) throw InputError(step + ": the profile is empty");
  if (accumulated.size() < 2 || std::abs(accumulated.length_m() - profile.length()) > 1e-9 + 1e-9 * profile.length()) {
    std::ostringstream m;
    m << step << ": depth grid length " << accumulated.length_m() * 1e3
      << " mm does not match the profile arc length " << profile.length() * 1e3 << " mm";
    throw InputError(m.str());
  }
  ProfileUpdateResult r;
  r.profile = profile;
  // 1. mass-conserving smoothing (before scaling; S is positively homogeneous)
  r.smoothing = SmoothDepthMassConserving(accumulated, o.smoothing);
  const double smoothed_max = r.smoothing.depth.max_depth_m();
  if (!(smoothed_max > 0.0)) {
    r.status = ProfileUpdateStatus::NoWear;
    r.message = step + ": no wear to remove";
    r.removed_depth = r.smoothing.depth;
    return r;
  }
  // 2. scaling: the largest depth of the step equals the cap (paper 003 §6), km_step = km_sim * factor
  r.scale_factor = std::min(o.max_depth_per_step_m / smoothed_max, o.max_distance_step_m / distance_represented_m);
  r.distance_step_m = distance_represented_m * r.scale_factor;
  r.removed_depth = r.smoothing.depth;
  for (double& v : r.removed_depth.depth_m) v *= r.scale_factor;
  r.max_depth_m = r.removed_depth.max_depth_m();
  r.removed_area_m2 = r.removed_depth.area_m2();
  // 3. removal along the normal and re-parametrisation, 4. validity (with the overhang cut)
  CutOutcome outcome;
  try {
    outcome = RemoveAndCut(profile, r.removed_depth, o, step);
  } catch (const InputError& e) {
    r.status = ProfileUpdateStatus::InvalidProfile;
    r.message = e.what();
    return r;
  }
  if (o.cut_conserves_area && outcome.cut_area_m2 > 0.0 && outcome.validity.valid)  // (a cut: cut_overhangs)
    ConserveAreaAroundCut(profile, o, step, &outcome, &r);
  r.validity = outcome.validity;
  r.overhang_cut_area_m2 = outcome.cut_area_m2;
  if (!r.validity.valid) {
    r.status = ProfileUpdateStatus::InvalidProfile;
    r.message = step + ": updated profile is invalid: " + r.validity.reason;
    return r;
  }
  r.status = ProfileUpdateStatus::Updated;
  r.profile = std::move(outcome.profile);
  return r;
}

}  // namespace conforma
