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
// zero-padded field, done as 1-D transforms so that the rows along x that are all padding (forward) or not needed
// (inverse) are skipped; the plans are made with FFTW_ESTIMATE (deterministic: no timing-dependent plan choice) under
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

  // Spectral interface (FFT path only), for sums of convolutions sharing transforms: the spectra of Convolutions
  // built for the same nx x ns are interchangeable, so sum_k K_k * in_k costs one forward transform per distinct
  // input and one inverse per output.
  class Spectrum {  // (px/2+1) ps complex values of a zero-padded field, FFTW-aligned; movable
   public:
    Spectrum() = default;
    explicit Spectrum(size_t size);
    ~Spectrum();
    Spectrum(Spectrum&& other) noexcept : data_(other.data_), size_(other.size_) { other.data_ = nullptr; other.size_ = 0; }
    Spectrum& operator=(Spectrum&& other) noexcept;
    Spectrum(const Spectrum&) = delete;
    Spectrum& operator=(const Spectrum&) = delete;
    std::complex<double>* data() const { return data_; }
    size_t size() const { return size_; }

   private:
    std::complex<double>* data_ = nullptr;
    size_t size_ = 0;
  };
  bool uses_fft() const { return use_fft_; }
  Spectrum NewSpectrum() const;                                  // zero-size unless uses_fft()
  void Forward(const Eigen::VectorXd& in, Spectrum& out);       // out = F(in) (in: nx ns values)
  void MultiplyAdd(const Spectrum& in, double sign, Spectrum& acc, bool overwrite) const;  // acc (=|+=) sign K^ in
  void Inverse(Spectrum& in, Eigen::VectorXd& out);             // out = window of F^-1(in); destroys in

 private:
  void Release();
  void LoadPadded(const Eigen::VectorXd& in);        // rows 0 .. ns-1 of real_ = in, zero-padded along x
  void ForwardTransform(std::complex<double>* out);  // out = F(real_) (rows ns.. of real_ taken as 0)
  void InverseTransform(std::complex<double>* in);   // rows 0 .. ns-1 of real_ = F^-1(in); destroys in
  void StoreWindow(Eigen::VectorXd& out) const;     // out = the nx x ns window of real_
  size_t ComplexSize() const { return static_cast<size_t>(px_ / 2 + 1) * static_cast<size_t>(ps_); }
  int nx_ = 0, ns_ = 0, px_ = 0, ps_ = 0;
  bool use_fft_ = false;
  Eigen::MatrixXd kernel_;          // direct path only
  std::complex<double>* kernel_spectrum_ = nullptr;  // ps x (px/2+1), scaled by 1 / (px ps)
  double* real_ = nullptr;                           // ps x px padded field (x contiguous)
  std::complex<double>* spectrum_ = nullptr;         // ps x (px/2+1)
  // fftw_plans of the pruned 2-D transforms: r2c along x of the ns data rows, c2c along s of every column
  // (forward), c2c along s, c2r along x of the ns output rows (inverse)
  enum Plan { kForwardX, kForwardS, kBackwardS, kBackwardX, kPlans };
  void* plans_[kPlans] = {nullptr, nullptr, nullptr, nullptr};
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
  Eigen::VectorXd cp_, sp_, tmp_;                                        // scratch
  Convolution::Spectrum spectrum_cp_, spectrum_sp_, out_a_, out_b_;  // scratch (FFT path)
};

// InputError when an nx x ns grid exceeds the budget max_elements (BemOptions::max_elements), naming the grid, the
// budget, and the options that change them.
void CheckGridBudget(double nx, double ns, double dx_m, double ds_m, long max_elements);

// Fills the integrated outputs of result (forces, area, extents, point of action, complementarity) from
// the pressure and deformed gap fields (flattened, i + nx j) on result.grid.
void SummariseBem(const Eigen::VectorXd& pressure, const Eigen::VectorXd& deformed_gap, BemResult& result);

}  // namespace bem_detail
}  // namespace conforma
