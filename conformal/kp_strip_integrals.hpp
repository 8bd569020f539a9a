#pragma once
// Private to the KP solvers: influence integrals of one KP strip (semi-elliptic pressure in x, constant
// half-length across the strip width) at one observation point. Kernels are those of influence.hpp
// (docs/physics-reference.md §4.3, paper 003 eq. 5); here they are integrated exactly in x and by Gauss
// quadrature in s.
namespace conforma {
namespace kp_detail {

// F1 = integral over x in [d - c, d + c] of sqrt(c^2 - (x - d)^2) / sqrt(x^2 + u^2); u > 0.
// Closed form in complete elliptic integrals (d = 0: 2 sqrt(c^2 + u^2) (K(k) - E(k)), k'^2 = u^2 / (c^2 + u^2);
// d != 0: K - E plus Bulirsch's cel, see the .cpp).
double SemiEllipseOverDistance(double half_length, double centre_offset, double u);
// The same at up to kMaxSemiEllipseBatch distances u[0..count) for one (c, d): values[i] = F1(c, d, u[i]), each
// bit-identical to SemiEllipseOverDistance(c, d, u[i]) (the lanes only share the loop, for speed).
constexpr int kMaxSemiEllipseBatch = 8;
void SemiEllipseOverDistanceBatch(double half_length, double centre_offset, const double* u, int count,
                                  double* values);
// The instruction sets of F1's vector kernel: the batches use the widest the CPU runs (AVX-512VL: the AVX operations
// with 32 registers). Every kernel is bit-identical to the scalar form; SemiEllipseOverDistanceLanes runs a given
// one (for the test of that), std::logic_error where it is not available (CPU or build).
enum class SemiEllipseKernel { Scalar, Avx, Avx512vl };
bool SemiEllipseKernelAvailable(SemiEllipseKernel kernel);
// F1 at count lanes, each with its own half-length c[i] >= 0, centre offset d[i] and distance u[i] (any count).
void SemiEllipseOverDistanceLanes(SemiEllipseKernel kernel, const double* c, const double* d, const double* u,
                                  int count, double* values);
// The same integral by quadrature (the solver's former method, kept as the test reference): the log-singular part
// phi(0) (asinh...) in closed form, the bounded rest by graded Gauss quadrature in t (x = d + c sin t).
double SemiEllipseOverDistanceQuadrature(double half_length, double centre_offset, double u);

// F2 = u * integral of sqrt(c^2 - (x - d)^2) / (x^2 + u^2) dx = pi (Im sqrt((w - c)(w + c)) - u), w = -d + i u
// (Stieltjes transform of the semicircle); bounded as u -> 0.
double SemiEllipseCoupling(double half_length, double centre_offset, double u);

// cos(alpha) for the small relative normal rotations alpha of a patch (§4.1): for |alpha| <= pi/4 the Taylor series
// through alpha^18 (truncation below 3.3e-21, far under half an ulp of cos >= 0.707) in Horner form in alpha^2,
// within 1 ulp of the correctly rounded cosine (tests/test_kp_strip_closed_form.cpp); beyond, std::cos. A plain
// polynomial, so a loop over many angles vectorises, where the library call does not.
double CosOfSmallAngle(double alpha);

// One strip of load: s in [s_low, s_high], semi-ellipse half-length c centred at x offset d from the observation
// point, relative normal rotation alpha_J - alpha_I varying linearly from alpha_low to alpha_high across it.
struct StripLoad {
  double s_low = 0.0;
  double s_high = 0.0;
  double half_length = 0.0;
  double centre_offset = 0.0;
  double alpha_low = 0.0;
  double alpha_high = 0.0;
};

// Integral over the strip of sqrt(c^2 - (x-d)^2) * [(1 - nu) w_c / r + coupling_K w_s (s - s_obs) / r^2], with
// w_c = cos(alpha), w_s = sin(alpha) when blanco is true, else w_c = 1, w_s = 0. Unit m^2 (times 1/(pi G) and the
// pressure scale p0 / c_norm it gives the normal displacement at the observation point).
double StripNormalDisplacementIntegral(const StripLoad& strip, double s_observation, double poisson_ratio,
                                       bool blanco, double coupling_K);
// The same for count strips seen from one observation point (a row of the collocation, §5.3): integrals[k] is
// bit-identical to StripNormalDisplacementIntegral(strips[k], ...); the F1 values of all strips' Gauss nodes are
// evaluated together (SIMD lanes, x86-64 with AVX), which is faster than strip by strip.
void StripNormalDisplacementIntegrals(const StripLoad* strips, int count, double s_observation, double poisson_ratio,
                                      bool blanco, double coupling_K, double* integrals);

}  // namespace kp_detail
}  // namespace conforma
