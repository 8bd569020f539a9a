// Friction-law identification from paper 000 Table 6 (conforma/validation/roller_rig_adhesion_fit.hpp,
// docs/physics-reference.md §7.5): Levenberg-Marquardt (Ceres, central differences) on transformed parameters
// (log mu_s, logit A, log B); the creep-curve peak by a log-spaced grid and Brent's minimisation (Boost.Math).
#include "conforma/validation/roller_rig_adhesion_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/Dense>
#include <boost/math/tools/minima.hpp>
#include <ceres/ceres.h>

#include "conforma/error.hpp"

namespace conforma {

namespace {

double Logistic(double t) { return 1.0 / (1.0 + std::exp(-t)); }
double Logit(double p) {
  p = std::clamp(p, 1e-9, 1.0 - 1e-9);
  return std::log(p / (1.0 - p));
}

struct Curve {
  const RollerRigLinearContact& linear;
  const Material& material;
  FrictionLaw law;
  double k, V;
  int elements;
  double operator()(double xi) const {
    return RollerRigTractionCoefficient(linear, material, law, k, xi, V, elements);
  }
};

// Peak of the creep curve on (xi_min, xi_max]: grid in log xi, then Brent's minimisation around the best grid point.
void CurvePeak(const Curve& curve, const RollerRigFitOptions& fit, double* xi_peak, double* mu_peak) {
  const double lo = std::log(1e-4), hi = std::log(fit.peak_search_max);
  const int n = fit.peak_grid_points;
  int best = 0;
  double best_mu = -1.0;
  for (int i = 0; i < n; ++i) {
    const double mu = curve(std::exp(lo + (hi - lo) * i / (n - 1)));
    if (mu > best_mu) best_mu = mu, best = i;
  }
  if (best == n - 1) {
    *xi_peak = fit.peak_search_max, *mu_peak = best_mu;
    return;
  }
  const double a = lo + (hi - lo) * std::max(best - 1, 0) / (n - 1), b = lo + (hi - lo) * (best + 1) / (n - 1);
  const auto [x, minus_f] = boost::math::tools::brent_find_minima(
      [&](double t) { return -curve(std::exp(t)); }, a, b, std::numeric_limits<double>::digits / 2);  // ~1e-8 in log xi
  const double f = -minus_f;
  *xi_peak = std::exp(x);
  *mu_peak = std::max({f, best_mu});
  if (best_mu > f) *xi_peak = std::exp(lo + (hi - lo) * best / (n - 1));
}

// Residuals of a fit as a Ceres cost (numeric central differences; the creep curve is a FASTSIM evaluation).
struct FitCost {
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> residuals;
  int parameters = 0;
  bool operator()(double const* const* q, double* r) const {
    const Eigen::VectorXd out = residuals(Eigen::Map<const Eigen::VectorXd>(q[0], parameters));
    for (Eigen::Index i = 0; i < out.size(); ++i) r[i] = out[i];
    return out.allFinite();
  }
};

// Levenberg-Marquardt (Ceres) on the unconstrained parameters q; returns the iteration count.
int LevenbergMarquardt(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals, Eigen::VectorXd* q,
                       int max_iterations, bool* converged) {
  const int n = static_cast<int>(q->size()), m = static_cast<int>(residuals(*q).size());
  ceres::NumericDiffOptions diff_options;
  diff_options.relative_step_size = 1e-6;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<FitCost, ceres::CENTRAL>(new FitCost{residuals, n},
                                                                                 ceres::TAKE_OWNERSHIP, diff_options);
  cost->AddParameterBlock(n);
  cost->SetNumResiduals(m);
  std::vector<double> x(q->data(), q->data() + n);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x.data());
  ceres::Solver::Options options;
  options.max_num_iterations = max_iterations;
  options.linear_solver_type = ceres::DENSE_QR;
  options.num_threads = 1;
  options.function_tolerance = 1e-8;  // relative cost decrease: the errors are then fixed to ~1e-4 %
  options.parameter_tolerance = 1e-10;
  options.gradient_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  *converged = summary.IsSolutionUsable() && summary.termination_type == ceres::CONVERGENCE;
  if (summary.IsSolutionUsable()) *q = Eigen::Map<const Eigen::VectorXd>(x.data(), n);
  return static_cast<int>(summary.iterations.size());
}

void Summarise(RollerRigFit* fit) {
  double sum = 0.0, worst = 0.0;
  for (const RollerRigTestModel& t : fit->tests) {
    sum += t.max_error_percent * t.max_error_percent + t.steady_error_percent * t.steady_error_percent;
    worst = std::max({worst, std::abs(t.max_error_percent), std::abs(t.steady_error_percent)});
  }
  fit->rms_error_percent = std::sqrt(sum / (2.0 * fit->tests.size()));
  fit->max_abs_error_percent = worst;
}

}  // namespace

FrictionLaw RollerRigLaw::ToFrictionLaw(double rolling_speed_m_per_s) const {
  // Polach's mu(w) = mu_s [A + (1 - A) e^(-B w)] with w = gamma V: paper 002 eq. 6 with beta = B V.
  return FrictionLaw::F1a(mu_static, sliding_ratio, decay_s_per_m * rolling_speed_m_per_s);
}

void RollerRigFitOptions::validate() const {
  require_positive(steady_creepage, "steady_creepage");
  if (!(peak_search_max > steady_creepage)) throw InputError("peak_search_max must exceed steady_creepage");
  if (peak_grid_points < 8) throw InputError("peak_grid_points must be >= 8");
  if (max_iterations < 1) throw InputError("max_iterations must be >= 1");
}

RollerRigTestModel EvaluateRollerRigTest(const RollerRigAdhesionTest& test, const RollerRigAdhesionOptions& rig,
                                         const RollerRigCurvatures& c, const RollerRigLaw& law,
                                         const RollerRigFitOptions& fit) {
  fit.validate();
  RollerRigTestModel m;
  m.measured = test;
  m.linear = RollerRigLinearTheory(c, test.wheel_load_kg * rig.gravity_m_per_s2, rig.material);
  m.rolling_speed_m_per_s = RollerRigRollingSpeed(test.reference_speed_rpm, rig.roller_radius_m);
  m.slope_reduction = test.initial_slope_N / m.linear.linear_slope_N;
  m.law = law;
  const Curve curve{m.linear, rig.material, law.ToFrictionLaw(m.rolling_speed_m_per_s), m.slope_reduction,
                    m.rolling_speed_m_per_s, rig.fastsim_elements};
  CurvePeak(curve, fit, &m.peak_creepage, &m.model_max);
  m.model_steady = curve(fit.steady_creepage);
  m.max_error_percent = (m.model_max - test.max_adhesion) / test.max_adhesion * 100.0;
  m.steady_error_percent = (m.model_steady - test.steady_adhesion) / test.steady_adhesion * 100.0;
  return m;
}

RollerRigFit FitRollerRigSharedLaw(const std::vector<RollerRigAdhesionTest>& tests, const RollerRigAdhesionOptions& rig,
                                   const RollerRigFitOptions& fit) {
  if (tests.empty()) throw InputError("FitRollerRigSharedLaw: no tests");
  fit.validate();
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  auto law_of = [](const Eigen::VectorXd& q) {
    RollerRigLaw l;
    l.mu_static = std::exp(q[0]), l.sliding_ratio = Logistic(q[1]), l.decay_s_per_m = std::exp(q[2]);
    return l;
  };
  auto residuals = [&](const Eigen::VectorXd& q) {
    Eigen::VectorXd r(2 * tests.size());
    const RollerRigLaw l = law_of(q);
    for (size_t i = 0; i < tests.size(); ++i) {
      const RollerRigTestModel m = EvaluateRollerRigTest(tests[i], rig, c, l, fit);
      r[2 * i] = m.max_error_percent / 100.0, r[2 * i + 1] = m.steady_error_percent / 100.0;
    }
    return r;
  };
  // Starts: mu_s 10 % above the largest measured maximum, A from the mean steady / max, B over two decades.
  double max_mu = 0.0, ratio = 0.0;
  for (const auto& t : tests) max_mu = std::max(max_mu, t.max_adhesion), ratio += t.steady_adhesion / t.max_adhesion;
  ratio /= tests.size();
  Eigen::VectorXd best;
  double best_cost = 1e300;
  for (double B : {0.03, 0.1, 0.3, 1.0, 3.0}) {
    Eigen::VectorXd q(3);
    q << std::log(1.1 * max_mu), Logit(0.9 * ratio), std::log(B);
    const double cost = residuals(q).squaredNorm();
    if (cost < best_cost) best_cost = cost, best = q;
  }
  RollerRigFit out;
  out.label = tests.front().condition;
  out.iterations = LevenbergMarquardt(residuals, &best, fit.max_iterations, &out.converged);
  out.law = law_of(best);
  for (const auto& t : tests) out.tests.push_back(EvaluateRollerRigTest(t, rig, c, out.law, fit));
  Summarise(&out);
  return out;
}

RollerRigFit FitRollerRigTestLaw(const RollerRigAdhesionTest& test, double decay_s_per_m,
                                 const RollerRigAdhesionOptions& rig, const RollerRigFitOptions& fit) {
  require_non_negative(decay_s_per_m, "decay_s_per_m");
  fit.validate();
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  auto law_of = [&](const Eigen::VectorXd& q) {
    RollerRigLaw l;
    l.mu_static = std::exp(q[0]), l.sliding_ratio = Logistic(q[1]), l.decay_s_per_m = decay_s_per_m;
    return l;
  };
  auto residuals = [&](const Eigen::VectorXd& q) {
    const RollerRigTestModel m = EvaluateRollerRigTest(test, rig, c, law_of(q), fit);
    Eigen::VectorXd r(2);
    r << m.max_error_percent / 100.0, m.steady_error_percent / 100.0;
    return r;
  };
  Eigen::VectorXd q(2);
  q << std::log(1.1 * test.max_adhesion), Logit(0.9 * test.steady_adhesion / test.max_adhesion);
  RollerRigFit out;
  out.label = "test " + std::to_string(test.test);
  out.iterations = LevenbergMarquardt(residuals, &q, fit.max_iterations, &out.converged);
  out.law = law_of(q);
  out.tests.push_back(EvaluateRollerRigTest(test, rig, c, out.law, fit));
  Summarise(&out);
  return out;
}

}  // namespace conforma
