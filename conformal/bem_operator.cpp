// Influence operator of the reference BEM (docs/physics-reference.md §10.1-10.3): DC-FFT convolution with the
// rectangle coefficients, plus the Blanco-Lorenzo correction written as sums of convolutions.
#include "bem_operator.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>

namespace conforma {
namespace bem_detail {
namespace {

// Smallest n >= minimum with no prime factor above 5 (fast for kissfft).
int GoodFftSize(int minimum) {
  for (int n = std::max(minimum, 1);; ++n) {
    int m = n;
    for (int f : {2, 3, 5})
      while (m % f == 0) m /= f;
    if (m == 1) return n;
  }
}

}  // namespace

Convolution::Convolution(const Eigen::MatrixXd& kernel, int nx, int ns, bool use_fft)
    : nx_(nx), ns_(ns), use_fft_(use_fft), kernel_(kernel) {
  if (!use_fft_) return;
  px_ = GoodFftSize(2 * nx_);
  ps_ = GoodFftSize(2 * ns_);
  kernel_spectrum_.assign(static_cast<size_t>(px_) * ps_, {0.0, 0.0});
  for (int dj = -(ns_ - 1); dj <= ns_ - 1; ++dj)
    for (int di = -(nx_ - 1); di <= nx_ - 1; ++di) {
      const int a = (di + px_) % px_, b = (dj + ps_) % ps_;
      kernel_spectrum_[static_cast<size_t>(a) + static_cast<size_t>(px_) * b] = kernel_(di + nx_ - 1, dj + ns_ - 1);
    }
  Transform(kernel_spectrum_, false, ps_);
  kernel_.resize(0, 0);
}

// 2-D FFT by rows and columns of 1-D transforms (Eigen's kissfft backend has no 2-D transform). Only the
// first `columns` lines along x carry data (zero padding) or are needed (the output window), so the
// x-transforms are restricted to them: forward x then s, inverse s then x.
void Convolution::Transform(std::vector<std::complex<double>>& data, bool inverse, int columns) {
  auto along_x = [&]() {
    for (int b = 0; b < columns; ++b) {
      line_in_.assign(data.begin() + static_cast<long>(b) * px_, data.begin() + static_cast<long>(b + 1) * px_);
      if (inverse) fft_.inv(line_out_, line_in_); else fft_.fwd(line_out_, line_in_);
      std::copy(line_out_.begin(), line_out_.end(), data.begin() + static_cast<long>(b) * px_);
    }
  };
  auto along_s = [&]() {
    line_in_.resize(static_cast<size_t>(ps_));
    for (int a = 0; a < px_; ++a) {
      for (int b = 0; b < ps_; ++b) line_in_[static_cast<size_t>(b)] = data[static_cast<size_t>(a) + static_cast<size_t>(px_) * b];
      if (inverse) fft_.inv(line_out_, line_in_); else fft_.fwd(line_out_, line_in_);
      for (int b = 0; b < ps_; ++b) data[static_cast<size_t>(a) + static_cast<size_t>(px_) * b] = line_out_[static_cast<size_t>(b)];
    }
  };
  if (inverse) { along_s(); along_x(); } else { along_x(); along_s(); }
}

void Convolution::Apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  out.resize(static_cast<long>(nx_) * ns_);
  if (!use_fft_) {
    for (int j = 0; j < ns_; ++j)
      for (int i = 0; i < nx_; ++i) {
        double sum = 0.0;
        for (int jj = 0; jj < ns_; ++jj)
          for (int ii = 0; ii < nx_; ++ii)
            sum += kernel_(i - ii + nx_ - 1, j - jj + ns_ - 1) * in[ii + static_cast<long>(nx_) * jj];
        out[i + static_cast<long>(nx_) * j] = sum;
      }
    return;
  }
  work_.assign(static_cast<size_t>(px_) * ps_, {0.0, 0.0});
  for (int j = 0; j < ns_; ++j)
    for (int i = 0; i < nx_; ++i)
      work_[static_cast<size_t>(i) + static_cast<size_t>(px_) * j] = in[i + static_cast<long>(nx_) * j];
  Transform(work_, false, ns_);
  for (size_t k = 0; k < work_.size(); ++k) work_[k] *= kernel_spectrum_[k];
  Transform(work_, true, ns_);
  for (int j = 0; j < ns_; ++j)
    for (int i = 0; i < nx_; ++i)
      out[i + static_cast<long>(nx_) * j] = work_[static_cast<size_t>(i) + static_cast<size_t>(px_) * j].real();
}

InfluenceOperator::InfluenceOperator(const BemGrid& grid, const ElasticConstants& elastic,
                                     BemInfluence influence, ConformalCoupling coupling, bool use_fft)
    : nx_(grid.nx), ns_(grid.ns) {
  Eigen::MatrixXd normal(2 * nx_ - 1, 2 * ns_ - 1);
  for (int dj = -(ns_ - 1); dj <= ns_ - 1; ++dj)
    for (int di = -(nx_ - 1); di <= nx_ - 1; ++di)
      normal(di + nx_ - 1, dj + ns_ - 1) =
          RectangleNormalInfluence(di * grid.dx_m, dj * grid.ds_m, grid.dx_m, grid.ds_m, elastic);  // §10.2
  self_coefficient_ = normal(nx_ - 1, ns_ - 1);
  normal_.emplace(normal, nx_, ns_, use_fft);

  bool any_rotation = false;
  for (int j = 0; j < ns_; ++j) any_rotation = any_rotation || grid.alpha(j) != 0.0;
  corrected_ = influence == BemInfluence::Blanco && any_rotation;
  if (!corrected_) return;
  cos_.resize(static_cast<long>(nx_) * ns_);
  sin_.resize(static_cast<long>(nx_) * ns_);
  for (int j = 0; j < ns_; ++j)
    for (int i = 0; i < nx_; ++i) {
      cos_[i + static_cast<long>(nx_) * j] = std::cos(grid.alpha(j));
      sin_[i + static_cast<long>(nx_) * j] = std::sin(grid.alpha(j));
    }
  const double K = CouplingParameter(coupling, elastic);
  if (K == 0.0) return;
  coupled_ = true;
  // A_ns = (K / (pi G)) [[j6]] (influence.hpp).
  const double scale = K / (3.14159265358979323846 * elastic.shear_modulus_Pa);
  Eigen::MatrixXd ns_table(2 * nx_ - 1, 2 * ns_ - 1);
  for (int dj = -(ns_ - 1); dj <= ns_ - 1; ++dj)
    for (int di = -(nx_ - 1); di <= nx_ - 1; ++di)
      ns_table(di + nx_ - 1, dj + ns_ - 1) =
          scale * RectangleCouplingIntegral(di * grid.dx_m, dj * grid.ds_m, grid.dx_m, grid.ds_m);
  coupling_.emplace(ns_table, nx_, ns_, use_fft);
}

// C_IJ = A_IJ cos(a_J - a_I) - S_IJ sin(a_J - a_I)   (§4.2, paper 003 eq. 2), with
// cos(a_J - a_I) = c_J c_I + s_J s_I and sin(a_J - a_I) = s_J c_I - c_J s_I.
void InfluenceOperator::Apply(const Eigen::VectorXd& pressure, Eigen::VectorXd& displacement) {
  if (!corrected_) {
    normal_->Apply(pressure, displacement);
    return;
  }
  Eigen::VectorXd cp = cos_.cwiseProduct(pressure), sp = sin_.cwiseProduct(pressure), tmp;
  normal_->Apply(cp, displacement);
  displacement = displacement.cwiseProduct(cos_);
  normal_->Apply(sp, tmp);
  displacement += tmp.cwiseProduct(sin_);
  if (!coupled_) return;
  coupling_->Apply(sp, tmp);
  displacement -= tmp.cwiseProduct(cos_);
  coupling_->Apply(cp, tmp);
  displacement += tmp.cwiseProduct(sin_);
}

}  // namespace bem_detail
}  // namespace conforma
