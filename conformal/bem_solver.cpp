// Reference BEM normal contact solver: Polonsky & Keer (1999) constrained conjugate gradient
// (docs/physics-reference.md §10.3) with prescribed force or prescribed approach.
//
// Curved patches: with w_j = cos(alpha_j) the problem g = h - delta w + C p >= 0, p >= 0, g p = 0 with
// sum w p dA = N is rewritten in q = w p as g/w = h/w - delta + (W^-1 C W^-1) q, sum q dA = N, which is the
// standard flat problem (symmetric operator, uniform approach), so the algorithm of §10.3 applies unchanged.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bem_operator.hpp"
#include "conforma/bem_reference.hpp"
#include "conforma/error.hpp"

namespace conforma {
namespace {

using bem_detail::InfluenceOperator;

// The flat problem in the scaled unknown q = w p.
class ScaledProblem {
 public:
  ScaledProblem(InfluenceOperator& op, const Eigen::VectorXd& weight, const Eigen::VectorXd& gap)
      : op_(op), weight_(weight), gap_(gap.cwiseQuotient(weight)) {}
  void Apply(const Eigen::VectorXd& q, Eigen::VectorXd& out) {
    scratch_ = q.cwiseQuotient(weight_);
    op_.Apply(scratch_, out);
    out = out.cwiseQuotient(weight_);
  }
  // z = W P^-1 W g with P^-1 the circulant inverse of A_nn: a preconditioner of W^-1 C W^-1 (C ~ A_nn for small
  // alpha differences); the identity without an FFT operator.
  bool has_preconditioner() const { return op_.has_preconditioner(); }
  void Precondition(const Eigen::VectorXd& g, Eigen::VectorXd& z) {
    scratch_ = g.cwiseProduct(weight_);
    op_.ApplyPreconditioner(scratch_, z);
    z = z.cwiseProduct(weight_);
  }
  const Eigen::VectorXd& gap() const { return gap_; }  // h / w
  const Eigen::VectorXd& weight() const { return weight_; }

 private:
  InfluenceOperator& op_;
  Eigen::VectorXd weight_, gap_, scratch_;
};

struct CoreSolution {
  Eigen::VectorXd q;
  double approach = 0.0;
  int iterations = 0;
  double residual = 0.0;  // relative pressure change of the last iteration
  bool converged = false;
};

// §10.3 with force constraint: sum q dA = force.
CoreSolution SolveForForce(ScaledProblem& problem, double force, double area, double tolerance,
                           int max_iterations, const Eigen::VectorXd* warm_start) {
  const long n = problem.gap().size();
  CoreSolution sol;
  if (warm_start && warm_start->size() == n && warm_start->sum() > 0.0)
    sol.q = *warm_start * (force / (area * warm_start->sum()));
  else
    sol.q = Eigen::VectorXd::Constant(n, force / (area * static_cast<double>(n)));
  Eigen::VectorXd g, t = Eigen::VectorXd::Zero(n), r, q_old, z, masked(n);
  double g_old = 1.0;
  bool conjugate = false;
  const bool preconditioned = problem.has_preconditioner();
  for (int it = 1; it <= max_iterations; ++it) {
    sol.iterations = it;
    problem.Apply(sol.q, g);
    g += problem.gap();
    long contact = 0;
    double g_mean = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) { g_mean += g[k]; ++contact; }
    g_mean /= static_cast<double>(contact);
    g.array() -= g_mean;
    // preconditioned residual, projected onto the force constraint (zero mean on the active set)
    if (preconditioned) {
      for (long k = 0; k < n; ++k) masked[k] = sol.q[k] > 0.0 ? g[k] : 0.0;
      problem.Precondition(masked, z);
      double z_mean = 0.0;
      for (long k = 0; k < n; ++k)
        if (sol.q[k] > 0.0) z_mean += z[k];
      z.array() -= z_mean / static_cast<double>(contact);
    } else {
      z = g;
    }
    double g_norm = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) g_norm += g[k] * z[k];
    const double beta = conjugate ? g_norm / g_old : 0.0;
    for (long k = 0; k < n; ++k) t[k] = sol.q[k] > 0.0 ? z[k] + beta * t[k] : 0.0;
    g_old = g_norm;
    problem.Apply(t, r);
    double r_mean = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) r_mean += r[k];
    r_mean /= static_cast<double>(contact);
    double num = 0.0, den = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) { num += g[k] * t[k]; den += (r[k] - r_mean) * t[k]; }
    const double tau = den > 0.0 ? num / den : 0.0;
    q_old = sol.q;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) sol.q[k] = std::max(sol.q[k] - tau * t[k], 0.0);
    bool overlap = false;  // elements out of contact that penetrate: put them back (Polonsky-Keer step)
    for (long k = 0; k < n; ++k)
      if (q_old[k] <= 0.0 && g[k] < 0.0) { sol.q[k] = -tau * g[k]; overlap = true; }
    conjugate = !overlap;
    const double total = sol.q.sum();
    if (!(total > 0.0)) {  // degenerate step: restart from the previous iterate
      sol.q = q_old;
      conjugate = false;
      continue;
    }
    sol.q *= force / (area * total);
    const double change = (sol.q - q_old).cwiseAbs().sum() / sol.q.sum();
    sol.residual = change;
    if (change < tolerance) { sol.converged = true; break; }
  }
  problem.Apply(sol.q, g);
  g += problem.gap();
  double mean = 0.0;
  long contact = 0;
  for (long k = 0; k < n; ++k)
    if (sol.q[k] > 0.0) { mean += g[k]; ++contact; }
  sol.approach = contact > 0 ? mean / static_cast<double>(contact) : 0.0;
  return sol;
}

// §10.3 "prescribed delta": the same active-set CG on g = C q + h - delta without the force scaling.
CoreSolution SolveForApproach(ScaledProblem& problem, double approach, double self_coefficient,
                              double tolerance, int max_iterations) {
  const long n = problem.gap().size();
  CoreSolution sol;
  sol.approach = approach;
  // Start: local (Winkler) estimate q = interpenetration / self coefficient.
  sol.q = ((approach - problem.gap().array()).max(0.0) * problem.weight().array().square() / self_coefficient)
              .matrix();
  if (!(sol.q.sum() > 0.0)) { sol.converged = true; return sol; }
  Eigen::VectorXd g, t = Eigen::VectorXd::Zero(n), r, q_old;
  {
    // Better start (§10.4): the Hertz shape. For h = paraboloid the contact is {h - h_min < (delta - h_min) / 2}
    // and p ~ sqrt((delta - h_min) / 2 - (h - h_min)) (Johnson 1985 §4.2); the amplitude is the least-squares fit
    // of C q = delta - h on that set (one operator application).
    const double h_min = problem.gap().minCoeff();
    const double half_depth = 0.5 * (approach - h_min);
    Eigen::VectorXd shape = (half_depth - (problem.gap().array() - h_min)).max(0.0).sqrt().matrix();
    if (half_depth > 0.0 && shape.sum() > 0.0) {
      problem.Apply(shape, g);
      double num = 0.0, den = 0.0;
      for (long k = 0; k < n; ++k)
        if (shape[k] > 0.0) { num += g[k] * (approach - problem.gap()[k]); den += g[k] * g[k]; }
      if (num > 0.0 && den > 0.0) sol.q = shape * (num / den);
    }
  }
  double g_old = 1.0;
  bool conjugate = false;
  const bool preconditioned = problem.has_preconditioner();
  Eigen::VectorXd z, masked(n);
  for (int it = 1; it <= max_iterations; ++it) {
    sol.iterations = it;
    problem.Apply(sol.q, g);
    g += problem.gap();
    g.array() -= approach;
    // preconditioned residual on the active set, z = P_I M^-1 P_I g (Vollebregt 2014: FFT-based preconditioner)
    if (preconditioned) {
      for (long k = 0; k < n; ++k) masked[k] = sol.q[k] > 0.0 ? g[k] : 0.0;
      problem.Precondition(masked, z);
    } else {
      z = g;
    }
    double g_norm = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) g_norm += g[k] * z[k];
    const double beta = conjugate ? g_norm / g_old : 0.0;
    for (long k = 0; k < n; ++k) t[k] = sol.q[k] > 0.0 ? z[k] + beta * t[k] : 0.0;
    g_old = g_norm;
    problem.Apply(t, r);
    double num = 0.0, den = 0.0;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) { num += g[k] * t[k]; den += r[k] * t[k]; }
    const double tau = den > 0.0 ? num / den : 0.0;
    q_old = sol.q;
    for (long k = 0; k < n; ++k)
      if (sol.q[k] > 0.0) sol.q[k] = std::max(sol.q[k] - tau * t[k], 0.0);
    bool overlap = false;
    for (long k = 0; k < n; ++k)
      if (q_old[k] <= 0.0 && g[k] < 0.0) {
        // tau may be 0 on the first step when the active set is exact; fall back to the local estimate
        sol.q[k] = tau > 0.0 ? -tau * g[k] : -g[k] * problem.weight()[k] * problem.weight()[k] / self_coefficient;
        overlap = true;
      }
    conjugate = !overlap;
    const double total = sol.q.sum();
    if (!(total > 0.0)) break;  // the approach does not close the gap anywhere once elasticity is counted
    const double change = (sol.q - q_old).cwiseAbs().sum() / total;
    sol.residual = change;
    if (change < tolerance) { sol.converged = true; break; }
  }
  return sol;
}

void ValidateOptions(const BemOptions& o) {
  if (o.control == BemLoadControl::NormalForce) require_non_negative(o.normal_force_N, "BemOptions.normal_force_N");
  else require_finite(o.approach_m, "BemOptions.approach_m");
  require_positive(o.tolerance, "BemOptions.tolerance");
  if (o.max_iterations < 1) throw InputError("BemOptions.max_iterations must be >= 1");
  if (o.max_elements < 1) throw InputError("BemOptions.max_elements must be >= 1");
}

}  // namespace

namespace bem_detail {

void CheckGridBudget(double nx, double ns, double dx_m, double ds_m, long max_elements) {
  const double elements = nx * ns;
  if (elements <= static_cast<double>(max_elements)) return;
  char text[512];
  std::snprintf(text, sizeof text,
                "reference BEM grid of %.0f x %.0f = %.0f elements (element size %.4g mm along x, %.4g mm along s) "
                "exceeds the memory budget of %ld elements (BemOptions.max_elements, WheelContactOptions::"
                "exact_max_elements, ~1 kB per element): increase the element size (WheelContactOptions::"
                "exact_element_size_m, BemOptions.element_dx_m / element_ds_m; on the command line: "
                "--exact-element-mm) or the budget",
                nx, ns, elements, dx_m * 1e3, ds_m * 1e3, max_elements);
  throw InputError(text);
}

}  // namespace bem_detail

const char* to_string(BemStatus status) {
  switch (status) {
    case BemStatus::Converged: return "converged";
    case BemStatus::NotConverged: return "not_converged";
    case BemStatus::NoContact: return "no_contact";
  }
  return "unknown";
}

const char* to_string(BemInfluence influence) {
  switch (influence) {
    case BemInfluence::HalfSpace: return "half-space";
    case BemInfluence::Blanco: return "blanco";
  }
  return "unknown";
}

void BemGrid::validate() const {
  if (nx < 1 || ns < 1) throw InputError("BemGrid: nx and ns must be >= 1");
  require_positive(dx_m, "BemGrid.dx_m");
  require_positive(ds_m, "BemGrid.ds_m");
  require_finite(x_first_m, "BemGrid.x_first_m");
  require_finite(s_first_m, "BemGrid.s_first_m");
  if (gap_m.rows() != nx || gap_m.cols() != ns)
    throw InputError("BemGrid.gap_m must be nx x ns (" + std::to_string(nx) + " x " + std::to_string(ns) + ")");
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nx; ++i)
      if (!std::isfinite(gap_m(i, j)))
        throw InputError("BemGrid.gap_m(" + std::to_string(i) + ", " + std::to_string(j) + ") is not finite");
  if (!alpha_rad.empty()) {
    if (alpha_rad.size() != static_cast<size_t>(ns)) throw InputError("BemGrid.alpha_rad must be empty or have ns entries");
    for (int j = 0; j < ns; ++j) {
      require_finite(alpha(j), "BemGrid.alpha_rad");
      if (std::fabs(alpha(j)) >= 0.5 * 3.14159265358979323846)
        throw InputError("BemGrid.alpha_rad[" + std::to_string(j) + "]: |alpha| must be below 90 degrees");
    }
  }
}

BemGrid QuadraticGapGrid(double A_per_m, double B_per_m, int nx, int ns, double half_x_m, double half_s_m) {
  require_finite(A_per_m, "A");
  require_finite(B_per_m, "B");
  require_positive(half_x_m, "half_x_m");
  require_positive(half_s_m, "half_s_m");
  if (nx < 1 || ns < 1) throw InputError("QuadraticGapGrid: nx and ns must be >= 1");
  BemGrid grid;
  grid.nx = nx;
  grid.ns = ns;
  grid.dx_m = 2.0 * half_x_m / nx;
  grid.ds_m = 2.0 * half_s_m / ns;
  grid.x_first_m = -half_x_m + 0.5 * grid.dx_m;
  grid.s_first_m = -half_s_m + 0.5 * grid.ds_m;
  grid.gap_m.resize(nx, ns);
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = grid.x_centre_m(i), s = grid.s_centre_m(j);
      grid.gap_m(i, j) = A_per_m * x * x + B_per_m * s * s;
    }
  return grid;
}

BemResult SolveBemNormal(const BemGrid& grid, const Material& material, const BemOptions& options) {
  grid.validate();
  ValidateOptions(options);
  bem_detail::CheckGridBudget(grid.nx, grid.ns, grid.dx_m, grid.ds_m, options.max_elements);
  const ElasticConstants elastic = CombinedElasticConstants(material);
  BemResult result;
  result.grid = grid;
  const long n = static_cast<long>(grid.nx) * grid.ns;
  result.pressure_Pa = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  result.deformed_gap_m = grid.gap_m;
  const bool force_control = options.control == BemLoadControl::NormalForce;
  if (force_control && options.normal_force_N == 0.0) {
    result.status = BemStatus::NoContact;
    return result;
  }

  Eigen::VectorXd weight(n), gap(n);
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      weight[i + static_cast<long>(grid.nx) * j] = std::cos(grid.alpha(j));
      gap[i + static_cast<long>(grid.nx) * j] = grid.gap_m(i, j);
    }
  InfluenceOperator op(grid, elastic, options.influence, options.coupling, options.use_fft);
  ScaledProblem problem(op, weight, gap);
  const double area = grid.element_area_m2();

  CoreSolution sol;
  if (force_control) {
    double target = options.normal_force_N;  // along the reference normal (sum q dA)
    sol = SolveForForce(problem, target, area, options.tolerance, options.max_iterations, nullptr);
    if (options.force_measure == BemForceMeasure::CurvedSurface && !grid.alpha_rad.empty()) {
      // Fixed point on the ratio fn_tilde / fn_bar, which depends only weakly on the load.
      for (int outer = 0; outer < 30; ++outer) {
        const double fn_bar = sol.q.sum() * area;
        const double fn_tilde = sol.q.cwiseQuotient(weight).sum() * area;
        if (std::fabs(fn_tilde - options.normal_force_N) <= 1e-10 * options.normal_force_N) break;
        target = options.normal_force_N * fn_bar / fn_tilde;
        const Eigen::VectorXd warm = sol.q;
        const int previous = sol.iterations;
        sol = SolveForForce(problem, target, area, options.tolerance, options.max_iterations, &warm);
        sol.iterations += previous;
      }
    }
  } else {
    sol = SolveForApproach(problem, options.approach_m, op.self_coefficient(), options.tolerance,
                           options.max_iterations);
  }

  const Eigen::VectorXd pressure = sol.q.cwiseQuotient(weight);
  Eigen::VectorXd displacement;
  op.Apply(pressure, displacement);
  const Eigen::VectorXd deformed_gap = gap - sol.approach * weight + displacement;
  result.approach_m = sol.approach;
  result.iterations = sol.iterations;
  result.residual = sol.residual;
  bem_detail::SummariseBem(pressure, deformed_gap, result);
  if (result.contact_elements == 0) result.status = BemStatus::NoContact;
  else result.status = sol.converged ? BemStatus::Converged : BemStatus::NotConverged;
  return result;
}

}  // namespace conforma
