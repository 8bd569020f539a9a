// Friction-law identification from a creep curve (paper 002 §4) with Ceres (numeric-diff least squares).
#include <algorithm>
#include <cmath>
#include <fstream>
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

  bool operator()(double const* const* parameters, double* residuals) const {
    FrictionLaw law;
    law.kind = kind;
    for (int i = 0; i < law_parameters; ++i) law.parameters[i] = parameters[0][i];
    const double k = fit_k ? parameters[0][law_parameters] : fixed_k;
    try {
      const std::vector<double> model = TwinDiscCreepCurve(*setup, law, k, creepages);
      for (size_t i = 0; i < model.size(); ++i) residuals[i] = model[i] - (*curve)[i].traction_coefficient;
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
  std::vector<double> x(total);
  for (int i = 0; i < np; ++i) x[i] = options.initial_law.parameters[i];
  if (options.fit_slope_reduction) x[np] = options.initial_slope_reduction;

  auto* functor = new CreepCurveCost{&curve, &setup, options.initial_law.kind, np, options.fit_slope_reduction,
                                     options.initial_slope_reduction, {}};
  for (const CreepCurvePoint& p : curve) functor->creepages.push_back(p.creepage);
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
  solver_options.function_tolerance = 1e-14;
  solver_options.parameter_tolerance = 1e-12;
  solver_options.gradient_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);

  FrictionFitResult result;
  result.converged = summary.IsSolutionUsable();
  result.law.kind = options.initial_law.kind;
  for (int i = 0; i < np; ++i) result.law.parameters[i] = x[i];
  result.slope_reduction = options.fit_slope_reduction ? x[np] : options.initial_slope_reduction;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.report = summary.BriefReport();
  std::vector<double> creepages;
  for (const CreepCurvePoint& p : curve) creepages.push_back(p.creepage);
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
