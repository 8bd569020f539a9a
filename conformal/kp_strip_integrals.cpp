// Influence integrals of one KP strip (docs/physics-reference.md §3.2 "integration tip", §4.3; paper 003 eqs. 5, 8).
#include "kp_strip_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

#include "conforma/hertz.hpp"

namespace conforma {
namespace kp_detail {

namespace {

// CosOfSmallAngle's range and polynomial: cos x = 1 - x^2/2 + x^4 R(x^2), R(z) = sum_n (-1)^n z^(n-2) / (2n)!,
// n = 2..9 (the factorials are exact doubles, 18! < 2^53, so each coefficient is their correctly rounded quotient),
// R by Horner; 1 - x^2/2 with its rounding error carried into the small rest (as fdlibm's __kernel_cos).
constexpr double kSmallAngle = 0.25 * M_PI;
inline double CosPolynomial(double x) {
  const double z = x * x;
  double r = 1.0 / 6402373705728000.0;  // 1/18!
  r = -1.0 / 20922789888000.0 + z * r;
  r = 1.0 / 87178291200.0 + z * r;
  r = -1.0 / 479001600.0 + z * r;
  r = 1.0 / 3628800.0 + z * r;
  r = -1.0 / 40320.0 + z * r;
  r = 1.0 / 720.0 + z * r;
  r = -1.0 / 24.0 + z * r;  // -R(z)
  const double half_z = 0.5 * z;
  const double w = 1.0 - half_z;
  return w + (((1.0 - w) - half_z) - z * z * r);
}

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

namespace {

// The closed form below, lane by lane in scalar arithmetic (any x86-64 CPU and other architectures), lane i with
// half-length c_in[i], centre offset d_in[i] and distance u[i]; count <= kMaxSemiEllipseBatch.
void SemiEllipseLanesScalar(const double* c_in, const double* d_in, const double* u, int count, double* values) {
  constexpr int kMaxBatch = kMaxSemiEllipseBatch;
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
  double qc[kMaxBatch], e[kMaxBatch], em[kMaxBatch], p[kMaxBatch], a[kMaxBatch], b[kMaxBatch], sum[kMaxBatch],
      prefactor[kMaxBatch], cel_weight[kMaxBatch];
  bool active[kMaxBatch], closed_form[kMaxBatch];
  double weight = 0.25;  // 2^(n-1) / 4^(n+1) for the term (2^n a_n - 2^n b_n)^2 of c_(n+1)
  double scale = 1.0;    // 2^(n+1) after the update of em
  double lane_scale[kMaxBatch];
  for (int i = 0; i < count; ++i) {
    active[i] = closed_form[i] = false;
    values[i] = 0.0;
    const double c = c_in[i];
    const double D = std::abs(d_in[i]);  // F1 is even in d
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
      values[i] = SemiEllipseOverDistanceQuadrature(c, d_in[i], u[i]);
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

#if defined(__GNUC__) && defined(__x86_64__)
#define CONFORMA_SEMI_ELLIPSE_AVX 1
// The AVX kernel (kp_semi_ellipse_lanes_avx.inc) compiled from one source for two instruction sets: AVX, and
// AVX-512VL, which runs the same 256-bit operations with 32 vector registers instead of 16 (the 4 vectors of ~11
// quantities each then stay in registers rather than on the stack: about 11 % less time per conformal C API
// evaluation, issue 15 item 6). Both bit-identical to SemiEllipseLanesScalar; AVX-512 has fused multiply-add, so
// contraction is switched off for it (the lanes' bit-identity is tested, tests/test_kp_strip_closed_form.cpp).
#define CONFORMA_LANES_TARGET "avx"
#define CONFORMA_LANES_FUNCTION SemiEllipseLanesAvx
#include "kp_semi_ellipse_lanes_avx.inc"
#undef CONFORMA_LANES_TARGET
#undef CONFORMA_LANES_FUNCTION
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#define CONFORMA_LANES_TARGET "avx512f,avx512vl"
#define CONFORMA_LANES_FUNCTION SemiEllipseLanesAvx512vl
#include "kp_semi_ellipse_lanes_avx.inc"
#undef CONFORMA_LANES_TARGET
#undef CONFORMA_LANES_FUNCTION
#pragma GCC pop_options


// The vector kernel for kVectors vectors, AVX or AVX-512VL (the same arithmetic either way).
template <int kVectors>
void SemiEllipseLanesVectors(SemiEllipseKernel kernel, const double* c, const double* D, const double* u, int count,
                             double* values, bool* quadrature) {
  if (kernel == SemiEllipseKernel::Avx512vl)
    SemiEllipseLanesAvx512vl<kVectors>(c, D, u, count, values, quadrature);
  else
    SemiEllipseLanesAvx<kVectors>(c, D, u, count, values, quadrature);
}
#endif

// The widest kernel the CPU runs.
SemiEllipseKernel BestSemiEllipseKernel() {
  static const SemiEllipseKernel best = [] {
    if (SemiEllipseKernelAvailable(SemiEllipseKernel::Avx512vl)) return SemiEllipseKernel::Avx512vl;
    if (SemiEllipseKernelAvailable(SemiEllipseKernel::Avx)) return SemiEllipseKernel::Avx;
    return SemiEllipseKernel::Scalar;
  }();
  return best;
}

// F1 at count lanes with their own half-length c[i] >= 0, centre offset d[i] and distance u[i] (any count), with an
// available kernel.
void SemiEllipseLanes(SemiEllipseKernel kernel, const double* c, const double* d, const double* u, int count,
                      double* values) {
#ifdef CONFORMA_SEMI_ELLIPSE_AVX
  // up to 16 lanes at a time in 4 vectors (their division and square-root chains overlap); one or two lanes are
  // faster in scalar arithmetic (two interleaved chains against one vector's chain)
  if (count >= 3 && kernel != SemiEllipseKernel::Scalar) {
    constexpr int kChunk = 16;
    for (int first = 0; first < count; first += kChunk) {
      const int lanes = std::min(kChunk, count - first);
      if (lanes <= 2) {
        SemiEllipseLanesScalar(c + first, d + first, u + first, lanes, values + first);
        continue;
      }
      double D[kChunk];
      bool quadrature[kChunk];
      for (int i = 0; i < lanes; ++i) D[i] = std::abs(d[first + i]);  // F1 is even in d
      switch ((lanes + 3) / 4) {
        case 1: SemiEllipseLanesVectors<1>(kernel, c + first, D, u + first, lanes, values + first, quadrature); break;
        case 2: SemiEllipseLanesVectors<2>(kernel, c + first, D, u + first, lanes, values + first, quadrature); break;
        case 3: SemiEllipseLanesVectors<3>(kernel, c + first, D, u + first, lanes, values + first, quadrature); break;
        default: SemiEllipseLanesVectors<4>(kernel, c + first, D, u + first, lanes, values + first, quadrature); break;
      }
      for (int i = first; i < first + lanes; ++i) {  // c <= 0 or on the segment: as SemiEllipseLanesScalar
        if (!quadrature[i - first]) continue;
        values[i] = c[i] <= 0.0 ? 0.0 : SemiEllipseOverDistanceQuadrature(c[i], d[i], u[i]);
      }
    }
    return;
  }
#endif
  for (int first = 0; first < count; first += kMaxSemiEllipseBatch)
    SemiEllipseLanesScalar(c + first, d + first, u + first, std::min(kMaxSemiEllipseBatch, count - first),
                           values + first);
}

}  // namespace

bool SemiEllipseKernelAvailable(SemiEllipseKernel kernel) {
  switch (kernel) {
    case SemiEllipseKernel::Scalar: return true;
#ifdef CONFORMA_SEMI_ELLIPSE_AVX
    case SemiEllipseKernel::Avx: {
      static const bool has_avx = __builtin_cpu_supports("avx");
      return has_avx;
    }
    case SemiEllipseKernel::Avx512vl: {  // (libgcc also checks that the OS saves the AVX-512 state)
      static const bool has_avx512vl = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
      return has_avx512vl;
    }
#endif
    default: return false;
  }
}

void SemiEllipseOverDistanceLanes(SemiEllipseKernel kernel, const double* c, const double* d, const double* u,
                                  int count, double* values) {
  if (!SemiEllipseKernelAvailable(kernel))
    throw std::logic_error("SemiEllipseOverDistanceLanes: the kernel is not available on this CPU or build");
  SemiEllipseLanes(kernel, c, d, u, count, values);
}

void SemiEllipseOverDistanceBatch(double half_length, double centre_offset, const double* u, int count,
                                  double* values) {
  if (count < 0 || count > kMaxSemiEllipseBatch)
    throw std::logic_error("SemiEllipseOverDistanceBatch: count out of range");
  double c[kMaxSemiEllipseBatch], d[kMaxSemiEllipseBatch];
  std::fill(c, c + count, half_length);
  std::fill(d, d + count, centre_offset);
  SemiEllipseLanes(BestSemiEllipseKernel(), c, d, u, count, values);
}

double SemiEllipseOverDistance(double half_length, double centre_offset, double u) {
  double value = 0.0;
  SemiEllipseOverDistanceBatch(half_length, centre_offset, &u, 1, &value);
  return value;
}

double CosOfSmallAngle(double alpha) {
  return std::abs(alpha) <= kSmallAngle ? CosPolynomial(alpha) : std::cos(alpha);  // (NaN: std::cos)
}

double SemiEllipseCoupling(double half_length, double centre_offset, double u) {
  const double c = half_length;
  if (c <= 0.0) return 0.0;
  const std::complex<double> w(-centre_offset, u);
  const std::complex<double> root = std::sqrt(w - c) * std::sqrt(w + c);  // branch ~ w at infinity, cut on [-c, c]
  return M_PI * (root.imag() - u);
}

namespace {

// The Gauss nodes of one strip's integral (StripNormalDisplacementIntegrals) and where its F1 values lie in the
// lanes shared by all strips of the call.
struct StripPlan {
  bool empty;     // no load (c <= 0 or no width): integral 0
  bool singular;  // the strip holds the observation point: two halves of 8 nodes (h[side] > 0)
  int first_lane;
  int points;     // regular: 2, 4 or 8 nodes on [s_low, s_high]
  double h[2];
};

// size elements on the stack up to N, else on the heap (a row of the collocation fits on the stack)
template <class T, int N>
class ScratchArray {
 public:
  explicit ScratchArray(int size) {
    if (size > N) heap_.resize(size);
    data_ = size > N ? heap_.data() : local_;
  }
  T& operator[](int i) { return data_[i]; }
  T* data() { return data_; }

 private:
  T local_[N];
  std::vector<T> heap_;
  T* data_;
};

// StripNormalDisplacementIntegrals with scratch space on the stack for kStackStrips strips.
template <int kStackStrips>
void IntegralsOfStrips(const StripLoad* strips, int count, double s_observation, double poisson_ratio, bool blanco,
                       double coupling_K, double* integrals) {
  // Every strip's regular-integrand nodes first, then F1 at all of them in one call (independent lanes: each value is
  // the one a strip-by-strip evaluation gives), then each strip's sum in the order of the single-strip rule.
  ScratchArray<StripPlan, kStackStrips> plans(count);
  const int max_lanes = 16 * count;  // at most 16 nodes per strip
  ScratchArray<double, 16 * kStackStrips> lane_c(max_lanes), lane_d(max_lanes), lane_u(max_lanes), lane_s(max_lanes);
  ScratchArray<double, 16 * kStackStrips> lane_alpha(blanco ? max_lanes : 0), lane_cos(blanco ? max_lanes : 0);
  int lanes = 0;
  auto add_lanes = [&](const StripLoad& strip, const double* s, int n) {
    // alpha at the node, linear across the strip (paper 003 eq. 5: the weight cos(alpha_J - alpha_I))
    const double alpha_slope = (strip.alpha_high - strip.alpha_low) / (strip.s_high - strip.s_low);
    for (int i = 0; i < n; ++i, ++lanes) {
      lane_c[lanes] = strip.half_length;
      lane_d[lanes] = strip.centre_offset;
      lane_s[lanes] = s[i];
      lane_u[lanes] = std::abs(s[i] - s_observation);
      if (blanco) lane_alpha[lanes] = strip.alpha_low + alpha_slope * (s[i] - strip.s_low);
    }
  };
  for (int k = 0; k < count; ++k) {
    const StripLoad& strip = strips[k];
    StripPlan& plan = plans[k];
    plan = StripPlan{true, false, 0, 0, {0.0, 0.0}};
    if (strip.half_length <= 0.0 || strip.s_high <= strip.s_low) continue;
    plan.empty = false;
    plan.first_lane = lanes;
    const bool outside = s_observation <= strip.s_low || s_observation >= strip.s_high;
    const bool touching = s_observation == strip.s_low || s_observation == strip.s_high;
    if (outside && !touching) {
      // A piece [a, b] of the strip not containing the observation point in its interior.
      const double a = strip.s_low, b = strip.s_high;
      const double distance = std::min(std::abs(a - s_observation), std::abs(b - s_observation));
      const double ratio = distance / (b - a);
      // Thresholds away from the half-integer ratios of a centred observation point (no switching by rounding).
      plan.points = ratio < 1.0 ? 8 : (ratio < 3.0 ? 4 : 2);
      const GaussRule rule(a, b, plan.points);
      double s[8];
      rule.Nodes(s);
      add_lanes(strip, s, rule.count());
      continue;
    }
    // The strip holds (or touches) the observation point: split there, 8 nodes on each half of positive length.
    plan.singular = true;
    for (int side = 0; side < 2; ++side) {
      const double h = side == 0 ? s_observation - strip.s_low : strip.s_high - s_observation;
      plan.h[side] = h;
      if (h <= 0.0) continue;
      const double sign = side == 0 ? -1.0 : 1.0;
      const GaussRule rule(0.0, h, 8);
      double u[8], s[8];
      rule.Nodes(u);
      for (int i = 0; i < 8; ++i) s[i] = s_observation + sign * u[i];
      add_lanes(strip, s, 8);
    }
  }
  ScratchArray<double, 16 * kStackStrips> f1(lanes);
  SemiEllipseLanes(BestSemiEllipseKernel(), lane_c.data(), lane_d.data(), lane_u.data(), lanes, f1.data());
  if (blanco) {  // the weights cos(alpha) of all lanes: the polynomial in one vectorisable loop, std::cos beyond
    for (int i = 0; i < lanes; ++i) lane_cos[i] = CosPolynomial(lane_alpha[i]);
    for (int i = 0; i < lanes; ++i)
      if (!(std::abs(lane_alpha[i]) <= kSmallAngle)) lane_cos[i] = std::cos(lane_alpha[i]);
  }

  for (int k = 0; k < count; ++k) {
    const StripLoad& strip = strips[k];
    const StripPlan& plan = plans[k];
    integrals[k] = 0.0;
    if (plan.empty) continue;
    const double c = strip.half_length;
    const double d = strip.centre_offset;
    const double alpha_slope = (strip.alpha_high - strip.alpha_low) / (strip.s_high - strip.s_low);
    auto alpha_at = [&](double s) { return strip.alpha_low + alpha_slope * (s - strip.s_low); };
    const bool coupled = blanco && coupling_K != 0.0;
    // Regular integrand at the lanes [first, first + n) (their F1 values in f1).
    auto integrand = [&](int first, int n, double* values) {
      for (int i = 0; i < n; ++i) {
        const double s = lane_s[first + i];
        double value = (1.0 - poisson_ratio) * f1[first + i];
        if (blanco) {
          const double alpha = lane_alpha[first + i];
          value *= lane_cos[first + i];
          if (coupled)
            value += coupling_K * std::sin(alpha) * (s > s_observation ? 1.0 : -1.0) *
                     SemiEllipseCoupling(c, d, lane_u[first + i]);
        }
        values[i] = value;
      }
    };
    if (!plan.singular) {
      const GaussRule rule(strip.s_low, strip.s_high, plan.points);
      double values[8];
      integrand(plan.first_lane, rule.count(), values);
      integrals[k] = rule.Sum(values);
      continue;
    }
    // Near u = 0 the 1/r part behaves like -2 phi(0) w_c(0) ln u (phi(0) = sqrt(c^2 - d^2)); subtract it and add its
    // exact integral h (ln h - 1).
    const double phi0 = std::abs(d) < c ? std::sqrt(c * c - d * d) : 0.0;
    const double weight0 = blanco ? std::cos(alpha_at(s_observation)) : 1.0;
    const double log_coefficient = 2.0 * (1.0 - poisson_ratio) * phi0 * weight0;
    double total = 0.0;
    int lane = plan.first_lane;
    for (int side = 0; side < 2; ++side) {
      const double h = plan.h[side];
      if (h <= 0.0) continue;
      const GaussRule rule(0.0, h, 8);
      double u[8], values[8];
      rule.Nodes(u);
      integrand(lane, 8, values);
      lane += 8;
      for (int i = 0; i < 8; ++i) values[i] += log_coefficient * std::log(u[i]);
      total += rule.Sum(values) - log_coefficient * h * (std::log(h) - 1.0);
    }
    integrals[k] = total;
  }
}

}  // namespace

void StripNormalDisplacementIntegrals(const StripLoad* strips, int count, double s_observation, double poisson_ratio,
                                      bool blanco, double coupling_K, double* integrals) {
  IntegralsOfStrips<32>(strips, count, s_observation, poisson_ratio, blanco, coupling_K, integrals);
}

double StripNormalDisplacementIntegral(const StripLoad& strip, double s_observation, double poisson_ratio,
                                       bool blanco, double coupling_K) {
  double integral = 0.0;
  IntegralsOfStrips<1>(&strip, 1, s_observation, poisson_ratio, blanco, coupling_K, &integral);
  return integral;
}

}  // namespace kp_detail
}  // namespace conforma
