#include "conforma/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "conforma/error.hpp"
#include "profile_smoothing.hpp"

namespace conforma {

const char* to_string(ProfileKind kind) { return kind == ProfileKind::Wheel ? "wheel" : "rail"; }

namespace {

// Second derivatives of the natural cubic spline through (t_i, v_i) (tridiagonal Thomas algorithm).
std::vector<double> natural_spline_second_derivatives(const std::vector<double>& t, const std::vector<double>& v) {
  const size_t n = t.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  // interior equations: h0 m_{i-1} + 2(h0+h1) m_i + h1 m_{i+1} = 6((v_{i+1}-v_i)/h1 - (v_i-v_{i-1})/h0),
  // natural ends m_0 = m_{n-1} = 0. Forward elimination keeps the modified diagonal in `diag` and the modified
  // right-hand side in m.
  std::vector<double> diag(n, 1.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    const double rhs = 6.0 * ((v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0);
    const double upper_prev = i >= 2 ? h0 : 0.0;  // upper coefficient of row i-1 (row 0 is the identity)
    const double w = h0 / diag[i - 1];
    diag[i] = 2.0 * (h0 + h1) - w * upper_prev;
    m[i] = rhs - w * m[i - 1];
  }
  m[n - 1] = 0.0;
  for (size_t i = n - 2; i >= 1; --i) m[i] = (m[i] - (i + 2 < n ? t[i + 1] - t[i] : 0.0) * m[i + 1]) / diag[i];
  m[0] = 0.0;
  return m;
}

// std::upper_bound(t.begin(), t.end(), x) - t.begin() on a sorted t, walked from `hint` (the previous answer): the
// same index at O(1) cost for increasing x.
size_t upper_index(const std::vector<double>& t, double x, size_t hint) {
  size_t i = std::min(hint, t.size());
  while (i > 0 && t[i - 1] > x) --i;
  while (i < t.size() && t[i] <= x) ++i;
  return i;
}

struct Spline1 {
  const std::vector<double>& t;
  const std::vector<double>& v;
  std::vector<double> m;
  // *hint: the upper_index of the previous evaluation (updated), for x walking along t
  double operator()(double x, double* deriv = nullptr, size_t* hint = nullptr) const {
    size_t i = hint ? (*hint = upper_index(t, x, *hint)) : std::upper_bound(t.begin(), t.end(), x) - t.begin();
    i = std::clamp<size_t>(i, 1, t.size() - 1) - 1;
    const double h = t[i + 1] - t[i];
    const double a = (t[i + 1] - x) / h, b = (x - t[i]) / h;
    if (deriv)
      *deriv = (v[i + 1] - v[i]) / h + ((3 * b * b - 1) * m[i + 1] - (3 * a * a - 1) * m[i]) * h / 6.0;
    return a * v[i] + b * v[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
  }
};

bool segments_cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r,
                    const Eigen::Vector2d& u) {
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  const double d1 = cross(q - p, r - p), d2 = cross(q - p, u - p);
  const double d3 = cross(u - r, p - r), d4 = cross(u - r, q - r);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

}  // namespace

std::optional<std::pair<size_t, size_t>> find_self_intersection(const std::vector<Eigen::Vector2d>& p) {
  // Segments sorted by their smallest y; a sweep compares each segment only with those overlapping it in y.
  const size_t n = p.size() < 2 ? 0 : p.size() - 1;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  auto lo = [&](size_t i) { return std::min(p[i].x(), p[i + 1].x()); };
  auto hi = [&](size_t i) { return std::max(p[i].x(), p[i + 1].x()); };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo(a) < lo(b); });
  std::optional<std::pair<size_t, size_t>> best;
  for (size_t a = 0; a < n; ++a) {
    const size_t i = order[a];
    for (size_t b = a + 1; b < n && lo(order[b]) <= hi(i); ++b) {
      const size_t j = order[b];
      const size_t first = std::min(i, j), second = std::max(i, j);
      if (second < first + 2) continue;
      if (segments_cross(p[first], p[first + 1], p[second], p[second + 1]))
        if (!best || std::make_pair(first, second) < *best) best = std::make_pair(first, second);
    }
  }
  return best;
}

Profile Profile::FromPoints(std::vector<Eigen::Vector2d> pts, ProfileKind kind, const ProfileFitOptions& options,
                            const std::string& source) {
  require_positive(options.sample_spacing_m, "sample_spacing_m");
  require_non_negative(options.smoothing_rms_m, "smoothing_rms_m");
  // Coordinates beyond kMaxProfileCoordinate_m are a unit or data error (e.g. a stray separator inside a number) and
  // would make the resampling allocate without bound.
  for (size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].allFinite()) throw InputError(source, 0, "point " + std::to_string(i + 1) + " is not finite");
    if (pts[i].cwiseAbs().maxCoeff() > kMaxProfileCoordinate_m) {
      std::ostringstream m;
      m << "point " << i + 1 << " (" << pts[i].x() << ", " << pts[i].y()
        << ") m lies more than 10 m from the origin: wrong length unit or a malformed number";
      throw InputError(source, 0, m.str());
    }
  }
  if (options.function_of_y)
    std::stable_sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  else if (pts.size() >= 2 && pts.front().x() > pts.back().x())
    std::reverse(pts.begin(), pts.end());
  // drop duplicates (closer than 1 nm to the previous kept point)
  std::vector<Eigen::Vector2d> p;
  for (const auto& q : pts)
    if (p.empty() || (q - p.back()).norm() > 1e-9) p.push_back(q);
  if (p.size() < 4) throw InputError(source, 0, "a profile needs at least 4 distinct points, got " + std::to_string(p.size()));
  // noisy points: replace them by the parametric smoothing spline sampled at a quarter of the output spacing
  if (options.smoothing_rms_m > 0)
    p = profile_smoothing::smooth(p, options.smoothing_rms_m, 0.25 * options.sample_spacing_m, source);
  if (auto hit = find_self_intersection(p)) {
    std::ostringstream m;
    m << "profile self-intersects between points " << hit->first + 1 << " and " << hit->second + 1 << " (y = "
      << p[hit->first].x() * 1e3 << " mm and " << p[hit->second].x() * 1e3 << " mm)";
    throw InputError(source, 0, m.str());
  }
  // chord-length parameter, interpolating splines y(t), z(t)
  std::vector<double> t(p.size(), 0.0), vy(p.size()), vz(p.size());
  for (size_t i = 0; i < p.size(); ++i) {
    if (i) t[i] = t[i - 1] + (p[i] - p[i - 1]).norm();
    vy[i] = p[i].x();
    vz[i] = p[i].y();
  }
  Spline1 sy{t, vy, natural_spline_second_derivatives(t, vy)};
  Spline1 sz{t, vz, natural_spline_second_derivatives(t, vz)};
  // arc length of the spline by fine Gauss-free trapezoid on the derivative norm
  const int fine = static_cast<int>(std::ceil(t.back() / (options.sample_spacing_m * 0.1))) + 1;
  std::vector<double> tf(fine + 1), sf(fine + 1, 0.0);
  double prev = 0.0;
  size_t hint = 0;  // sy and sz share the parameter grid t
  for (int k = 0; k <= fine; ++k) {
    tf[k] = t.back() * k / fine;
    double dy, dz;
    sy(tf[k], &dy, &hint);
    sz(tf[k], &dz, &hint);
    const double speed = std::hypot(dy, dz);
    if (k) sf[k] = sf[k - 1] + 0.5 * (speed + prev) * (tf[k] - tf[k - 1]);
    prev = speed;
  }
  Profile out;
  out.kind_ = kind;
  out.source_ = source;
  out.length_ = sf.back();
  const int n = std::max(4, static_cast<int>(std::ceil(out.length_ / options.sample_spacing_m)) + 1);
  out.h_ = out.length_ / (n - 1);
  out.y_.resize(n);
  out.z_.resize(n);
  size_t sf_hint = 0;
  hint = 0;
  for (int i = 0; i < n; ++i) {
    const double s = std::min(i * out.h_, sf.back());
    size_t k = sf_hint = upper_index(sf, s, sf_hint);
    k = std::clamp<size_t>(k, 1, sf.size() - 1) - 1;
    const double w = (sf[k + 1] > sf[k]) ? (s - sf[k]) / (sf[k + 1] - sf[k]) : 0.0;
    const double tt = tf[k] + w * (tf[k + 1] - tf[k]);
    out.y_[i] = sy(tt, nullptr, &hint);
    out.z_[i] = sz(tt, nullptr, &hint);
  }
  std::vector<double> sgrid(n);
  for (int i = 0; i < n; ++i) sgrid[i] = i * out.h_;
  out.y2_ = natural_spline_second_derivatives(sgrid, out.y_);
  out.z2_ = natural_spline_second_derivatives(sgrid, out.z_);
  out.set_y_range();
  return out;
}

Profile Profile::FromArcLengthSamples(const std::vector<Eigen::Vector2d>& samples, ProfileKind kind,
                                      const std::string& source) {
  if (samples.size() < 4)
    throw InputError(source, 0, "a profile needs at least 4 samples, got " + std::to_string(samples.size()));
  double length = 0.0;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (!samples[i].allFinite()) throw InputError(source, 0, "sample " + std::to_string(i + 1) + " is not finite");
    if (i) length += (samples[i] - samples[i - 1]).norm();
  }
  if (!(length > 0.0)) throw InputError(source, 0, "the samples have zero length");
  const int n = static_cast<int>(samples.size());
  Profile out;
  out.kind_ = kind;
  out.source_ = source;
  out.length_ = length;
  out.h_ = length / (n - 1);
  out.y_.resize(n);
  out.z_.resize(n);
  std::vector<double> sgrid(n);
  for (int i = 0; i < n; ++i) {
    out.y_[i] = samples[i].x();
    out.z_[i] = samples[i].y();
    sgrid[i] = i * out.h_;
  }
  out.y2_ = natural_spline_second_derivatives(sgrid, out.y_);
  out.z2_ = natural_spline_second_derivatives(sgrid, out.z_);
  out.set_y_range();
  return out;
}

namespace {

// Second derivatives m_i, a < i < b, of the cubic spline through v on a uniform grid of spacing h, with m_a and m_b
// given: m_{i-1} + 4 m_i + m_{i+1} = 6 (v_{i+1} - 2 v_i + v_{i-1}) / h^2 (Thomas algorithm).
void resolve_second_derivatives(const std::vector<double>& v, std::vector<double>& m, size_t a, size_t b, double h) {
  if (b < a + 2) return;
  const size_t k = b - a - 1;  // unknowns a + 1 .. b - 1
  std::vector<double> diag(k), rhs(k);
  const double c = 6.0 / (h * h);
  for (size_t j = 0; j < k; ++j) {
    const size_t i = a + 1 + j;
    rhs[j] = c * (v[i + 1] - 2.0 * v[i] + v[i - 1]);
  }
  rhs.front() -= m[a];
  rhs.back() -= m[b];
  diag[0] = 4.0;
  for (size_t j = 1; j < k; ++j) {
    const double w = 1.0 / diag[j - 1];
    diag[j] = 4.0 - w;
    rhs[j] -= w * rhs[j - 1];
  }
  m[b - 1] = rhs[k - 1] / diag[k - 1];
  for (size_t j = k - 1; j-- > 0;) m[a + 1 + j] = (rhs[j] - m[a + 2 + j]) / diag[j];
}

}  // namespace

Profile Profile::WithMovedSamples(size_t first, const std::vector<Eigen::Vector2d>& moved) const {
  const size_t n = y_.size();
  if (moved.empty()) return *this;
  if (first + moved.size() > n) {
    std::ostringstream m;
    m << "moved samples " << first + 1 << " to " << first + moved.size() << " lie beyond the profile's " << n
      << " samples";
    throw InputError(source_, 0, m.str());
  }
  Profile out = *this;
  for (size_t j = 0; j < moved.size(); ++j) {
    if (!moved[j].allFinite()) throw InputError(source_, 0, "moved sample " + std::to_string(first + j + 1) + " is not finite");
    out.y_[first + j] = moved[j].x();
    out.z_[first + j] = moved[j].y();
  }
  const size_t margin = static_cast<size_t>(kMovedSplineMargin), last = first + moved.size() - 1;
  const size_t a = first > margin ? first - margin : 0, b = std::min(n - 1, last + margin);
  resolve_second_derivatives(out.y_, out.y2_, a, b, h_);
  resolve_second_derivatives(out.z_, out.z2_, a, b, h_);
  out.set_y_range();
  return out;
}

Profile Profile::Translated(double dy, double dz, const std::string& source) const {
  Profile out = *this;
  out.source_ = source;
  if (dz != 0.0)
    for (double& z : out.z_) z += dz;
  if (dy != 0.0) {
    for (double& y : out.y_) y += dy;
    out.set_y_range();
  }
  return out;
}

void Profile::locate(double s, int& i, double& t) const {
  const int n = static_cast<int>(y_.size());
  const double u = std::clamp(s, 0.0, length_) / h_;
  i = std::min(static_cast<int>(u), n - 2);
  t = u - i;
}

Eigen::Vector2d Profile::position(double s) const {
  int i;
  double b;
  locate(s, i, b);
  const double a = 1.0 - b, c = (a * a * a - a) * h_ * h_ / 6.0, d = (b * b * b - b) * h_ * h_ / 6.0;
  return {a * y_[i] + b * y_[i + 1] + c * y2_[i] + d * y2_[i + 1], a * z_[i] + b * z_[i + 1] + c * z2_[i] + d * z2_[i + 1]};
}

Eigen::Vector2d Profile::tangent(double s) const {
  int i;
  double b;
  locate(s, i, b);
  const double a = 1.0 - b;
  const double c = -(3 * a * a - 1) * h_ / 6.0, d = (3 * b * b - 1) * h_ / 6.0;
  Eigen::Vector2d v((y_[i + 1] - y_[i]) / h_ + c * y2_[i] + d * y2_[i + 1], (z_[i + 1] - z_[i]) / h_ + c * z2_[i] + d * z2_[i + 1]);
  return v.normalized();
}

Eigen::Vector2d Profile::normal(double s) const {
  const Eigen::Vector2d t = tangent(s);
  return {-t.y(), t.x()};
}

double Profile::curvature(double s) const {
  int i;
  double b;
  locate(s, i, b);
  const double a = 1.0 - b;
  const Eigen::Vector2d dd(a * y2_[i] + b * y2_[i + 1], a * z2_[i] + b * z2_[i + 1]);
  const Eigen::Vector2d t = tangent(s);
  // kappa = t x t' ; convex (tangent turning clockwise for outward left normal) is positive
  return -(t.x() * dd.y() - t.y() * dd.x());
}

double Profile::slope_angle(double s) const {
  const Eigen::Vector2d t = tangent(s);
  return std::atan2(t.y(), t.x());
}

void Profile::set_y_range() {
  y_min_ = *std::min_element(y_.begin(), y_.end());
  y_max_ = *std::max_element(y_.begin(), y_.end());
  y_runs_.clear();
  for (int i = 0; i + 1 < static_cast<int>(y_.size()); ++i) {
    const int direction = y_[i + 1] > y_[i] ? 1 : (y_[i + 1] < y_[i] ? -1 : 0);
    if (direction == 0) continue;  // a segment of constant y contains no y strictly inside its direction: never found
    if (!y_runs_.empty() && y_runs_.back().direction == direction && y_runs_.back().last_segment == i - 1)
      y_runs_.back().last_segment = i;
    else
      y_runs_.push_back({i, i, direction});
  }
}

std::optional<double> Profile::s_at(double y) const {
  if (y < y_min_ || y > y_max_) return std::nullopt;
  // the first segment i (in s) with y between y_i and y_i+1: in the first run whose y range holds y, the segment
  // before the run's first sample >= y (increasing) or <= y (decreasing), or the run's first segment
  for (const MonotonicRun& run : y_runs_) {
    const auto begin = y_.begin() + run.first_segment, end = y_.begin() + run.last_segment + 2;
    const double lo_y = run.direction > 0 ? *begin : *(end - 1), hi_y = run.direction > 0 ? *(end - 1) : *begin;
    if (y < lo_y || y > hi_y) continue;
    const auto at =
        run.direction > 0 ? std::lower_bound(begin, end, y) : std::lower_bound(begin, end, y, std::greater<double>());
    const int i = std::max(run.first_segment, static_cast<int>(at - y_.begin()) - 1);
    const double y0 = y_[i], y1 = y_[i + 1];
    // refine by bisection on the cubic segment
    double lo = i * h_, hi = (i + 1) * h_;
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double ym = position(mid).x();
      if ((ym < y) == (y1 > y0)) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
  }
  return std::nullopt;
}

std::optional<double> Profile::height_at(double y) const {
  auto s = s_at(y);
  if (!s) return std::nullopt;
  return position(*s).y();
}

double Profile::closest_s(const Eigen::Vector2d& q) const {
  const int n = static_cast<int>(y_.size());
  int best = 0;
  double bestd = 1e300;
  for (int i = 0; i < n; ++i) {
    const double d = (Eigen::Vector2d(y_[i], z_[i]) - q).squaredNorm();
    if (d < bestd) { bestd = d; best = i; }
  }
  double s = best * h_;
  for (int it = 0; it < 8; ++it) {  // Newton on (P(s) - q) . t(s) = 0 with unit speed
    const Eigen::Vector2d t = tangent(s);
    s = std::clamp(s - (position(s) - q).dot(t), 0.0, length_);
  }
  return s;
}

std::vector<Eigen::Vector2d> Profile::samples() const {
  std::vector<Eigen::Vector2d> out(y_.size());
  for (size_t i = 0; i < y_.size(); ++i) out[i] = {y_[i], z_[i]};
  return out;
}

namespace {
constexpr double kMinSampleSpacing_m = 1e-6;
}  // namespace

std::vector<Eigen::Vector2d> Profile::sample(double spacing_m) const {
  require_positive(spacing_m, "spacing_m");
  // (a spacing of 1e-10 m asked for 1.5e9 points, 1e-12 overflowed the count: fuzzing, session 25)
  if (spacing_m < kMinSampleSpacing_m) {
    char text[160];
    std::snprintf(text, sizeof text, "spacing_m = %g m is below %g m (1 um): a profile sampled finer is noise", spacing_m,
                  kMinSampleSpacing_m);
    throw InputError(text);
  }
  const int n = std::max(2, static_cast<int>(std::ceil(length_ / spacing_m)) + 1);
  std::vector<Eigen::Vector2d> out(n);
  for (int i = 0; i < n; ++i) out[i] = position(length_ * i / (n - 1));
  return out;
}

}  // namespace conforma
