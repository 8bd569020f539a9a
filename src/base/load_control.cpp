// The one load control (load_control.hpp).
#include "conforma/load_control.hpp"

#include <cmath>

#include "conforma/root_finding.hpp"

namespace conforma {

namespace {
// The Hertzian coordinate of a carried load, sign(F) |F|^(2/3): linear in the push for a Hertzian contact
// (F ~ delta^1.5, docs/physics-reference.md §1.2).
double HertzianCoordinate(double carried) { return std::cbrt(carried * carried) * (carried < 0.0 ? -1.0 : 1.0); }
}  // namespace

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
  const double target = hertz_power ? HertzianCoordinate(load_N) : load_N;
  double last_carried = 0.0;
  auto residual = [&](double push) {
    last_carried = carried_load(push);
    if (!hertz_power) return last_carried - load_N;
    return HertzianCoordinate(last_carried) - target;
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

LoadControlResult SolveLoadControlFrom(const std::function<double(double)>& carried_load, double carried_at_zero_N,
                                       double load_N, double first_step_m, double max_push_m,
                                       double relative_tolerance) {
  LoadControlResult result;
  const double tolerance_abs = relative_tolerance * load_N;
  const double f0 = carried_at_zero_N - load_N;
  if (std::fabs(f0) <= tolerance_abs) {
    result.status = LoadControlStatus::Ok;
    result.residual_N = f0;
    return result;
  }
  // The next push is chosen on the Hertzian coordinate h = sign(F) |F|^(2/3) - load^(2/3), linear in the push for a
  // Hertzian contact (F ~ delta^1.5; LoadResponse::HertzPower of SolveLoadControl): a secant or false position
  // through an evaluation far from the load (a flange, 25-65 % over it at the candidates' push-down) lands ~1e-5
  // from it where the straight line through F landed ~1e-4 (one evaluation more). Convergence is judged on the
  // load itself: |F - load| <= tolerance. h has the sign of F - load.
  const double target = HertzianCoordinate(load_N);
  double last_residual = 0.0;  // F - load at the last evaluation
  auto evaluate = [&](double push) {
    const double carried = carried_load(push);
    last_residual = carried - load_N;
    return HertzianCoordinate(carried) - target;
  };
  // towards the load: a larger push where too little is carried
  double step = std::copysign(std::max(std::fabs(first_step_m), 1e-12), -f0);
  double a = 0.0, ha = HertzianCoordinate(carried_at_zero_N) - target, b = step, hb = evaluate(b);
  int evaluations = 1;
  // Until the carried load crosses the load or comes within the tolerance: the secant through the last two
  // evaluations where it points on the same way, at most to where the doubled step would go; else the step doubled.
  // (The first step is good to ~1e-3 of itself, so a step that stops short typically leaves ~1e-6 of the load: the
  // secant lands on the load where doubling overshot by the whole step and cost a bracket step more.)
  int secant_steps = 0;
  while ((ha < 0.0) == (hb < 0.0) && hb != 0.0 && std::fabs(last_residual) > tolerance_abs) {
    step *= 2.0;
    double next = b + step;
    const double secant = b - hb * (b - a) / (hb - ha);
    const bool towards = step > 0.0 ? (secant > b && secant < next) : (secant < b && secant > next);
    if (towards && secant_steps < 8) next = secant, ++secant_steps;  // (bounded: the doubling always progresses)
    if (std::fabs(next) > max_push_m) return result;  // NoBracket
    a = b, ha = hb;
    b = next;
    hb = evaluate(b);
    ++evaluations;
  }
  if (std::fabs(last_residual) <= tolerance_abs) {  // the step landed on the load (the last evaluation is at b)
    result.status = LoadControlStatus::Ok;
    result.push_m = b, result.residual_N = last_residual, result.iterations = evaluations;
    return result;
  }
  const bool increasing_bracket = b > a;
  const double low = increasing_bracket ? a : b, high = increasing_bracket ? b : a;
  const double h_low = increasing_bracket ? ha : hb, h_high = increasing_bracket ? hb : ha;
  if (!(h_low < 0.0 && h_high > 0.0)) return result;  // the carried load decreases with the push here: NoBracket
  // (0 where the load is met: the root finder stops there, its own tolerance 0)
  auto h_or_met = [&](double push) {
    const double h = evaluate(push);
    return std::fabs(last_residual) <= tolerance_abs ? 0.0 : h;
  };
  double h_root = 0.0;
  int root_iterations = 0;
  result.push_m = SolveIncreasingRoot(h_or_met, low, high, h_low, h_high, 0.0, &root_iterations, &h_root);
  result.iterations = evaluations + root_iterations;
  result.residual_N = last_residual;
  result.status =
      std::fabs(last_residual) > 10.0 * tolerance_abs ? LoadControlStatus::NotConverged : LoadControlStatus::Ok;
  return result;
}

}  // namespace conforma
