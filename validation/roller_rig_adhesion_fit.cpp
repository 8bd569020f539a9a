// Friction-law identification from paper 000 Table 6 (conforma/validation/roller_rig_adhesion_fit.hpp,
// docs/physics-reference.md §7.5): Levenberg-Marquardt on transformed parameters (log mu_s, logit A, log B) with
// forward-difference Jacobians; the creep-curve peak by a log-spaced grid and golden-section refinement.
#include "conforma/validation/roller_rig_adhesion_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Dense>

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

// Peak of the creep curve on (xi_min, xi_max]: grid in log xi, then golden section around the best grid point.
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
  double a = lo + (hi - lo) * std::max(best - 1, 0) / (n - 1), b = lo + (hi - lo) * (best + 1) / (n - 1);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = curve(std::exp(x1)), f2 = curve(std::exp(x2));
  for (int it = 0; it < 40; ++it) {  // bracket 0.618^40 ~ 4e-9 of a grid cell in log xi
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = curve(std::exp(x1));
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = curve(std::exp(x2));
    }
  }
  const double x = 0.5 * (a + b), f = curve(std::exp(x));
  *xi_peak = std::exp(x);
  *mu_peak = std::max({f, best_mu});
  if (best_mu > f) *xi_peak = std::exp(lo + (hi - lo) * best / (n - 1));
}

// Levenberg-Marquardt on unconstrained parameters q: residuals r(q); returns the iteration count.
int LevenbergMarquardt(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals, Eigen::VectorXd* q,
                       int max_iterations, bool* converged) {
  Eigen::VectorXd r = residuals(*q);
  double cost = r.squaredNorm(), lambda = 1e-3;
  *converged = false;
  int it = 0;
  for (; it < max_iterations; ++it) {
    const int m = static_cast<int>(r.size()), n = static_cast<int>(q->size());
    Eigen::MatrixXd J(m, n);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd qj = *q;
      const double h = 1e-6 * std::max(1.0, std::abs(qj[j]));
      qj[j] += h;
      J.col(j) = (residuals(qj) - r) / h;
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool accepted = false;
    for (int tries = 0; tries < 12 && !accepted; ++tries) {
      Eigen::MatrixXd M = JtJ;
      M.diagonal() += lambda * (JtJ.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd step = -M.ldlt().solve(g);
      const Eigen::VectorXd qn = *q + step;
      const Eigen::VectorXd rn = residuals(qn);
      const double cn = rn.squaredNorm();
      if (std::isfinite(cn) && cn < cost) {
        const double gain = cost - cn;
        *q = qn, r = rn;
        const double old = cost;
        cost = cn;
        lambda = std::max(lambda * 0.3, 1e-9);
        accepted = true;
        // stop when the step or the relative cost decrease is negligible (the errors are then fixed to ~1e-4 %)
        if (step.norm() < 1e-7 || gain < 1e-8 * std::max(old, 1e-30)) *converged = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!accepted || cost < 1e-20) {
      *converged = true;  // no descent left from this point (a minimum to the step tolerance) or an exact fit
      break;
    }
    if (*converged) break;
  }
  return it + 1;
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
