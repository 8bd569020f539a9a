#pragma once
// Internal to the reference BEM: the influence operator u = C p on a BemGrid, by DC-FFT (zero-padded
// circular convolution, Liu, Wang & Liu 2000) or by direct summation. Vectors are column-major
// nx x ns fields flattened as i + nx * j.
#include <Eigen/Core>
#include <complex>
#include <optional>
#include <vector>

#include "conforma/bem_reference.hpp"
#include "conforma/influence.hpp"

namespace conforma {
namespace bem_detail {

// Convolution of an nx x ns field with a kernel tabulated on the offsets (di, dj) in (-nx, nx) x (-ns, ns).
// FFT path: DC-FFT (Liu, Wang & Liu 2000) with FFTW's real-to-complex / complex-to-real 2-D transforms of the
// zero-padded field; the plans are made with FFTW_ESTIMATE (deterministic: no timing-dependent plan choice) under
// one process-wide mutex, because FFTW's planner is not thread-safe (executing a plan on new arrays is).
// Owns FFTW plans and buffers: not copyable, movable (usable inside std::optional).
class Convolution {
 public:
  // kernel(di + nx - 1, dj + ns - 1) = K(di, dj), a (2nx-1) x (2ns-1) table.
  Convolution(const Eigen::MatrixXd& kernel, int nx, int ns, bool use_fft);
  ~Convolution();
  Convolution(const Convolution&) = delete;
  Convolution& operator=(const Convolution&) = delete;
  Convolution(Convolution&& other) noexcept;
  Convolution& operator=(Convolution&& other) noexcept;
  // out_I = sum_J K(i_I - i_J, j_I - j_J) in_J
  void Apply(const Eigen::VectorXd& in, Eigen::VectorXd& out);

 private:
  void Release();
  int nx_ = 0, ns_ = 0, px_ = 0, ps_ = 0;
  bool use_fft_ = false;
  Eigen::MatrixXd kernel_;          // direct path only
  std::complex<double>* kernel_spectrum_ = nullptr;  // ps x (px/2+1), scaled by 1 / (px ps)
  double* real_ = nullptr;                           // ps x px padded field (x contiguous)
  std::complex<double>* spectrum_ = nullptr;         // ps x (px/2+1)
  void* forward_ = nullptr;   // fftw_plan (r2c)
  void* backward_ = nullptr;  // fftw_plan (c2r)
};

class InfluenceOperator {
 public:
  InfluenceOperator(const BemGrid& grid, const ElasticConstants& elastic, BemInfluence influence,
                    ConformalCoupling coupling, bool use_fft);
  void Apply(const Eigen::VectorXd& pressure, Eigen::VectorXd& displacement);
  double self_coefficient() const { return self_coefficient_; }

 private:
  int nx_, ns_;
  bool corrected_ = false, coupled_ = false;
  Eigen::VectorXd cos_, sin_;  // per element, cos / sin of the column's alpha
  std::optional<Convolution> normal_;    // A_nn
  std::optional<Convolution> coupling_;  // A_ns (only with a non-zero coupling parameter)
  double self_coefficient_ = 0.0;
};

// Fills the integrated outputs of result (forces, area, extents, point of action, complementarity) from
// the pressure and deformed gap fields (flattened, i + nx j) on result.grid.
void SummariseBem(const Eigen::VectorXd& pressure, const Eigen::VectorXd& deformed_gap, BemResult& result);

}  // namespace bem_detail
}  // namespace conforma
