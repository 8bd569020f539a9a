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

void SampledTrackFunction::validate() const {
  require_finite(s_begin_m, "irregularity s_begin_m");
  require_positive(spacing_m, "irregularity spacing_m");
  if (values.size() < 2) throw InputError("irregularity samples: at least 2 values are needed");
  for (double v : values) require_finite(v, "irregularity sample");
}

namespace {

// Catmull-Rom on uniform samples: value (derivative = false) or d/ds at s; 0 outside [first, last sample].
double CatmullRom(const SampledTrackFunction& f, double s, bool derivative) {
  const double u = (s - f.s_begin_m) / f.spacing_m;
  const int n = static_cast<int>(f.values.size());
  if (!(u >= 0.0) || u > n - 1) return 0.0;
  const int i = std::min(static_cast<int>(std::floor(u)), n - 2);
  const double t = u - i;
  auto at = [&](int k) { return f.values[std::clamp(k, 0, n - 1)]; };
  const double p0 = at(i), p1 = at(i + 1);
  const double m0 = 0.5 * (at(i + 1) - at(i - 1)), m1 = 0.5 * (at(i + 2) - at(i));  // per sample
  const double t2 = t * t, t3 = t2 * t;
  if (!derivative)
    return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1;
  return ((6 * t2 - 6 * t) * p0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * p1 + (3 * t2 - 2 * t) * m1) /
         f.spacing_m;
}

}  // namespace

double SampledTrackFunction::value(double s) const { return CatmullRom(*this, s, false); }
double SampledTrackFunction::slope(double s) const { return CatmullRom(*this, s, true); }

void SetSampledIrregularities(TrackInput& track, const SampledTrackFunction& alignment,
                              const SampledTrackFunction* cross_level) {
  alignment.validate();
  track.alignment_m = [alignment](double s) { return alignment.value(s); };
  track.alignment_slope = [alignment](double s) { return alignment.slope(s); };
  if (cross_level) {
    cross_level->validate();
    const SampledTrackFunction c = *cross_level;
    track.cross_level_m = [c](double s) { return c.value(s); };
  }
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
