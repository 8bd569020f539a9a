// Kalker's exact steady-rolling tangential problem on the BEM grid (exact_tangential.hpp; docs/physics-reference.md
// §14): line Gauss-Seidel in the rolling direction with the exact 2x2 element problem, Jacobi between lines with the
// full operator by FFT.
#include "conforma/exact_tangential.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/influence.hpp"
#include "steady_rolling_operator.hpp"

namespace conforma {
namespace {

// One element: the slip s = r0 + diag(a, b) p with |p| <= g (§14.2). Adhesion when the traction that annuls the slip
// fits the bound; otherwise p = -g e, s = sigma e (|e| = 1, sigma >= 0), r0 = (sigma I + g diag(a, b)) e.
struct ElementSolution {
  double px = 0.0, ps = 0.0, sx = 0.0, ss = 0.0;
  bool slip = false;
};

ElementSolution SolveElement(double r0x, double r0s, double a, double b, double g) {
  ElementSolution e;
  if (!(g > 0.0)) {  // no traction possible: the slip is the rigid + elastic one
    e.sx = r0x;
    e.ss = r0s;
    e.slip = r0x != 0.0 || r0s != 0.0;
    return e;
  }
  const double px = -r0x / a, ps = -r0s / b;
  if (px * px + ps * ps <= g * g) {
    e.px = px;
    e.ps = ps;
    return e;
  }
  double sigma = 0.0;
  if (a == b) {
    sigma = std::max(std::hypot(r0x, r0s) - g * a, 0.0);
  } else {
    // f(sigma) = (r0x / (sigma + g a))^2 + (r0s / (sigma + g b))^2 - 1: f(0) > 0, decreasing and convex, so Newton
    // from sigma = 0 rises monotonically to the root.
    for (int it = 0; it < 100; ++it) {
      const double ux = r0x / (sigma + g * a), us = r0s / (sigma + g * b);
      const double f = ux * ux + us * us - 1.0;
      const double df = -2.0 * (ux * ux / (sigma + g * a) + us * us / (sigma + g * b));
      const double step = -f / df;
      sigma += step;
      if (std::fabs(step) <= 1e-15 * (sigma + g * std::max(a, b))) break;
    }
  }
  const double ex = r0x / (sigma + g * a), es = r0s / (sigma + g * b);
  const double norm = std::hypot(ex, es);
  e.px = -g * ex / norm;
  e.ps = -g * es / norm;
  e.sx = sigma * ex / norm;
  e.ss = sigma * es / norm;
  e.slip = true;
  return e;
}

void CheckField(const Eigen::MatrixXd& field, const BemGrid& grid, const char* name) {
  if (field.rows() != grid.nx || field.cols() != grid.ns)
    throw InputError(std::string("exact tangential: ") + name + " must be nx x ns (" + std::to_string(grid.nx) +
                     " x " + std::to_string(grid.ns) + ")");
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i)
      if (!std::isfinite(field(i, j)))
        throw InputError(std::string("exact tangential: ") + name + "(" + std::to_string(i) + ", " +
                         std::to_string(j) + ") is not finite");
}

}  // namespace

const char* to_string(ExactTangentialStatus status) {
  switch (status) {
    case ExactTangentialStatus::Converged: return "converged";
    case ExactTangentialStatus::NotConverged: return "not_converged";
    case ExactTangentialStatus::NoContact: return "no_contact";
  }
  return "unknown";
}

void ExactTangentialOptions::validate() const {
  require_non_negative(friction_coefficient, "ExactTangentialOptions.friction_coefficient");
  require_non_negative(rolling_speed_m_per_s, "ExactTangentialOptions.rolling_speed_m_per_s");
  require_positive(tolerance, "ExactTangentialOptions.tolerance");
  if (max_sweeps < 1) throw InputError("ExactTangentialOptions.max_sweeps must be >= 1");
  if (lines_per_fft < 0) throw InputError("ExactTangentialOptions.lines_per_fft must be >= 0");
}

ExactTangentialResult SolveExactTangential(const BemGrid& grid, const Eigen::MatrixXd& pressure_Pa,
                                           const RigidSlipField& rigid_slip, const Material& material,
                                           const ExactTangentialOptions& options, double spin_origin_x_m,
                                           double spin_origin_s_m) {
  grid.validate();
  options.validate();
  CheckField(pressure_Pa, grid, "pressure_Pa");
  CheckField(rigid_slip.wx, grid, "rigid slip wx");
  CheckField(rigid_slip.ws, grid, "rigid slip ws");
  require_finite(spin_origin_x_m, "spin_origin_x_m");
  require_finite(spin_origin_s_m, "spin_origin_s_m");
  if ((pressure_Pa.array() < 0.0).any()) throw InputError("exact tangential: negative pressure");
  const ElasticConstants elastic = CombinedElasticConstants(material);
  auto mu = [&](double gamma) {
    const double value = options.friction ? options.friction(gamma) : options.friction_coefficient;
    if (!(value >= 0.0) || !std::isfinite(value))
      throw InputError("exact tangential: the friction law gives mu = " + MessageNumber(value) + " at slip " +
                       MessageNumber(gamma));
    return value;
  };

  ExactTangentialResult out;
  out.px_Pa = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  out.ps_Pa = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  out.sx = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  out.ss = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  out.state = Eigen::MatrixXi::Zero(grid.nx, grid.ns);
  out.bound_Pa = Eigen::MatrixXd::Zero(grid.nx, grid.ns);
  if (!(pressure_Pa.maxCoeff() > 0.0)) return out;  // NoContact

  // The grid extended by one row behind the trailing edge (i = 0 of the extended grid): the traction that leaves the
  // potential contact area there is released, v = -p / dx, and its displacement counts (§14.1).
  BemGrid ext = grid;
  ext.nx = grid.nx + 1;
  ext.x_first_m = grid.x_first_m - grid.dx_m;
  ext.gap_m = Eigen::MatrixXd::Zero(ext.nx, grid.ns);
  auto extended = [&](const Eigen::MatrixXd& field) {
    Eigen::MatrixXd e = Eigen::MatrixXd::Zero(ext.nx, grid.ns);
    e.bottomRows(grid.nx) = field;
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(e.data(), e.size()));
  };
  const int nx = ext.nx, ns = ext.ns;
  const long n = static_cast<long>(nx) * ns;
  const Eigen::VectorXd pn = extended(pressure_Pa), wx = extended(rigid_slip.wx), ws = extended(rigid_slip.ws);
  exact_detail::SteadyRollingOperator op(ext, elastic, options.influence == BemInfluence::Blanco, options.use_fft);
  const double h = grid.dx_m;
  const double a = op.line_xx(0) / h, b = op.line_ss(0) / h;  // element self terms of s in p (s = w + A v, v = dp/dx)

  // p: traction; v = (p - p_upstream) / dx along each line (§14.1), defined on every grid element (p = 0 outside the
  // contact, so v = -p_upstream / dx just behind a loaded element).
  Eigen::VectorXd px = Eigen::VectorXd::Zero(n), ps = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd vx = Eigen::VectorXd::Zero(n), vs = Eigen::VectorXd::Zero(n), sx, ss, g(n);
  std::vector<double> dvx(static_cast<size_t>(nx)), dvs(static_cast<size_t>(nx));
  std::vector<unsigned char> slip(static_cast<size_t>(n), 0), loaded(static_cast<size_t>(n), 0);
  for (long k = 0; k < n; ++k) loaded[static_cast<size_t>(k)] = pn[k] > 0.0 ? 1 : 0;
  g = pn * mu(0.0);
  out.status = ExactTangentialStatus::NotConverged;
  // Lines per FFT refresh: the direct updates within a block cost ~ns K nx^2 / 2 element pairs per sweep, the
  // refreshes ns / K FFT products of ~4 nx ns points. Measured (§14.2): ~0.4 ns per pair and ~17 ns per FFT point on a
  // 66 x 150 grid (optimum K ~ sqrt(340 ns / nx) = 28), cheaper pairs on small grids (the Manchester tread patch is
  // fastest with all lines in one block); K = sqrt(2000 ns / nx) is the compromise. K only changes the cost (and the
  // rounding), not the iteration.
  const int block = options.lines_per_fft > 0
                        ? options.lines_per_fft
                        : std::clamp(static_cast<int>(std::lround(std::sqrt(2000.0 * ns / nx))), 1, ns);
  for (int sweep = 1; sweep <= options.max_sweeps; ++sweep) {
    out.sweeps = sweep;
    double change = 0.0;
    // Gauss-Seidel between lines, by blocks of lines: the slip of every element is recomputed by FFT before each
    // block (it then holds the changes of every line done so far), and within the block each line's change is added
    // to the block's later lines by direct summation. The same iteration as line-by-line Gauss-Seidel, at one FFT
    // product per block instead of a direct O(n) update per line (§14.2).
    for (int first = 0; first < ns; first += block) {
      const int last = std::min(first + block, ns) - 1;
      op.Apply(vx, vs, sx, ss);  // slip of the current iterate, s = w + A v
      sx += wx;
      ss += ws;
      if (options.friction && first == 0)  // slip-dependent bound from the current slip (adhesion: mu(0)), §14.3
        for (long k = 0; k < n; ++k)
          g[k] = pn[k] > 0.0 ? pn[k] * mu(slip[static_cast<size_t>(k)] ? std::hypot(sx[k], ss[k]) : 0.0) : 0.0;
      for (int j = first; j <= last; ++j) {
        std::fill(dvx.begin(), dvx.end(), 0.0);
        std::fill(dvs.begin(), dvs.end(), 0.0);
        double up_x = 0.0, up_s = 0.0;  // traction of the upstream neighbour (already updated in this sweep)
        for (int i = nx - 1; i >= 0; --i) {  // from the leading edge (largest x) to the trailing edge
          const long k = i + static_cast<long>(nx) * j;
          double new_x = 0.0, new_s = 0.0;
          if (loaded[static_cast<size_t>(k)]) {
            double lx = sx[k], ls = ss[k];
            for (int m = i + 1; m < nx; ++m) {  // upstream elements of this line already updated in this sweep
              lx += op.line_xx(i - m) * dvx[static_cast<size_t>(m)];
              ls += op.line_ss(i - m) * dvs[static_cast<size_t>(m)];
            }
            // s = lx + a_self (v_new - v_old) with v_new = (p - up) / dx:  s = r0 + diag(a, b) p
            const ElementSolution e = SolveElement(lx - op.line_xx(0) * vx[k] - a * up_x,
                                                   ls - op.line_ss(0) * vs[k] - b * up_s, a, b, g[k]);
            new_x = e.px;
            new_s = e.ps;
            slip[static_cast<size_t>(k)] = e.slip ? 1 : 0;
            change = std::max(change, std::hypot(new_x - px[k], new_s - ps[k]));
          }
          const double v_new_x = (new_x - up_x) / h, v_new_s = (new_s - up_s) / h;
          dvx[static_cast<size_t>(i)] = v_new_x - vx[k];
          dvs[static_cast<size_t>(i)] = v_new_s - vs[k];
          vx[k] = v_new_x;
          vs[k] = v_new_s;
          px[k] = new_x;
          ps[k] = new_s;
          up_x = new_x;
          up_s = new_s;
        }
        op.AddColumnChange(j, dvx, dvs, loaded, j + 1, last, sx, ss);
      }
    }
    out.residual = change / std::max(g.maxCoeff(), 1e-300);
    if (out.residual < options.tolerance) {
      out.status = ExactTangentialStatus::Converged;
      break;
    }
  }

  // Final slip of the converged traction; adhesion elements carry s = 0 by definition.
  op.Apply(vx, vs, sx, ss);
  sx += wx;
  ss += ws;
  const double area = grid.element_area_m2();
  for (int j = 0; j < ns; ++j) {
    const double c = std::cos(grid.alpha(j)), s = std::sin(grid.alpha(j));
    const double y = grid.s_centre_m(j) - spin_origin_s_m;
    for (int i = 0; i < grid.nx; ++i) {
      const long k = i + 1 + static_cast<long>(nx) * j;  // extended grid
      if (!(pn[k] > 0.0)) continue;
      out.px_Pa(i, j) = px[k];
      out.ps_Pa(i, j) = ps[k];
      out.bound_Pa(i, j) = g[k];
      const bool in_slip = slip[static_cast<size_t>(k)] != 0;
      out.state(i, j) = in_slip ? 2 : 1;
      if (in_slip) {
        out.sx(i, j) = sx[k];
        out.ss(i, j) = ss[k];
        out.slip_area_m2 += area;
      } else {
        out.adhesion_area_m2 += area;
      }
      out.fx_N += px[k] * area;
      out.fy_N += ps[k] * c * area;
      out.fn_tangential_N -= ps[k] * s * area;
      out.mz_Nm += ((grid.x_centre_m(i) - spin_origin_x_m) * ps[k] - y * px[k]) * area;
      out.frictional_power_W +=
          std::fabs(px[k] * out.sx(i, j) + ps[k] * out.ss(i, j)) * options.rolling_speed_m_per_s * area;
    }
  }
  return out;
}

}  // namespace conforma
