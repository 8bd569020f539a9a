// The one load control (load_control.hpp).
#include "conforma/load_control.hpp"

#include <cmath>

#include "conforma/root_finding.hpp"

namespace conforma {

const char* to_string(LoadControlStatus status) {
  switch (status) {
    case LoadControlStatus::Ok: return "ok";
    case LoadControlStatus::NoBracket: return "no_bracket";
    case LoadControlStatus::NotConverged: return "not_converged";
  }
  return "?";
}

LoadControlResult SolveLoadControl(const std::function<double(double)>& carried_load, double load_N, double scale_m,
                                   double relative_tolerance) {
  LoadControlResult result;
  auto residual = [&](double push) { return carried_load(push) - load_N; };
  // bracket the push: the first guess is close, so start with a small step and expand
  const double scale = scale_m;
  double lo = -scale, hi = 0.25 * scale;
  double flo = residual(lo), fhi = residual(hi);
  for (int k = 0; k < 40 && fhi < 0.0; ++k) { lo = hi, flo = fhi; hi += scale * std::pow(2.0, k); fhi = residual(hi); }
  for (int k = 0; k < 40 && flo > 0.0; ++k) { hi = lo, fhi = flo; lo -= scale * std::pow(2.0, k); flo = residual(lo); }
  if (flo > 0.0 || fhi < 0.0) return result;  // NoBracket
  result.push_m = SolveIncreasingRoot(residual, lo, hi, flo, fhi, relative_tolerance * load_N, &result.iterations,
                                      &result.residual_N);
  result.status = std::fabs(result.residual_N) > 10.0 * relative_tolerance * load_N ? LoadControlStatus::NotConverged
                                                                                     : LoadControlStatus::Ok;
  return result;
}

}  // namespace conforma
