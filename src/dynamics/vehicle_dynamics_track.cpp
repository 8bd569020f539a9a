// Track input of the time-domain vehicle model (vehicle_dynamics_track.hpp).
#include "conforma/vehicle_dynamics_track.hpp"

#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

double TrackInput::alignment_derivative(double s) const {
  if (alignment_slope) return alignment_slope(s);
  if (!alignment_m) return 0.0;
  const double h = 1e-3;
  return (alignment_m(s + h) - alignment_m(s - h)) / (2.0 * h);
}

double TrackInput::curvature_derivative(double s) const {
  if (!curvature_per_m) return 0.0;
  const double h = 1e-3;
  return (curvature_per_m(s + h) - curvature_per_m(s - h)) / (2.0 * h);
}

void CurveTrackSpec::validate() const {
  require_non_negative(tangent_length_m, "tangent_length_m");
  require_non_negative(transition_length_m, "transition_length_m");
  require_finite(radius_m, "radius_m");
  require_non_negative(curve_length_m, "curve_length_m");
  require_non_negative(cant_m, "cant_m");
  if (radius_m != 0.0 && std::fabs(radius_m) < 10.0)
    throw InputError("curve track field 'radius_m' must be 0 (tangent) or |R| >= 10 m");
}

namespace {

// 0 before the entry transition, rising linearly to 1 over it, 1 on the arc, falling linearly to 0 over the exit.
double CurveShape(const CurveTrackSpec& k, double s) {
  const double s1 = k.tangent_length_m, s2 = s1 + k.transition_length_m, s3 = s2 + k.curve_length_m,
               s4 = s3 + k.transition_length_m;
  if (s < s1 || s >= s4) return 0.0;
  if (s < s2) return (s - s1) / k.transition_length_m;
  if (s < s3) return 1.0;
  return (s4 - s) / k.transition_length_m;
}

}  // namespace

TrackInput MakeCurveTrack(const CurveTrackSpec& spec) {
  spec.validate();
  TrackInput t;
  if (spec.radius_m == 0.0) return t;
  const CurveTrackSpec k = spec;
  const double c = 1.0 / k.radius_m;
  const double cant = k.radius_m > 0.0 ? k.cant_m : -k.cant_m;  // + raises the right rail = outer of a left curve
  t.curvature_per_m = [k, c](double s) { return c * CurveShape(k, s); };
  const double s1 = k.tangent_length_m, s2 = s1 + k.transition_length_m, s3 = s2 + k.curve_length_m,
               s4 = s3 + k.transition_length_m;
  t.curvature_breaks_m = {s1, s2, s3, s4};
  if (cant != 0.0) t.cant_m = [k, cant](double s) { return cant * CurveShape(k, s); };
  return t;
}

void SetTrackIrregularity(TrackInput& track, const TrackIrregularity& irregularity, double cant_base_m) {
  require_positive(cant_base_m, "cant_base_m");
  const auto irr = std::make_shared<const TrackIrregularity>(irregularity);
  track.alignment_m = [irr](double s) { return irr->At(s).alignment_m; };
  track.alignment_slope = [irr](double s) { return irr->At(s).alignment_slope; };
  track.cross_level_m = [irr, cant_base_m](double s) { return -irr->At(s).cross_level_rad * cant_base_m; };
}

TrackRelativePosition RelativeTrackPosition(const TrackInput& track, double s_from, double s_to) {
  TrackRelativePosition r;
  if (!track.curvature_per_m || s_to == s_from) return r;
  // 4-point Gauss-Legendre on [-1, 1]
  static const double kNode[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double kWeight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  // sub-intervals between the break points inside (s_from, s_to), in the direction of integration
  std::vector<double> ends{s_from};
  const double lo = std::min(s_from, s_to), hi = std::max(s_from, s_to);
  std::vector<double> inside;
  for (double b : track.curvature_breaks_m)
    if (b > lo && b < hi) inside.push_back(b);
  if (s_to < s_from) std::reverse(inside.begin(), inside.end());
  ends.insert(ends.end(), inside.begin(), inside.end());
  ends.push_back(s_to);
  for (size_t e = 0; e + 1 < ends.size(); ++e) {
    const double d = ends[e + 1] - ends[e];
    const int panels = std::max(1, static_cast<int>(std::ceil(std::fabs(d) / 1.0)));
    const double h = d / panels;
    for (int p = 0; p < panels; ++p) {
      const double mid = ends[e] + (p + 0.5) * h;
      for (int i = 0; i < 4; ++i) {
        const double u = mid + 0.5 * h * kNode[i];
        const double cu = track.curvature_per_m(u);
        r.heading_change_rad += 0.5 * h * kWeight[i] * cu;
        r.lateral_offset_m += 0.5 * h * kWeight[i] * (s_to - u) * cu;
      }
    }
  }
  return r;
}

}  // namespace conforma
