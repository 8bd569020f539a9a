#pragma once
// Internal to the exact tangential solver (exact_tangential.hpp): the tangential influence operator on a BemGrid.
// The steady-rolling slip is s = w + (u - u') / dx with u' the displacement one element upstream; since a convolution
// commutes with the shift, u - u' = A (p - p_upstream), so (docs/physics-reference.md §14.1)
//     s = w + A v,   v_I = (p_I - p_I+) / dx     (I+ = the upstream neighbour of I in its grid line, p = 0 beyond)
// with the rectangle coefficients A_xx, A_xs = A_sx, A_ss (§10.2) and on a curved grid the Blanco-Lorenzo factor
// cos(alpha_J - alpha_I) on the lateral load column (§4.2 version 1, K = 0). A is symmetric positive definite, which
// is what makes Gauss-Seidel in v converge (it diverges on the non-symmetric operator in p).
// cos(a - b) = cos a cos b + sin a sin b keeps every product a sum of convolutions (as the normal operator).
// Vectors are column-major nx x ns fields flattened as i + nx * j.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "bem_operator.hpp"
#include "conforma/bem_reference.hpp"
#include "conforma/influence.hpp"

namespace conforma {
namespace exact_detail {

class SteadyRollingOperator {
 public:
  // corrected: apply the Blanco-Lorenzo factor (ignored on a flat grid).
  SteadyRollingOperator(const BemGrid& grid, const ElasticConstants& elastic, bool corrected, bool use_fft);
  // out = A v for the field v = (vx, vs).
  void Apply(const Eigen::VectorXd& vx, const Eigen::VectorXd& vs, Eigen::VectorXd& out_x, Eigen::VectorXd& out_s);
  // A within one grid line (same column: alpha_J = alpha_I, A_xs = 0 on Y = 0): A_xx(di, 0), A_ss(di, 0) for the
  // offset di = i_I - i_J in (-nx, nx).
  double line_xx(int di) const { return axx_(di + nx_ - 1, ns_ - 1); }
  double line_ss(int di) const { return ass_(di + nx_ - 1, ns_ - 1); }
  // Adds A (dv on column j) to the slip of the elements of the columns other than j that `mask` marks (nonzero), by
  // direct summation over the elements of column j with a nonzero change (Gauss-Seidel within a block of lines, §14.2).
  // Only the columns in [first_column, last_column] (other than j) are updated.
  void AddColumnChange(int j, const std::vector<double>& dvx, const std::vector<double>& dvs,
                       const std::vector<unsigned char>& mask, int first_column, int last_column,
                       Eigen::VectorXd& slip_x, Eigen::VectorXd& slip_s) const;

 private:
  int nx_, ns_;
  bool corrected_ = false;
  Eigen::VectorXd cos_, sin_;  // per element, of the column's alpha (corrected only)
  std::optional<bem_detail::Convolution> xx_, xs_, ss_;
  Eigen::MatrixXd axx_, axs_, ass_;  // A tables, (2nx-1) x (2ns-1), offsets (di + nx - 1, dj + ns - 1)
  Eigen::VectorXd a_, b_, t_;  // scratch
  bem_detail::Convolution::Spectrum fx_, fs_, acc_x_, acc_s_;  // scratch (FFT path)
};

}  // namespace exact_detail
}  // namespace conforma
