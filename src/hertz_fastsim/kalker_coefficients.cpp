// Kalker's creep coefficients (docs/physics-reference.md §2.2: Kalker 1990 Table E.3 via CONTACT m_hertz.f90 `linrol`,
// asymptotes for g < 0.1, 1/C quadratic in nu). The interpolation choices are documented in kalker.hpp.
#include "conforma/kalker.hpp"

#include <array>
#include <cmath>
#include <string>

#include "conforma/error.hpp"

namespace conforma {

namespace {

using Row = std::array<double, 3>;  // nu = 0, 0.25, 0.5

// Table E.3, rows g = 0.1 ... 1.0. a <= b (g = a/b).
constexpr std::array<Row, 10> kC11AleB = {{{2.51, 3.31, 4.85}, {2.59, 3.37, 4.81}, {2.68, 3.44, 4.80},
                                           {2.78, 3.53, 4.82}, {2.88, 3.62, 4.83}, {2.98, 3.72, 4.91},
                                           {3.09, 3.81, 4.97}, {3.19, 3.91, 5.05}, {3.29, 4.01, 5.12},
                                           {3.40, 4.12, 5.20}}};
constexpr std::array<Row, 10> kC22AleB = {{{2.51, 2.52, 2.53}, {2.59, 2.63, 2.66}, {2.68, 2.75, 2.81},
                                           {2.78, 2.88, 2.98}, {2.88, 3.01, 3.14}, {2.98, 3.14, 3.31},
                                           {3.09, 3.28, 3.48}, {3.19, 3.41, 3.65}, {3.29, 3.54, 3.82},
                                           {3.40, 3.67, 3.98}}};
// 1.25 at g = 0.8, nu = 0.25: see the typo warning of §2.2.
constexpr std::array<Row, 10> kC23AleB = {{{0.334, 0.473, 0.731}, {0.483, 0.603, 0.809}, {0.607, 0.715, 0.889},
                                           {0.720, 0.823, 0.977}, {0.827, 0.929, 1.07}, {0.930, 1.03, 1.18},
                                           {1.03, 1.14, 1.29}, {1.13, 1.25, 1.40}, {1.23, 1.36, 1.51},
                                           {1.33, 1.47, 1.63}}};
// C33 [MEM, unverified], a <= b only.
constexpr std::array<Row, 10> kC33AleB = {{{6.42, 8.28, 11.7}, {3.46, 4.27, 5.66}, {2.49, 2.96, 3.72},
                                           {2.02, 2.32, 2.77}, {1.74, 1.93, 2.22}, {1.56, 1.68, 1.86},
                                           {1.43, 1.50, 1.60}, {1.34, 1.37, 1.42}, {1.27, 1.27, 1.27},
                                           {1.21, 1.19, 1.16}}};
// a > b (g = b/a).
constexpr std::array<Row, 10> kC11AgtB = {{{10.7, 11.7, 12.9}, {6.96, 7.78, 8.82}, {5.57, 6.34, 7.34},
                                           {4.84, 5.57, 6.57}, {4.37, 5.10, 6.11}, {4.06, 4.78, 5.80},
                                           {3.82, 4.54, 5.58}, {3.65, 4.36, 5.42}, {3.51, 4.22, 5.30},
                                           {3.40, 4.12, 5.20}}};
constexpr std::array<Row, 10> kC22AgtB = {{{10.7, 12.8, 16.0}, {6.96, 8.14, 9.79}, {5.57, 6.40, 7.51},
                                           {4.84, 5.48, 6.31}, {4.37, 4.90, 5.56}, {4.06, 4.50, 5.04},
                                           {3.82, 4.21, 4.67}, {3.65, 3.99, 4.39}, {3.51, 3.81, 4.16},
                                           {3.40, 3.67, 3.98}}};
constexpr std::array<Row, 10> kC23AgtB = {{{12.2, 14.6, 18.0}, {5.72, 6.63, 7.89}, {3.79, 4.32, 5.01},
                                           {2.88, 3.24, 3.70}, {2.35, 2.62, 2.96}, {2.01, 2.23, 2.50},
                                           {1.76, 1.95, 2.18}, {1.58, 1.75, 1.94}, {1.44, 1.59, 1.77},
                                           {1.33, 1.47, 1.63}}};

constexpr std::array<double, 3> kNuNodes = {0.0, 0.25, 0.5};

// Asymptotes for g -> 0 (§2.2, CONTACT linrol), Lambda = ln(16/g^2).
double C11AsymptoteAleB(double, double nu) { return M_PI * M_PI / (4.0 * (1.0 - nu)); }
double C22AsymptoteAleB(double, double) { return M_PI * M_PI / 4.0; }
double C23AsymptoteAleB(double g, double nu) {
  return M_PI * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0));
}
double C33AsymptoteAleB(double g, double nu) { return M_PI * M_PI / (16.0 * (1.0 - nu) * g); }  // [MEM]
double C11AsymptoteAgtB(double g, double nu) {
  const double lambda = std::log(16.0 / (g * g));
  return 2.0 * M_PI / ((lambda - 2.0 * nu) * g) * (1.0 + (3.0 - std::log(4.0)) / (lambda - 2.0 * nu));
}
double C22AsymptoteAgtB(double g, double nu) {
  const double lambda = std::log(16.0 / (g * g));
  const double d = (1.0 - nu) * lambda + 2.0 * nu;
  return 2.0 * M_PI / g * (1.0 + (1.0 - nu) * (3.0 - std::log(4.0)) / d) / d;
}
double C23AsymptoteAgtB(double g, double nu) {
  const double lambda = std::log(16.0 / (g * g));
  return 2.0 * M_PI / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * lambda - 2.0 + 4.0 * nu));
}

// g^power for the four exponents used (0, -1/2, 1, 3/2), without std::pow (this runs once per patch).
double Power(double g, double power) {
  if (power == 0.0) return 1.0;
  if (power == 1.0) return g;
  if (power == 1.5) return g * std::sqrt(g);
  if (power == -0.5) return 1.0 / std::sqrt(g);
  return std::pow(g, power);
}

// One coefficient at one table Poisson ratio (column): the table interpolated in g of C * g^power
// (power = exponent that keeps it bounded), and below g = 0.1 the asymptote with a linear correction.
double CoefficientAtNode(const std::array<Row, 10>& table, int column, double g, double power,
                         double (*asymptote)(double, double)) {
  const double nu = kNuNodes[column];
  if (g < 0.1) {
    const double ratio_at_knot = table[0][column] / asymptote(0.1, nu);
    return asymptote(g, nu) * (1.0 + (g / 0.1) * (ratio_at_knot - 1.0));
  }
  // Row index: g = 0.1 (i = 0) ... 1.0 (i = 9).
  const double position = g * 10.0 - 1.0;
  int i = static_cast<int>(std::floor(position));
  if (i >= 9) return table[9][column];
  if (i < 0) i = 0;
  const double t = position - i;
  const double g0 = 0.1 * (i + 1), g1 = 0.1 * (i + 2);
  const double f0 = table[i][column] * Power(g0, power);
  const double f1 = table[i + 1][column] * Power(g1, power);
  return ((1.0 - t) * f0 + t * f1) / Power(g, power);
}

// Quadratic Lagrange interpolation of 1/C in nu through nu = 0, 0.25, 0.5 (§2.2, CONTACT).
double InterpolateInPoisson(const std::array<double, 3>& c, double nu) {
  const double inverse = 8.0 * (nu - 0.25) * (nu - 0.5) / c[0] - 16.0 * nu * (nu - 0.5) / c[1] +
                         8.0 * nu * (nu - 0.25) / c[2];
  return 1.0 / inverse;
}

double Coefficient(const std::array<Row, 10>& table, double g, double power, double (*asymptote)(double, double),
                   double nu) {
  std::array<double, 3> at_nodes{};
  for (int column = 0; column < 3; ++column) at_nodes[column] = CoefficientAtNode(table, column, g, power, asymptote);
  return InterpolateInPoisson(at_nodes, nu);
}

}  // namespace

CreepCoefficients KalkerCoefficients(double a_over_b, double poisson_ratio) {
  require_positive(a_over_b, "a_over_b");
  require_finite(poisson_ratio, "poisson_ratio");
  if (poisson_ratio < 0.0 || poisson_ratio > 0.5)
    throw InputError("KalkerCoefficients: parameter 'poisson_ratio' = " + MessageNumber(poisson_ratio) +
                     " must lie in [0, 0.5]");
  CreepCoefficients out;
  const double nu = poisson_ratio;
  if (a_over_b <= 1.0) {
    const double g = a_over_b;
    out.c11 = Coefficient(kC11AleB, g, 0.0, C11AsymptoteAleB, nu);
    out.c22 = Coefficient(kC22AleB, g, 0.0, C22AsymptoteAleB, nu);
    out.c23 = Coefficient(kC23AleB, g, -0.5, C23AsymptoteAleB, nu);
    out.c33 = Coefficient(kC33AleB, g, 1.0, C33AsymptoteAleB, nu);
    out.c33_available = true;
  } else {
    const double g = 1.0 / a_over_b;
    out.c11 = Coefficient(kC11AgtB, g, 1.0, C11AsymptoteAgtB, nu);
    out.c22 = Coefficient(kC22AgtB, g, 1.0, C22AsymptoteAgtB, nu);
    out.c23 = Coefficient(kC23AgtB, g, 1.5, C23AsymptoteAgtB, nu);
    out.c33_available = false;
  }
  out.c33_verified = false;
  return out;
}

}  // namespace conforma
