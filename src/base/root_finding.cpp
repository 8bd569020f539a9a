// The one scalar root finder (root_finding.hpp).
#include "conforma/root_finding.hpp"

#include <cmath>

namespace conforma {

double SolveIncreasingRoot(const std::function<double(double)>& f, double low, double high, double f_low,
                           double f_high, double tolerance_abs, int* iterations, double* f_at_root) {
  IllinoisBracket bracket(low, f_low, high, f_high);
  double x = low;
  for (int it = 0; it < 100; ++it) {
    *iterations = it + 1;
    x = bracket.FalsePosition();
    if (!(x > bracket.low() && x < bracket.high())) x = 0.5 * (bracket.low() + bracket.high());
    const double fx = f(x);
    *f_at_root = fx;
    if (std::fabs(fx) <= tolerance_abs || bracket.high() - bracket.low() < 1e-15) return x;
    bracket.Replace(x, fx, fx < 0.0);
  }
  return x;
}

}  // namespace conforma
