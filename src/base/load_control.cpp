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
                                   double relative_tolerance, LoadResponse response) {
  LoadControlResult result;
  const bool hertz_power = response == LoadResponse::HertzPower;
  // HertzPower: f = N^(2/3) - L^(2/3); |N - L| <= tol L is then |f| <~ (2/3) tol L^(2/3) (first order)
  const double target = hertz_power ? std::cbrt(load_N * load_N) : load_N;
  double last_carried = 0.0;
  auto residual = [&](double push) {
    last_carried = carried_load(push);
    if (!hertz_power) return last_carried - load_N;
    return std::cbrt(last_carried * last_carried) * (last_carried < 0.0 ? -1.0 : 1.0) - target;
  };
  const double tolerance_abs = hertz_power ? (2.0 / 3.0) * relative_tolerance * target : relative_tolerance * load_N;
  // bracket the push: the first guess is close, so start with a small step and expand
  const double scale = scale_m;
  double lo = -scale, hi = 0.25 * scale;
  double flo = residual(lo), fhi = residual(hi);
  for (int k = 0; k < 40 && fhi < 0.0; ++k) { lo = hi, flo = fhi; hi += scale * std::pow(2.0, k); fhi = residual(hi); }
  for (int k = 0; k < 40 && flo > 0.0; ++k) { hi = lo, fhi = flo; lo -= scale * std::pow(2.0, k); flo = residual(lo); }
  if (flo > 0.0 || fhi < 0.0) return result;  // NoBracket
  double f_root = 0.0;
  result.push_m = SolveIncreasingRoot(residual, lo, hi, flo, fhi, tolerance_abs, &result.iterations, &f_root);
  result.residual_N = hertz_power ? last_carried - load_N : f_root;
  result.status = std::fabs(result.residual_N) > 10.0 * relative_tolerance * load_N ? LoadControlStatus::NotConverged
                                                                                     : LoadControlStatus::Ok;
  return result;
}

}  // namespace conforma
