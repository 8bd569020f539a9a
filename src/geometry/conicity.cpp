// Equivalent conicity of EN 15302 from a tabulated Delta r(y) (conicity.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "conforma/conicity.hpp"
#include "conforma/error.hpp"

namespace conforma {

const char* to_string(ConicityMethod method) {
  return method == ConicityMethod::KinematicIntegral ? "kinematic integral" : "harmonic linearisation";
}
const char* to_string(ConicityStatus status) {
  switch (status) {
    case ConicityStatus::Ok: return "ok";
    case ConicityStatus::AmplitudeOutOfRange: return "amplitude out of the Delta r range";
    default: return "no centre (Delta r has no sign change from - to +)";
  }
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// Delta r linear between the nodes, S = integral of Delta r (piecewise quadratic, S(y_0) = 0).
struct DeltaRFunction {
  const std::vector<double>& y;
  const std::vector<double>& dr;
  std::vector<double> S;
  DeltaRFunction(const std::vector<double>& yy, const std::vector<double>& d) : y(yy), dr(d), S(yy.size(), 0.0) {
    for (size_t i = 1; i < y.size(); ++i) S[i] = S[i - 1] + 0.5 * (dr[i] + dr[i - 1]) * (y[i] - y[i - 1]);
  }
  size_t interval(double x) const {
    const size_t k = std::upper_bound(y.begin(), y.end(), x) - y.begin();
    return std::clamp<size_t>(k, 1, y.size() - 1) - 1;
  }
  double delta_r(double x) const {
    const size_t i = interval(x);
    const double t = (x - y[i]) / (y[i + 1] - y[i]);
    return (1 - t) * dr[i] + t * dr[i + 1];
  }
  double integral(double x) const {
    const size_t i = interval(x);
    const double u = x - y[i], h = y[i + 1] - y[i];
    return S[i] + dr[i] * u + 0.5 * (dr[i + 1] - dr[i]) / h * u * u;
  }
  // Position where S - s_min first reaches level c walking from `from` in direction dir (-1 or +1);
  // false when the table ends first.
  bool reach(double from, int dir, double level, double* out) const {
    const size_t n = y.size();
    size_t i = interval(from);
    double a = from;
    while (true) {
      const double b = dir > 0 ? y[i + 1] : y[i];
      if (integral(b) >= level) {  // root in [a, b]: bisection on the monotone-enough quadratic piece
        double lo = a, hi = b;
        for (int it = 0; it < 80; ++it) {
          const double mid = 0.5 * (lo + hi);
          if (integral(mid) >= level) hi = mid; else lo = mid;
        }
        *out = 0.5 * (lo + hi);
        return true;
      }
      if (dir > 0) {
        if (i + 2 >= n) return false;
        ++i;
      } else {
        if (i == 0) return false;
        --i;
      }
      a = b;
    }
  }
};

}  // namespace

ConicityResult EquivalentConicity(const std::vector<double>& lateral_m, const std::vector<double>& delta_r_m,
                                  double amplitude_m, const ConicityOptions& options) {
  if (lateral_m.size() != delta_r_m.size())
    throw InputError("EquivalentConicity: lateral_m and delta_r_m differ in length");
  if (lateral_m.size() < 3) throw InputError("EquivalentConicity: at least 3 points of Delta r are needed");
  for (size_t i = 0; i < lateral_m.size(); ++i) {
    require_finite(lateral_m[i], "EquivalentConicity lateral_m");
    require_finite(delta_r_m[i], "EquivalentConicity delta_r_m");
    if (i && !(lateral_m[i] > lateral_m[i - 1]))
      throw InputError("EquivalentConicity: lateral_m must be strictly ascending (point " + std::to_string(i + 1) + ")");
  }
  require_positive(amplitude_m, "amplitude_m");
  if (options.quadrature_points < 10) throw InputError("ConicityOptions.quadrature_points must be >= 10");
  ConicityResult res;
  res.amplitude_m = amplitude_m;
  const DeltaRFunction f(lateral_m, delta_r_m);
  // Centre: the lowest minimum of S, i.e. a sign change of Delta r from - to + (zero plateaus included).
  double s_min = std::numeric_limits<double>::infinity(), y_min = 0.0;
  bool found = false;
  for (size_t i = 0; i + 1 < lateral_m.size(); ++i) {
    const double a = delta_r_m[i], b = delta_r_m[i + 1];
    if (a <= 0.0 && b >= 0.0 && !(a == 0.0 && b == 0.0 && i > 0 && delta_r_m[i - 1] == 0.0)) {
      const double yc = (a == b) ? lateral_m[i] : lateral_m[i] - a * (lateral_m[i + 1] - lateral_m[i]) / (b - a);
      const double s = f.integral(yc);
      if (s < s_min - 1e-18 || (!found)) {
        s_min = s;
        y_min = yc;
        found = true;
      }
    }
  }
  if (!found) return res;
  // plateau of S around the centre (Delta r exactly zero over a range)
  double p_lo = y_min, p_hi = y_min;
  {
    size_t i = f.interval(y_min);
    while (i + 1 < lateral_m.size() && delta_r_m[i + 1] == 0.0 && delta_r_m[i] == 0.0) p_hi = lateral_m[++i];
    size_t j = f.interval(y_min);
    if (delta_r_m[j] == 0.0) p_lo = std::min(p_lo, lateral_m[j]);
    while (j > 0 && delta_r_m[j - 1] == 0.0 && delta_r_m[j] == 0.0) p_lo = lateral_m[--j];
  }
  res.centre_m = 0.5 * (p_lo + p_hi);
  res.status = ConicityStatus::AmplitudeOutOfRange;

  if (options.method == ConicityMethod::HarmonicLinearisation) {
    const double yc = res.centre_m;
    if (yc - amplitude_m < lateral_m.front() || yc + amplitude_m > lateral_m.back()) return res;
    const int n = 4 * options.quadrature_points;
    double acc = 0.0;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * kPi * (k + 0.5) / n;
      acc += f.delta_r(yc + amplitude_m * std::sin(t)) * std::sin(t);
    }
    res.equivalent_conicity = acc * (2 * kPi / n) / (2 * kPi * amplitude_m);
    res.turning_left_m = yc - amplitude_m;
    res.turning_right_m = yc + amplitude_m;
    res.status = ConicityStatus::Ok;
    return res;
  }

  // Kinematic integral. Amplitude as a function of the energy level C (above s_min): bisection.
  auto turning = [&](double c, double* y1, double* y2) {
    return f.reach(p_lo, -1, s_min + c, y1) && f.reach(p_hi, +1, s_min + c, y2);
  };
  if (0.5 * (p_hi - p_lo) >= amplitude_m) {  // oscillation inside a zero plateau: no restoring force
    res.equivalent_conicity = 0.0;
    res.turning_left_m = res.centre_m - amplitude_m;
    res.turning_right_m = res.centre_m + amplitude_m;
    res.status = ConicityStatus::Ok;
    return res;
  }
  double c_hi = std::min(f.S.front(), f.S.back()) - s_min;
  double y1, y2;
  if (!(c_hi > 0) || !turning(c_hi, &y1, &y2) || 0.5 * (y2 - y1) < amplitude_m) {
    // the table end may be reached on one side before the other: use the largest level that still works
    double lo = 0.0, hi = std::max(f.S.front(), f.S.back()) - s_min;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (turning(mid, &y1, &y2)) lo = mid; else hi = mid;
    }
    c_hi = lo;
    if (!(c_hi > 0) || !turning(c_hi, &y1, &y2) || 0.5 * (y2 - y1) < amplitude_m) return res;
  }
  double c_lo = 0.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (c_lo + c_hi);
    if (turning(mid, &y1, &y2) && 0.5 * (y2 - y1) >= amplitude_m) c_hi = mid; else c_lo = mid;
  }
  const double c = c_hi;
  turning(c, &y1, &y2);
  const double level = s_min + c;
  // L = integral_{y1}^{y2} dy / sqrt(C - S): y = y1 + D t^2 on the left half, y = y2 - D t^2 on the right
  // half (removes the inverse square-root singularity at the turning points); midpoint rule in t.
  const double y_split = res.centre_m;
  const int n = options.quadrature_points;
  double L = 0.0;
  for (int side = 0; side < 2; ++side) {
    const double D = side == 0 ? (y_split - y1) : (y2 - y_split);
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) / n;
      const double yy = side == 0 ? y1 + D * t * t : y2 - D * t * t;
      const double gap = level - f.integral(yy);
      if (gap > 0) L += 2 * D * t / std::sqrt(gap) / n;
    }
  }
  res.turning_left_m = y1;
  res.turning_right_m = y2;
  res.equivalent_conicity = L > 0 ? (kPi / L) * (kPi / L) : 0.0;
  res.status = ConicityStatus::Ok;
  return res;
}

}  // namespace conforma
