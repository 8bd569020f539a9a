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
#include "conforma/validation/roller_rig_polach.hpp"

namespace conforma {

namespace {

double Logistic(double t) { return 1.0 / (1.0 + std::exp(-t)); }
double Logit(double p) {
  p = std::clamp(p, 1e-9, 1.0 - 1e-9);
  return std::log(p / (1.0 - p));
}

bool IsPolach(RollerRigLawVariant v) {
  return v == RollerRigLawVariant::PolachAnalytic || v == RollerRigLawVariant::PolachExtended;
}

// The creep curve -F_x/N(xi) of a test: FASTSIM with the law of the local slip, or Polach's analytic model with the
// law at the rigid slip velocity xi V (Polach 2005) and (k_A + k_S)/2 = k.
struct Curve {
  const RollerRigLinearContact& linear;
  const Material& material;
  FrictionLaw law;
  double k, V;
  int elements;
  RollerRigLawVariant variant = RollerRigLawVariant::SlipVelocity;
  double slip_area_ratio = 1.0;  // k_S / k_A
  double operator()(double xi) const {
    if (IsPolach(variant)) {
      // k_S / k_A kept off 0 (a logistic parameter far out underflows to 0; the curve is continuous there)
      const double r = variant == RollerRigLawVariant::PolachExtended ? std::clamp(slip_area_ratio, 1e-9, 1.0) : 1.0;
      const double k_a = 2.0 * k / (1.0 + r), k_s = r * k_a;
      return PolachTractionCoefficient(linear.linear_slope_N, linear.normal_force_N, k_a, k_s, law(xi), xi);
    }
    return RollerRigTractionCoefficient(linear, material, law, k, xi, V, elements);
  }
};

// Steady creepage as a fitted parameter: xi_s = exp(log 0.02 + (log 0.5 - log 0.02) logistic(t)), in [0.02, 0.5].
constexpr double kSteadyMin = 0.02, kSteadyMax = 0.5;

double SteadyCreepageOf(double t) {
  return std::exp(std::log(kSteadyMin) + (std::log(kSteadyMax) - std::log(kSteadyMin)) * Logistic(t));
}
double SteadyParameterOf(double xi_s) {
  return Logit((std::log(xi_s) - std::log(kSteadyMin)) / (std::log(kSteadyMax) - std::log(kSteadyMin)));
}

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
  fit->data_points = static_cast<int>(2 * fit->tests.size());
  fit->within_5_percent = 0;
  for (const RollerRigTestModel& t : fit->tests)
    fit->within_5_percent += (std::abs(t.max_error_percent) <= 5.0) + (std::abs(t.steady_error_percent) <= 5.0);
}

}  // namespace

const char* to_string(RollerRigLawVariant v) {
  switch (v) {
    case RollerRigLawVariant::SlipVelocity: return "slip_velocity";
    case RollerRigLawVariant::CurtiusKniffler: return "curtius_kniffler";
    case RollerRigLawVariant::SpeedPower: return "speed_power";
    case RollerRigLawVariant::SpeedHyperbolic: return "speed_hyperbolic";
    case RollerRigLawVariant::PolachAnalytic: return "polach_analytic";
    case RollerRigLawVariant::PolachExtended: return "polach_extended";
  }
  return "?";
}

std::vector<RollerRigLawVariant> AllRollerRigLawVariants() {
  return {RollerRigLawVariant::SlipVelocity,    RollerRigLawVariant::CurtiusKniffler,
          RollerRigLawVariant::SpeedPower,      RollerRigLawVariant::SpeedHyperbolic,
          RollerRigLawVariant::PolachAnalytic,  RollerRigLawVariant::PolachExtended};
}

RollerRigLawVariant ParseRollerRigLawVariant(const std::string& name) {
  for (RollerRigLawVariant v : AllRollerRigLawVariants())
    if (name == to_string(v)) return v;
  throw InputError("roller-rig law '" + name +
                   "': expected slip_velocity, curtius_kniffler, speed_power, speed_hyperbolic, polach_analytic or "
                   "polach_extended");
}

int RollerRigLawParameterCount(RollerRigLawVariant v) {
  switch (v) {
    case RollerRigLawVariant::SpeedPower:
    case RollerRigLawVariant::SpeedHyperbolic:
    case RollerRigLawVariant::PolachExtended: return 4;
    default: return 3;
  }
}

double RollerRigLaw::StaticLevel(double V) const {
  require_positive(V, "rolling speed");
  const double Vr = kRollerRigReferenceSpeed;
  switch (variant) {
    case RollerRigLawVariant::CurtiusKniffler: {
      // Curtius-Kniffler adhesion limit, mu = 0.161 + 7.5 / (v + 44), v in km/h (docs/physics-reference.md §7.5)
      auto g = [](double speed) { return 0.161 + 7.5 / (3.6 * speed + 44.0); };
      return mu_static * g(V) / g(Vr);
    }
    case RollerRigLawVariant::SpeedPower: return mu_static * std::pow(V / Vr, -speed_exponent);
    case RollerRigLawVariant::SpeedHyperbolic:
      require_positive(speed_scale_m_per_s, "speed_scale_m_per_s");
      return mu_static * (Vr + speed_scale_m_per_s) / (V + speed_scale_m_per_s);
    default: return mu_static;
  }
}

FrictionLaw RollerRigLaw::ToFrictionLaw(double rolling_speed_m_per_s) const {
  // Polach's mu(w) = mu_s [A + (1 - A) e^(-B w)] with w = gamma V: paper 002 eq. 6 with beta = B V.
  return FrictionLaw::F1a(StaticLevel(rolling_speed_m_per_s), sliding_ratio, decay_s_per_m * rolling_speed_m_per_s);
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
  const Curve curve{m.linear,        rig.material,          law.ToFrictionLaw(m.rolling_speed_m_per_s),
                    m.slope_reduction, m.rolling_speed_m_per_s, rig.fastsim_elements,
                    law.variant,       law.slip_area_ratio};
  RollerRigFitOptions search = fit;
  if (fit.peak_before_steady) search.peak_search_max = fit.steady_creepage;  // the largest value up to xi_s
  CurvePeak(curve, search, &m.peak_creepage, &m.model_max);
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
  const RollerRigLawVariant variant = fit.variant;
  const int law_parameters = RollerRigLawParameterCount(variant);
  const int n = law_parameters + (fit.fit_steady_creepage ? 1 : 0);
  // q = (log mu_s, logit A, log B [, n | log V_0 | logit k_S/k_A] [, steady parameter])
  auto law_of = [&](const Eigen::VectorXd& q) {
    RollerRigLaw l;
    l.variant = variant;
    l.mu_static = std::exp(q[0]), l.sliding_ratio = Logistic(q[1]), l.decay_s_per_m = std::exp(q[2]);
    if (variant == RollerRigLawVariant::SpeedPower) l.speed_exponent = q[3];
    if (variant == RollerRigLawVariant::SpeedHyperbolic) l.speed_scale_m_per_s = std::exp(q[3]);
    if (variant == RollerRigLawVariant::PolachExtended) l.slip_area_ratio = Logistic(q[3]);
    return l;
  };
  auto options_of = [&](const Eigen::VectorXd& q) {
    RollerRigFitOptions o = fit;
    if (fit.fit_steady_creepage) {
      o.steady_creepage = SteadyCreepageOf(q[law_parameters]);
      o.peak_search_max = std::max(fit.peak_search_max, 1.5 * o.steady_creepage);
    }
    return o;
  };
  auto residuals = [&](const Eigen::VectorXd& q) {
    Eigen::VectorXd r(2 * tests.size());
    const RollerRigLaw l = law_of(q);
    const RollerRigFitOptions o = options_of(q);
    for (size_t i = 0; i < tests.size(); ++i) {
      const RollerRigTestModel m = EvaluateRollerRigTest(tests[i], rig, c, l, o);
      r[2 * i] = m.max_error_percent / 100.0, r[2 * i + 1] = m.steady_error_percent / 100.0;
    }
    return r;
  };
  // Starts: mu_s 10 % above the largest measured maximum, A from the mean steady / max, B over two decades; the
  // extra parameter at two values (no speed dependence / a moderate one; k_S/k_A 0.5 and 0.15).
  double max_mu = 0.0, ratio = 0.0;
  for (const auto& t : tests) max_mu = std::max(max_mu, t.max_adhesion), ratio += t.steady_adhesion / t.max_adhesion;
  ratio /= tests.size();
  std::vector<double> extra_starts{0.0};
  if (variant == RollerRigLawVariant::SpeedPower) extra_starts = {0.0, 0.5};
  if (variant == RollerRigLawVariant::SpeedHyperbolic) extra_starts = {std::log(30.0), std::log(5.0)};
  if (variant == RollerRigLawVariant::PolachExtended) extra_starts = {Logit(0.5), Logit(0.15)};
  Eigen::VectorXd best;
  double best_cost = 1e300;
  for (double extra : extra_starts)
    for (double B : {0.03, 0.1, 0.3, 1.0, 3.0}) {
      Eigen::VectorXd q(n);
      q.head(3) << std::log(1.1 * max_mu), Logit(0.9 * ratio), std::log(B);
      if (law_parameters == 4) q[3] = extra;
      if (fit.fit_steady_creepage) q[law_parameters] = SteadyParameterOf(fit.steady_creepage);
      const double cost = residuals(q).squaredNorm();
      if (cost < best_cost) best_cost = cost, best = q;
    }
  auto parameters_of = [&](const RollerRigLaw& l) {
    Eigen::VectorXd q(n);
    q.head(3) << std::log(l.mu_static), Logit(l.sliding_ratio), std::log(std::max(l.decay_s_per_m, 1e-6));
    const bool same = l.variant == variant;
    if (variant == RollerRigLawVariant::SpeedPower) q[3] = same ? l.speed_exponent : 0.0;
    if (variant == RollerRigLawVariant::SpeedHyperbolic) q[3] = std::log(same ? l.speed_scale_m_per_s : 1000.0);
    if (variant == RollerRigLawVariant::PolachExtended) q[3] = Logit(same ? l.slip_area_ratio : 0.9);
    if (fit.fit_steady_creepage) q[law_parameters] = SteadyParameterOf(fit.steady_creepage);
    return q;
  };
  std::vector<Eigen::VectorXd> lm_starts;
  if (fit.lm_from_grid || fit.extra_starts.empty()) lm_starts.push_back(best);
  for (const RollerRigLaw& l : fit.extra_starts) lm_starts.push_back(parameters_of(l));
  RollerRigFit out;
  out.label = tests.front().condition;
  double out_cost = 1e300;
  for (Eigen::VectorXd q : lm_starts) {
    bool converged = false;
    const int iterations = LevenbergMarquardt(residuals, &q, fit.max_iterations, &converged);
    const double cost = lm_starts.size() == 1 ? 0.0 : residuals(q).squaredNorm();
    if (cost < out_cost) out_cost = cost, best = q, out.iterations = iterations, out.converged = converged;
  }
  out.law = law_of(best);
  const RollerRigFitOptions o = options_of(best);
  for (const auto& t : tests) out.tests.push_back(EvaluateRollerRigTest(t, rig, c, out.law, o));
  Summarise(&out);
  out.steady_creepage = o.steady_creepage;
  out.parameters = n;
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
  out.steady_creepage = fit.steady_creepage;
  out.parameters = 2;
  return out;
}

}  // namespace conforma
