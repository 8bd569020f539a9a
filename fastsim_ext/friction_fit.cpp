// Friction-law identification from a creep curve (paper 002 §4) with Ceres (numeric-diff least squares).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <utility>
#include <sstream>
#include <string>

#include <ceres/ceres.h>

#include "conforma/error.hpp"
#include "conforma/friction_fit.hpp"

namespace conforma {

std::vector<CreepCurvePoint> ReadCreepCurveCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open creep curve file");
  std::vector<CreepCurvePoint> curve;
  std::string line;
  int number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), ';', ' ');
    std::istringstream row(line);
    CreepCurvePoint p;
    if (!(row >> p.creepage >> p.traction_coefficient)) {
      if (header_allowed) { header_allowed = false; continue; }
      throw InputError(path, number, "expected two numbers: creepage, F/N");
    }
    header_allowed = false;
    if (!std::isfinite(p.creepage) || !std::isfinite(p.traction_coefficient))
      throw InputError(path, number, "creepage and F/N must be finite");
    curve.push_back(p);
  }
  if (curve.empty()) throw InputError(path, 0, "no creep curve points");
  return curve;
}

namespace {

struct CreepCurveCost {
  const std::vector<CreepCurvePoint>* curve;
  const TwinDiscSetup* setup;
  FrictionLawKind kind;
  int law_parameters;
  bool fit_k;
  double fixed_k;
  std::vector<double> creepages;
  bool relative;

  bool operator()(double const* const* parameters, double* residuals) const {
    FrictionLaw law;
    law.kind = kind;
    for (int i = 0; i < law_parameters; ++i) law.parameters[i] = parameters[0][i];
    const double k = fit_k ? parameters[0][law_parameters] : fixed_k;
    try {
      const std::vector<double> model = TwinDiscCreepCurve(*setup, law, k, creepages);
      for (size_t i = 0; i < model.size(); ++i) {
        const double measured = (*curve)[i].traction_coefficient;
        residuals[i] = (model[i] - measured) / (relative ? std::max(std::abs(measured), 1e-12) : 1.0);
      }
    } catch (const InputError&) {
      return false;  // parameters outside the physical range: Ceres shortens the step
    }
    return true;
  }
};

}  // namespace

FrictionFitResult FitFrictionLaw(const std::vector<CreepCurvePoint>& curve, const TwinDiscSetup& setup,
                                 const FrictionFitOptions& options) {
  if (curve.empty()) throw InputError("FitFrictionLaw: empty creep curve");
  for (size_t i = 0; i < curve.size(); ++i)
    if (!std::isfinite(curve[i].creepage) || !std::isfinite(curve[i].traction_coefficient))
      throw InputError("FitFrictionLaw: creep curve point " + std::to_string(i) + " is not finite");
  setup.validate();
  options.initial_law.validate();
  require_positive(options.initial_slope_reduction, "initial_slope_reduction");

  const int np = options.initial_law.parameter_count();
  const int total = np + (options.fit_slope_reduction ? 1 : 0);
  std::vector<double> creepages;
  for (const CreepCurvePoint& p : curve) creepages.push_back(p.creepage);
  const CreepCurveCost evaluator{&curve, &setup, options.initial_law.kind, np, options.fit_slope_reduction,
                                 options.initial_slope_reduction, creepages, options.relative_residuals};
  std::vector<double> residuals(curve.size());
  auto cost_of = [&](const std::vector<double>& x) {
    const double* block = x.data();
    if (!evaluator(&block, residuals.data())) return std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (double r : residuals) sum += r * r;
    return 0.5 * sum;
  };

  // Stage 1 (paper 002 §4, the "spectrum of creep curves"): the initial guess with its rate / threshold parameters
  // (f1a beta, f1b gamma_c, f2 alpha and beta) scaled by 1/4 ... 4; the best starts go to stage 2.
  std::vector<double> x0(total);
  for (int i = 0; i < np; ++i) x0[i] = options.initial_law.parameters[i];
  if (options.fit_slope_reduction) x0[np] = options.initial_slope_reduction;
  std::vector<int> shape;
  switch (options.initial_law.kind) {
    case FrictionLawKind::F1aExponential: shape = {2}; break;
    case FrictionLawKind::F1bPiecewise: shape = {2}; break;
    case FrictionLawKind::F2: shape = {1, 3}; break;
    case FrictionLawKind::Constant: break;
  }
  const double factors[] = {0.25, 0.5, 1.0, 2.0, 4.0};
  std::vector<std::pair<double, std::vector<double>>> starts;
  const int combinations = static_cast<int>(std::pow(5.0, static_cast<double>(shape.size())));
  for (int c = 0; c < combinations; ++c) {
    std::vector<double> x = x0;
    int code = c;
    for (int index : shape) {
      x[index] *= factors[code % 5];
      code /= 5;
    }
    starts.push_back({cost_of(x), x});
  }
  std::stable_sort(starts.begin(), starts.end(),
                   [](const auto& l, const auto& r) { return l.first < r.first; });
  const int refined = std::max(1, std::min(options.refined_starts, static_cast<int>(starts.size())));

  // Stage 2: bounded Levenberg-Marquardt (numeric central differences) from each selected start; lowest cost wins.
  std::vector<double> best;
  double best_cost = std::numeric_limits<double>::infinity();
  ceres::Solver::Summary summary, best_summary;
  for (int s = 0; s < refined; ++s) {
    std::vector<double> x = starts[s].second;
    auto* functor = new CreepCurveCost(evaluator);
    ceres::NumericDiffOptions diff_options;
    diff_options.relative_step_size = 1e-5;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<CreepCurveCost, ceres::CENTRAL>(
        functor, ceres::TAKE_OWNERSHIP, diff_options);
    cost->AddParameterBlock(total);
    cost->SetNumResiduals(static_cast<int>(curve.size()));
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (int i = 0; i < total; ++i) problem.SetParameterLowerBound(x.data(), i, 0.0);
    if (options.initial_law.kind == FrictionLawKind::F1aExponential) problem.SetParameterUpperBound(x.data(), 1, 1.0);
    if (options.initial_law.kind == FrictionLawKind::F1bPiecewise) problem.SetParameterLowerBound(x.data(), 2, 1e-9);
    if (options.fit_slope_reduction) {
      problem.SetParameterLowerBound(x.data(), np, 1e-3);
      problem.SetParameterUpperBound(x.data(), np, 2.0);
    }
    ceres::Solver::Options solver_options;
    solver_options.max_num_iterations = options.max_iterations;
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.num_threads = 1;
    solver_options.function_tolerance = 1e-12;
    solver_options.parameter_tolerance = 1e-12;
    solver_options.gradient_tolerance = 1e-16;
    // Restarts reset the trust region, which the small kinks of the discrete creep curve (elements switching
    // between adhesion and slip) can collapse before the minimum is reached.
    double previous = std::numeric_limits<double>::infinity();
    for (int restart = 0; restart < 6; ++restart) {
      ceres::Solve(solver_options, &problem, &summary);
      if (!summary.IsSolutionUsable() || !(summary.final_cost < previous * (1.0 - 1e-3))) break;
      previous = summary.final_cost;
    }
    if (summary.IsSolutionUsable() && summary.final_cost < best_cost) {
      best_cost = summary.final_cost;
      best = x;
      best_summary = summary;
    }
  }
  if (best.empty()) best = starts[0].second;
  const std::vector<double>& x = best;
  summary = best_summary;

  FrictionFitResult result;
  result.converged = std::isfinite(best_cost);
  result.law.kind = options.initial_law.kind;
  for (int i = 0; i < np; ++i) result.law.parameters[i] = x[i];
  result.slope_reduction = options.fit_slope_reduction ? x[np] : options.initial_slope_reduction;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.report = summary.BriefReport();
  const std::vector<double> model = TwinDiscCreepCurve(setup, result.law, result.slope_reduction, creepages);
  double sum2 = 0.0, sum_abs = 0.0;
  size_t largest = 0;
  for (size_t i = 0; i < curve.size(); ++i) {
    const double e = model[i] - curve[i].traction_coefficient;
    sum2 += e * e;
    sum_abs += std::abs(e);
    if (curve[i].creepage > curve[largest].creepage) largest = i;
  }
  result.rms_error = std::sqrt(sum2 / curve.size());
  const double mu_ref = std::abs(curve[largest].traction_coefficient);
  result.relative_error_percent = mu_ref > 0.0 ? sum_abs / curve.size() / mu_ref * 100.0 : 0.0;  // paper 002 eq. 11
  return result;
}

}  // namespace conforma
