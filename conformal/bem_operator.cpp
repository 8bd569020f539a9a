// Influence operator of the reference BEM (docs/physics-reference.md §10.1-10.3): DC-FFT convolution with the
// rectangle coefficients (FFTW), plus the Blanco-Lorenzo correction written as sums of convolutions.
#include "bem_operator.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

namespace conforma {
namespace bem_detail {
namespace {

// Smallest n >= minimum with no prime factor above 5 (the fastest FFTW_ESTIMATE sizes).
int GoodFftSize(int minimum) {
  for (int n = std::max(minimum, 1);; ++n) {
    int m = n;
    for (int f : {2, 3, 5})
      while (m % f == 0) m /= f;
    if (m == 1) return n;
  }
}

// FFTW's planner (plan creation and destruction) is not thread-safe; executing a plan is. One process-wide lock.
std::mutex& FftwPlannerMutex() {
  static std::mutex mutex;
  return mutex;
}

fftw_complex* AsFftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }

}  // namespace

Convolution::Convolution(const Eigen::MatrixXd& kernel, int nx, int ns, bool use_fft)
    : nx_(nx), ns_(ns), use_fft_(use_fft) {
  if (!use_fft_) {
    kernel_ = kernel;
    return;
  }
  // Zero padding to >= 2n - 1 per direction: the circular convolution then equals the linear one on the window.
  px_ = GoodFftSize(2 * nx_ - 1);
  ps_ = GoodFftSize(2 * ns_ - 1);
  const size_t real_size = static_cast<size_t>(px_) * ps_;
  const size_t complex_size = static_cast<size_t>(px_ / 2 + 1) * ps_;
  real_ = static_cast<double*>(fftw_malloc(sizeof(double) * real_size));
  spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * complex_size));
  kernel_spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * complex_size));
  if (!real_ || !spectrum_ || !kernel_spectrum_) {
    Release();
    throw std::bad_alloc();
  }
  {
    // FFTW arrays are row-major: dimension 0 is s (ps_), dimension 1 is x (px_, contiguous), as i + px j here; the
    // spectrum is ps_ rows of px_/2 + 1 complex values (FFTW's 2-D r2c layout).
    const int h = px_ / 2 + 1;
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    plans_[kForwardX] = fftw_plan_many_dft_r2c(1, &px_, ns_, real_, nullptr, 1, px_, AsFftw(spectrum_), nullptr, 1, h,
                                               FFTW_ESTIMATE);
    plans_[kForwardS] = fftw_plan_many_dft(1, &ps_, h, AsFftw(spectrum_), nullptr, h, 1, AsFftw(spectrum_), nullptr,
                                           h, 1, FFTW_FORWARD, FFTW_ESTIMATE);
    plans_[kBackwardS] = fftw_plan_many_dft(1, &ps_, h, AsFftw(spectrum_), nullptr, h, 1, AsFftw(spectrum_), nullptr,
                                            h, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
    plans_[kBackwardX] = fftw_plan_many_dft_c2r(1, &px_, ns_, AsFftw(spectrum_), nullptr, 1, h, real_, nullptr, 1, px_,
                                                FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  }
  for (void* plan : plans_)
    if (!plan) {
      Release();
      throw std::runtime_error("FFTW: plan creation failed");
    }
  // The kernel fills every row of the padded table: its spectrum by a full 2-D transform (once).
  std::fill(real_, real_ + real_size, 0.0);
  for (int dj = -(ns_ - 1); dj <= ns_ - 1; ++dj)
    for (int di = -(nx_ - 1); di <= nx_ - 1; ++di) {
      const int a = (di + px_) % px_, b = (dj + ps_) % ps_;
      real_[static_cast<size_t>(a) + static_cast<size_t>(px_) * b] = kernel(di + nx_ - 1, dj + ns_ - 1);
    }
  fftw_plan full;
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    full = fftw_plan_dft_r2c_2d(ps_, px_, real_, AsFftw(kernel_spectrum_), FFTW_ESTIMATE);
  }
  if (!full) {
    Release();
    throw std::runtime_error("FFTW: plan creation failed");
  }
  fftw_execute(full);
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    fftw_destroy_plan(full);
  }
  const double scale = 1.0 / static_cast<double>(real_size);  // FFTW's inverse is unnormalised
  for (size_t k = 0; k < complex_size; ++k) kernel_spectrum_[k] *= scale;
}

void Convolution::ForwardTransform(std::complex<double>* out) {
  fftw_execute_dft_r2c(static_cast<fftw_plan>(plans_[kForwardX]), real_, AsFftw(out));
  const size_t h = static_cast<size_t>(px_ / 2 + 1);
  std::fill(out + h * ns_, out + h * ps_, std::complex<double>(0.0, 0.0));  // rows of padding transform to 0
  fftw_execute_dft(static_cast<fftw_plan>(plans_[kForwardS]), AsFftw(out), AsFftw(out));
}

void Convolution::InverseTransform(std::complex<double>* in) {
  fftw_execute_dft(static_cast<fftw_plan>(plans_[kBackwardS]), AsFftw(in), AsFftw(in));
  fftw_execute_dft_c2r(static_cast<fftw_plan>(plans_[kBackwardX]), AsFftw(in), real_);
}

void Convolution::Release() {
  bool any = false;
  for (void* plan : plans_) any = any || plan;
  if (any) {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    for (void*& plan : plans_) {
      if (plan) fftw_destroy_plan(static_cast<fftw_plan>(plan));
      plan = nullptr;
    }
  }
  fftw_free(real_);
  fftw_free(spectrum_);
  fftw_free(kernel_spectrum_);
  real_ = nullptr;
  spectrum_ = kernel_spectrum_ = nullptr;
}

Convolution::~Convolution() { Release(); }

Convolution::Convolution(Convolution&& other) noexcept
    : nx_(other.nx_), ns_(other.ns_), px_(other.px_), ps_(other.ps_), use_fft_(other.use_fft_),
      kernel_(std::move(other.kernel_)), kernel_spectrum_(other.kernel_spectrum_), real_(other.real_),
      spectrum_(other.spectrum_) {
  for (int k = 0; k < kPlans; ++k) {
    plans_[k] = other.plans_[k];
    other.plans_[k] = nullptr;
  }
  other.kernel_spectrum_ = other.spectrum_ = nullptr;
  other.real_ = nullptr;
  other.nx_ = other.ns_ = other.px_ = other.ps_ = 0;
}

Convolution& Convolution::operator=(Convolution&& other) noexcept {
  if (this != &other) {
    Release();
    nx_ = other.nx_; ns_ = other.ns_; px_ = other.px_; ps_ = other.ps_; use_fft_ = other.use_fft_;
    kernel_ = std::move(other.kernel_);
    std::swap(kernel_spectrum_, other.kernel_spectrum_);
    std::swap(real_, other.real_);
    std::swap(spectrum_, other.spectrum_);
    for (int k = 0; k < kPlans; ++k) std::swap(plans_[k], other.plans_[k]);
    other.nx_ = other.ns_ = other.px_ = other.ps_ = 0;
  }
  return *this;
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
  LoadPadded(in);
  ForwardTransform(spectrum_);
  double* a = reinterpret_cast<double*>(spectrum_);
  const double* k = reinterpret_cast<const double*>(kernel_spectrum_);
  for (size_t m = 0; m < 2 * ComplexSize(); m += 2) {  // real arithmetic, as in MultiplyAdd
    const double re = k[m] * a[m] - k[m + 1] * a[m + 1];
    a[m + 1] = k[m] * a[m + 1] + k[m + 1] * a[m];
    a[m] = re;
  }
  InverseTransform(spectrum_);
  StoreWindow(out);
}

void Convolution::LoadPadded(const Eigen::VectorXd& in) {
  const size_t px = static_cast<size_t>(px_);
  for (int j = 0; j < ns_; ++j) {
    double* row = real_ + px * j;
    std::copy(in.data() + static_cast<long>(nx_) * j, in.data() + static_cast<long>(nx_) * (j + 1), row);
    std::fill(row + nx_, row + px, 0.0);
  }  // rows ns_.. are not read (ForwardTransform)
}

void Convolution::StoreWindow(Eigen::VectorXd& out) const {
  out.resize(static_cast<long>(nx_) * ns_);
  const size_t px = static_cast<size_t>(px_);
  for (int j = 0; j < ns_; ++j)
    std::copy(real_ + px * j, real_ + px * j + nx_, out.data() + static_cast<long>(nx_) * j);
}

Convolution::Spectrum::Spectrum(size_t size)
    : data_(reinterpret_cast<std::complex<double>*>(fftw_malloc(sizeof(fftw_complex) * size))), size_(size) {
  if (!data_) throw std::bad_alloc();
}

Convolution::Spectrum::~Spectrum() { fftw_free(data_); }

Convolution::Spectrum& Convolution::Spectrum::operator=(Spectrum&& other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  return *this;
}

Convolution::Spectrum Convolution::NewSpectrum() const { return use_fft_ ? Spectrum(ComplexSize()) : Spectrum(); }

void Convolution::Forward(const Eigen::VectorXd& in, Spectrum& out) {
  if (out.size() != ComplexSize()) out = NewSpectrum();
  LoadPadded(in);
  ForwardTransform(out.data());
}

void Convolution::MultiplyAdd(const Spectrum& in, double sign, Spectrum& acc, bool overwrite) const {
  // in real arithmetic (std::complex's operator* checks for inf / NaN and does not vectorise)
  const size_t n = ComplexSize();
  const double* a = reinterpret_cast<const double*>(in.data());
  const double* k = reinterpret_cast<const double*>(kernel_spectrum_);
  double* b = reinterpret_cast<double*>(acc.data());
  if (overwrite)
    for (size_t m = 0; m < 2 * n; m += 2) {
      b[m] = sign * (k[m] * a[m] - k[m + 1] * a[m + 1]);
      b[m + 1] = sign * (k[m] * a[m + 1] + k[m + 1] * a[m]);
    }
  else
    for (size_t m = 0; m < 2 * n; m += 2) {
      b[m] += sign * (k[m] * a[m] - k[m + 1] * a[m + 1]);
      b[m + 1] += sign * (k[m] * a[m + 1] + k[m + 1] * a[m]);
    }
}

void Convolution::Inverse(Spectrum& in, Eigen::VectorXd& out) {
  InverseTransform(in.data());
  StoreWindow(out);
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
// cos(a_J - a_I) = c_J c_I + s_J s_I and sin(a_J - a_I) = s_J c_I - c_J s_I:
//     u = c (A (c p) - S (s p)) + s (A (s p) + S (c p)).
// FFT path: two forward transforms (c p, s p) and two inverse ones, whatever the number of kernels.
void InfluenceOperator::Apply(const Eigen::VectorXd& pressure, Eigen::VectorXd& displacement) {
  if (!corrected_) {
    normal_->Apply(pressure, displacement);
    return;
  }
  cp_ = cos_.cwiseProduct(pressure);
  sp_ = sin_.cwiseProduct(pressure);
  if (normal_->uses_fft()) {
    normal_->Forward(cp_, spectrum_cp_);
    normal_->Forward(sp_, spectrum_sp_);
    if (out_a_.size() != spectrum_cp_.size()) {
      out_a_ = normal_->NewSpectrum();
      out_b_ = normal_->NewSpectrum();
    }
    normal_->MultiplyAdd(spectrum_cp_, 1.0, out_a_, true);
    normal_->MultiplyAdd(spectrum_sp_, 1.0, out_b_, true);
    if (coupled_) {
      coupling_->MultiplyAdd(spectrum_sp_, -1.0, out_a_, false);
      coupling_->MultiplyAdd(spectrum_cp_, 1.0, out_b_, false);
    }
    normal_->Inverse(out_a_, displacement);
    normal_->Inverse(out_b_, tmp_);
    displacement = displacement.cwiseProduct(cos_) + tmp_.cwiseProduct(sin_);
    return;
  }
  normal_->Apply(cp_, displacement);
  displacement = displacement.cwiseProduct(cos_);
  normal_->Apply(sp_, tmp_);
  displacement += tmp_.cwiseProduct(sin_);
  if (!coupled_) return;
  coupling_->Apply(sp_, tmp_);
  displacement -= tmp_.cwiseProduct(cos_);
  coupling_->Apply(cp_, tmp_);
  displacement += tmp_.cwiseProduct(sin_);
}

}  // namespace bem_detail
}  // namespace conforma
