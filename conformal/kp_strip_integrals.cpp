// Influence integrals of one KP strip (docs/physics-reference.md §3.2 "integration tip", §4.3; paper 003 eqs. 5, 8).
#include "kp_strip_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "conforma/hertz.hpp"

namespace conforma {
namespace kp_detail {

namespace {

// Gauss-Legendre nodes and weights on [-1, 1] (positive half; symmetric).
constexpr double kGauss2Node[1] = {0.5773502691896257};
constexpr double kGauss2Weight[1] = {1.0};
constexpr double kGauss4Node[2] = {0.3399810435848563, 0.8611363115940526};
constexpr double kGauss4Weight[2] = {0.6521451548625461, 0.3478548451374538};
constexpr double kGauss8Node[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kGauss8Weight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                     0.1012285362903763};

// The n-point rule (n = 2, 4, 8) on [a, b]: its nodes in evaluation order (x[2i] = mid - half node_i, x[2i+1] = mid + half
// node_i) and the sum it forms from the values there: the same arithmetic, with f evaluated as a batch.
struct GaussRule {
  const double* node = kGauss8Node;
  const double* weight = kGauss8Weight;
  int pairs = 4;
  double mid = 0.0, half = 0.0;
  GaussRule(double a, double b, int points) : mid(0.5 * (a + b)), half(0.5 * (b - a)) {
    if (points == 2) {
      node = kGauss2Node;
      weight = kGauss2Weight;
      pairs = 1;
    } else if (points == 4) {
      node = kGauss4Node;
      weight = kGauss4Weight;
      pairs = 2;
    }
  }
  int count() const { return 2 * pairs; }
  void Nodes(double* x) const {
    for (int i = 0; i < pairs; ++i) {
      x[2 * i] = mid - half * node[i];
      x[2 * i + 1] = mid + half * node[i];
    }
  }
  double Sum(const double* values) const {
    double sum = 0.0;
    for (int i = 0; i < pairs; ++i) sum += weight[i] * (values[2 * i] + values[2 * i + 1]);
    return sum * half;
  }
};

// Integral of f over [a, b] with the n-point rule (n = 2, 4, 8).
template <class F>
double Gauss(const F& f, double a, double b, int points) {
  const GaussRule rule(a, b, points);
  double x[8], values[8];
  rule.Nodes(x);
  for (int i = 0; i < rule.count(); ++i) values[i] = f(x[i]);
  return rule.Sum(values);
}

// Integral of f over [t_start, t_end] with panels growing geometrically away from t_start (where f varies on the
// scale first_panel), 8-point Gauss per panel.
template <class F>
double GradedGauss(const F& f, double t_start, double t_end, double first_panel) {
  const double length = std::abs(t_end - t_start);
  if (length <= 0.0) return 0.0;
  const double direction = t_end > t_start ? 1.0 : -1.0;
  double panel = std::min(std::max(first_panel, 1e-6 * length), length);
  double position = 0.0;
  double sum = 0.0;
  while (position < length) {
    const double next = (length - position < 1.5 * panel) ? length : position + panel;
    sum += Gauss(f, t_start + direction * position, t_start + direction * next, 8);
    position = next;
    panel *= 4.0;
  }
  return sum;  // Gauss() on a reversed interval already carries the sign
}

}  // namespace

double SemiEllipseOverDistanceQuadrature(double half_length, double centre_offset, double u) {
  const double c = half_length;
  if (c <= 0.0) return 0.0;
  if (centre_offset == 0.0) {
    // Integral of sqrt(c^2 - x^2)/sqrt(x^2 + u^2) over [-c, c] = 2 sqrt(c^2+u^2) (K(k) - E(k)), k' = u/sqrt(c^2+u^2).
    const double hypot = std::sqrt(c * c + u * u);
    return 2.0 * hypot * EllipticIntegralsFromComplementaryModulus(u / hypot).K_minus_E;
  }
  const double d = centre_offset;
  // Log-singular part phi(0) * integral of 1/sqrt(x^2 + u^2) in closed form, bounded rest numerically in t
  // (x = d + c sin t), panels graded towards the point x = 0 (or the end nearest to it).
  const double phi0 = std::abs(d) < c ? std::sqrt(c * c - d * d) : 0.0;
  const double singular = phi0 * (std::asinh((d + c) / u) - std::asinh((d - c) / u));
  const double t_zero = std::asin(std::clamp(-d / c, -1.0, 1.0));
  auto rest = [&](double t) {
    const double x = d + c * std::sin(t);
    const double cos_t = std::cos(t);
    return (c * cos_t - phi0) * c * cos_t / std::sqrt(x * x + u * u);
  };
  const double first_panel = 0.5 * u / c;
  return singular + GradedGauss(rest, t_zero, 0.5 * M_PI, first_panel) -
         GradedGauss(rest, t_zero, -0.5 * M_PI, first_panel);
}

void SemiEllipseOverDistanceBatch(double half_length, double centre_offset, const double* u, int count,
                                  double* values) {
  constexpr int kMaxBatch = kMaxSemiEllipseBatch;
  if (count < 0 || count > kMaxBatch) throw std::logic_error("SemiEllipseOverDistanceBatch: count out of range");
  // Closed form (own derivation, checked against 40-digit quadrature in tests/test_kp_strip_closed_form.cpp): with
  // the distances A, B from the observation point to the two ends of the semi-ellipse, Byrd & Friedman 259.00's
  // substitution turns F1 into complete elliptic integrals of the first, second and third kind,
  //   F1 = 2 sqrt(A B) [ K(k) - E(k) + (A - B)^2 / (4 A B) * cel(k', p, 1, 0) ],
  //   k^2 = (4 c^2 - (A - B)^2) / (4 A B),  k'^2 = ((A + B)^2 - 4 c^2) / (4 A B),  p = (A + B)^2 / (4 A B),
  // cel(k', p, a, b) = integral over [0, pi/2] of (a cos^2 + b sin^2) / ((cos^2 + p sin^2) sqrt(cos^2 + k'^2 sin^2))
  // (Bulirsch's general complete elliptic integral). Every term is positive: no cancellation. d = 0 (A = B):
  // 2 sqrt(c^2 + u^2) (K - E), k' = u / sqrt(c^2 + u^2).
  // K - E and cel(k', p, 1, 0) (Bulirsch 1969, Numer. Math. 13; the Numerical Recipes `cel`) come from ONE
  // arithmetic-geometric mean of (1, k'): Bulirsch's em_n, qc_n are 2^n a_n, 2^n b_n of the AGM, and
  // K - E = K sum_n 2^(n-1) c_n^2 (docs/physics-reference.md §1.2, as EllipticIntegralsFromComplementaryModulus),
  // c_0 = k, c_(n+1) = (a_n - b_n) / 2. The lanes run side by side (independent dependency chains overlap in the
  // CPU); each lane stops at its own convergence, so its value does not depend on the other lanes.
  const double c = half_length;
  const double D = std::abs(centre_offset);  // F1 is even in d
  double qc[kMaxBatch], e[kMaxBatch], em[kMaxBatch], p[kMaxBatch], a[kMaxBatch], b[kMaxBatch], sum[kMaxBatch],
      prefactor[kMaxBatch], cel_weight[kMaxBatch];
  bool active[kMaxBatch], closed_form[kMaxBatch];
  double weight = 0.25;  // 2^(n-1) / 4^(n+1) for the term (2^n a_n - 2^n b_n)^2 of c_(n+1)
  double scale = 1.0;    // 2^(n+1) after the update of em
  double lane_scale[kMaxBatch];
  for (int i = 0; i < count; ++i) {
    active[i] = closed_form[i] = false;
    values[i] = 0.0;
    if (c <= 0.0) continue;
    const double u2 = u[i] * u[i];
    const double A = std::sqrt((c + D) * (c + D) + u2);  // to the far end
    const double B = std::sqrt((D - c) * (D - c) + u2);  // to the near end
    const double four_AB = 4.0 * A * B;
    const double inverse_four_AB = 1.0 / four_AB, inverse_sum = 1.0 / (A + B);
    // A + B - 2c >= 0 and A + B - 2D >= 0 (triangle inequalities) without cancellation
    const double far_excess = u2 / (A + c + D);                                                // A - (c + D)
    const double near_excess = u2 / (B + std::abs(c - D));                                     // B - |c - D|
    const double near_excess_c = c >= D ? near_excess : B - (c - D);                          // B - (c - D)
    const double near_excess_D = D >= c ? near_excess : B - (D - c);                          // B - (D - c)
    const double kc_squared = (far_excess + near_excess_c) * (A + B + 2.0 * c) * inverse_four_AB;
    if (!(kc_squared > 0.0)) {  // on the segment: log-infinite (or NaN input); the quadrature says what it says
      values[i] = SemiEllipseOverDistanceQuadrature(c, centre_offset, u[i]);
      continue;
    }
    const double A_minus_B = 4.0 * c * D * inverse_sum;  // (A^2 - B^2) / (A + B)
    // 2c - (A - B) = 2c (A + B - 2D) / (A + B)
    const double k_squared =
        2.0 * c * (far_excess + near_excess_D) * inverse_sum * (2.0 * c + A_minus_B) * inverse_four_AB;
    active[i] = closed_form[i] = true;
    qc[i] = e[i] = std::min(std::sqrt(kc_squared), 1.0);
    em[i] = 1.0;
    p[i] = std::sqrt((A + B) * (A + B) * inverse_four_AB);
    a[i] = 1.0;
    b[i] = 0.0;
    sum[i] = 0.5 * k_squared;  // 2^(-1) c_0^2
    prefactor[i] = 2.0 * std::sqrt(A * B);
    cel_weight[i] = A_minus_B * A_minus_B * inverse_four_AB;
  }
  constexpr double kTolerance = 1e-9;  // relative AGM spread; the error after the last step is its square
  for (int iteration = 0; iteration < 60; ++iteration) {
    scale *= 2.0;
    bool any_active = false;
    for (int i = 0; i < count; ++i) {
      if (!active[i]) continue;
      const double f = a[i];
      const double inverse_p = 1.0 / p[i];
      a[i] += b[i] * inverse_p;
      double g = e[i] * inverse_p;
      b[i] += f * g;
      b[i] += b[i];
      p[i] += g;
      g = em[i];
      em[i] += qc[i];
      sum[i] += weight * (g - qc[i]) * (g - qc[i]);
      if (std::abs(g - qc[i]) <= g * kTolerance) {
        active[i] = false;
        lane_scale[i] = scale;
        continue;
      }
      any_active = true;
      qc[i] = 2.0 * std::sqrt(e[i]);
      e[i] = qc[i] * em[i];
    }
    weight *= 0.5;
    if (!any_active) break;
  }
  for (int i = 0; i < count; ++i) {
    if (!closed_form[i]) continue;
    if (active[i]) lane_scale[i] = scale;  // not converged in 60 steps (cannot happen for k' in (0, 1])
    const double K_minus_E = M_PI * lane_scale[i] / (2.0 * em[i]) * sum[i];  // K = pi / (2 AGM), AGM = em / 2^(n+1)
    const double cel = 0.5 * M_PI * (b[i] + a[i] * em[i]) / (em[i] * (em[i] + p[i]));
    values[i] = prefactor[i] * (K_minus_E + cel_weight[i] * cel);
  }
}

double SemiEllipseOverDistance(double half_length, double centre_offset, double u) {
  double value = 0.0;
  SemiEllipseOverDistanceBatch(half_length, centre_offset, &u, 1, &value);
  return value;
}

double SemiEllipseCoupling(double half_length, double centre_offset, double u) {
  const double c = half_length;
  if (c <= 0.0) return 0.0;
  const std::complex<double> w(-centre_offset, u);
  const std::complex<double> root = std::sqrt(w - c) * std::sqrt(w + c);  // branch ~ w at infinity, cut on [-c, c]
  return M_PI * (root.imag() - u);
}

double StripNormalDisplacementIntegral(const StripLoad& strip, double s_observation, double poisson_ratio,
                                       bool blanco, double coupling_K) {
  const double c = strip.half_length;
  const double d = strip.centre_offset;
  if (c <= 0.0 || strip.s_high <= strip.s_low) return 0.0;
  const double alpha_slope = (strip.alpha_high - strip.alpha_low) / (strip.s_high - strip.s_low);
  auto alpha_at = [&](double s) { return strip.alpha_low + alpha_slope * (s - strip.s_low); };
  const bool coupled = blanco && coupling_K != 0.0;
  // Regular integrand at the points s[0..count) != s_observation (F1 for all of them in one batch).
  auto integrand = [&](const double* s, int count, double* values) {
    double u[kMaxSemiEllipseBatch];
    for (int i = 0; i < count; ++i) u[i] = std::abs(s[i] - s_observation);
    SemiEllipseOverDistanceBatch(c, d, u, count, values);
    for (int i = 0; i < count; ++i) {
      double value = (1.0 - poisson_ratio) * values[i];
      if (blanco) {
        const double alpha = alpha_at(s[i]);
        value *= std::cos(alpha);
        if (coupled)
          value += coupling_K * std::sin(alpha) * (s[i] > s_observation ? 1.0 : -1.0) * SemiEllipseCoupling(c, d, u[i]);
      }
      values[i] = value;
    }
  };
  // A piece [a, b] of the strip not containing the observation point in its interior.
  auto regular_piece = [&](double a, double b) {
    const double distance = std::min(std::abs(a - s_observation), std::abs(b - s_observation));
    const double ratio = distance / (b - a);
    // Thresholds away from the half-integer ratios of a centred observation point (no switching by rounding).
    const int points = ratio < 1.0 ? 8 : (ratio < 3.0 ? 4 : 2);
    const GaussRule rule(a, b, points);
    double s[8], values[8];
    rule.Nodes(s);
    integrand(s, rule.count(), values);
    return rule.Sum(values);
  };
  if (s_observation <= strip.s_low || s_observation >= strip.s_high) {
    if (s_observation == strip.s_low || s_observation == strip.s_high) {
      // touches the observation point: handled like a singular half below
    } else {
      return regular_piece(strip.s_low, strip.s_high);
    }
  }
  // The strip holds the observation point: split there. Near u = 0 the 1/r part behaves like
  // -2 phi(0) w_c(0) ln u (phi(0) = sqrt(c^2 - d^2)); subtract it and add its exact integral h (ln h - 1).
  const double phi0 = std::abs(d) < c ? std::sqrt(c * c - d * d) : 0.0;
  const double weight0 = blanco ? std::cos(alpha_at(s_observation)) : 1.0;
  const double log_coefficient = 2.0 * (1.0 - poisson_ratio) * phi0 * weight0;
  double total = 0.0;
  for (int side = 0; side < 2; ++side) {
    const double h = side == 0 ? s_observation - strip.s_low : strip.s_high - s_observation;
    if (h <= 0.0) continue;
    const double sign = side == 0 ? -1.0 : 1.0;
    const GaussRule rule(0.0, h, 8);
    double u[8], s[8], values[8];
    rule.Nodes(u);
    for (int i = 0; i < 8; ++i) s[i] = s_observation + sign * u[i];
    integrand(s, 8, values);
    for (int i = 0; i < 8; ++i) values[i] += log_coefficient * std::log(u[i]);
    total += rule.Sum(values) - log_coefficient * h * (std::log(h) - 1.0);
  }
  return total;
}

}  // namespace kp_detail
}  // namespace conforma
