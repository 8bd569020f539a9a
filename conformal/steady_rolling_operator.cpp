// The tangential influence operator of the exact steady-rolling solver (docs/physics-reference.md §14.1).
#include "steady_rolling_operator.hpp"

#include <algorithm>
#include <cmath>

namespace conforma {
namespace exact_detail {

SteadyRollingOperator::SteadyRollingOperator(const BemGrid& grid, const ElasticConstants& elastic, bool corrected,
                                             bool use_fft)
    : nx_(grid.nx), ns_(grid.ns) {
  // A on the offsets di in (-nx, nx), dj in (-ns, ns)   (§10.2)
  const int rows = 2 * nx_ - 1, cols = 2 * ns_ - 1;
  Eigen::MatrixXd axx(rows, cols), axs(rows, cols), ass(rows, cols);
  for (int dj = -(ns_ - 1); dj <= ns_ - 1; ++dj)
    for (int di = -(nx_ - 1); di <= nx_ - 1; ++di) {
      const HalfSpaceInfluence a = RectangleInfluence(di * grid.dx_m, dj * grid.ds_m, grid.dx_m, grid.ds_m, elastic);
      axx(di + nx_ - 1, dj + ns_ - 1) = a.xx;
      axs(di + nx_ - 1, dj + ns_ - 1) = a.xs;
      ass(di + nx_ - 1, dj + ns_ - 1) = a.ss;
    }
  axx_ = axx;
  axs_ = axs;
  ass_ = ass;
  xx_.emplace(axx, nx_, ns_, use_fft);
  xs_.emplace(axs, nx_, ns_, use_fft);
  ss_.emplace(ass, nx_, ns_, use_fft);
  bool any_rotation = false;
  for (int j = 0; j < ns_; ++j) any_rotation = any_rotation || grid.alpha(j) != 0.0;
  corrected_ = corrected && any_rotation;
  if (!corrected_) return;
  const long n = static_cast<long>(nx_) * ns_;
  cos_.resize(n);
  sin_.resize(n);
  for (int j = 0; j < ns_; ++j)
    for (int i = 0; i < nx_; ++i) {
      cos_[i + static_cast<long>(nx_) * j] = std::cos(grid.alpha(j));
      sin_[i + static_cast<long>(nx_) * j] = std::sin(grid.alpha(j));
    }
}

// u_x = A_xx vx + A_xs (c_J c_I + s_J s_I) vs,  u_s = A_sx vx + A_ss (c_J c_I + s_J s_I) vs   (§4.2 version 1, K = 0:
// B_xx = A_xx, B_sx = A_sx, B_xs = A_xs cos(alpha_J - alpha_I), B_ss = A_ss cos(alpha_J - alpha_I))
void SteadyRollingOperator::Apply(const Eigen::VectorXd& vx, const Eigen::VectorXd& vs, Eigen::VectorXd& out_x,
                                  Eigen::VectorXd& out_s) {
  if (!xx_->uses_fft()) {  // direct summation (checks)
    xx_->Apply(vx, out_x);
    xs_->Apply(vx, out_s);  // A_sx = A_xs
    if (!corrected_) {
      xs_->Apply(vs, a_);
      out_x += a_;
      ss_->Apply(vs, a_);
      out_s += a_;
      return;
    }
    t_ = cos_.cwiseProduct(vs);
    xs_->Apply(t_, a_);
    ss_->Apply(t_, b_);
    out_x += a_.cwiseProduct(cos_);
    out_s += b_.cwiseProduct(cos_);
    t_ = sin_.cwiseProduct(vs);
    xs_->Apply(t_, a_);
    ss_->Apply(t_, b_);
    out_x += a_.cwiseProduct(sin_);
    out_s += b_.cwiseProduct(sin_);
    return;
  }
  // FFT: the spectra of the inputs once, products summed in the spectral domain where the weights allow
  if (fx_.size() == 0) {
    fx_ = xx_->NewSpectrum();
    fs_ = xx_->NewSpectrum();
    acc_x_ = xx_->NewSpectrum();
    acc_s_ = xx_->NewSpectrum();
  }
  xx_->Forward(vx, fx_);
  if (!corrected_) {
    xs_->Forward(vs, fs_);
    xx_->MultiplyAdd(fx_, 1.0, acc_x_, true);
    xs_->MultiplyAdd(fs_, 1.0, acc_x_, false);
    xs_->MultiplyAdd(fx_, 1.0, acc_s_, true);
    ss_->MultiplyAdd(fs_, 1.0, acc_s_, false);
    xx_->Inverse(acc_x_, out_x);
    xx_->Inverse(acc_s_, out_s);
    return;
  }
  xx_->MultiplyAdd(fx_, 1.0, acc_x_, true);
  xs_->MultiplyAdd(fx_, 1.0, acc_s_, true);
  xx_->Inverse(acc_x_, out_x);
  xx_->Inverse(acc_s_, out_s);
  for (int part = 0; part < 2; ++part) {  // cos and sin parts of cos(alpha_J - alpha_I)
    const Eigen::VectorXd& weight = part == 0 ? cos_ : sin_;
    t_ = weight.cwiseProduct(vs);
    xs_->Forward(t_, fs_);
    xs_->MultiplyAdd(fs_, 1.0, acc_x_, true);
    ss_->MultiplyAdd(fs_, 1.0, acc_s_, true);
    xx_->Inverse(acc_x_, a_);
    xx_->Inverse(acc_s_, b_);
    out_x += a_.cwiseProduct(weight);
    out_s += b_.cwiseProduct(weight);
  }
}

void SteadyRollingOperator::AddColumnChange(int j, const std::vector<double>& dvx, const std::vector<double>& dvs,
                                            const std::vector<unsigned char>& mask, int first_column,
                                            int last_column, Eigen::VectorXd& slip_x, Eigen::VectorXd& slip_s) const {
  std::vector<int> changed;
  for (int m = 0; m < nx_; ++m)
    if (dvx[static_cast<size_t>(m)] != 0.0 || dvs[static_cast<size_t>(m)] != 0.0) changed.push_back(m);
  if (changed.empty()) return;
  for (int jj = std::max(first_column, 0); jj <= std::min(last_column, ns_ - 1); ++jj) {
    if (jj == j) continue;
    const int dj = jj - j + ns_ - 1;
    // cos(alpha_J - alpha_I) on the lateral load column (corrected grids), J in column j, I in column jj
    const long kj = static_cast<long>(nx_) * j, kjj = static_cast<long>(nx_) * jj;
    const double rot = corrected_ ? cos_[kj] * cos_[kjj] + sin_[kj] * sin_[kjj] : 1.0;
    int i_lo = nx_, i_hi = -1;  // loaded rows of column jj
    for (int i = 0; i < nx_; ++i)
      if (mask[static_cast<size_t>(i + kjj)]) { i_lo = std::min(i_lo, i); i_hi = i; }
    if (i_hi < 0) continue;
    const double* cxx = &axx_(0, dj);
    const double* cxs = &axs_(0, dj);
    const double* css = &ass_(0, dj);
    double* sx = slip_x.data() + kjj;
    double* ss = slip_s.data() + kjj;
    for (int m : changed) {
      const double vx = dvx[static_cast<size_t>(m)], vs = rot * dvs[static_cast<size_t>(m)];
      const int offset = nx_ - 1 - m;  // table row of (i - m) is i + offset
      for (int i = i_lo; i <= i_hi; ++i) {
        sx[i] += cxx[i + offset] * vx + cxs[i + offset] * vs;
        ss[i] += cxs[i + offset] * vx + css[i + offset] * vs;
      }
    }
  }
}

}  // namespace exact_detail
}  // namespace conforma
