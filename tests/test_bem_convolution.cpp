// bem_detail::Convolution (conformal/bem_operator.hpp): the FFTW DC-FFT path equals the direct summation of the
// linear (not circular) convolution to rounding for odd, even, prime and degenerate (1 x n) grids; it is movable,
// lives in std::optional, and concurrent construction and use from several threads gives identical results.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "../conformal/bem_operator.hpp"

namespace conforma {
namespace {

using bem_detail::Convolution;

static_assert(!std::is_copy_constructible_v<Convolution>, "owns FFTW plans");
static_assert(std::is_nothrow_move_constructible_v<Convolution>, "movable");
static_assert(std::is_nothrow_move_assignable_v<Convolution>, "movable");

Eigen::MatrixXd RandomKernel(int nx, int ns, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd k(2 * nx - 1, 2 * ns - 1);
  for (long c = 0; c < k.cols(); ++c)
    for (long r = 0; r < k.rows(); ++r) k(r, c) = u(rng);
  return k;
}

Eigen::VectorXd RandomField(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int k = 0; k < n; ++k) v[k] = u(rng);
  return v;
}

// Straight from the definition out_I = sum_J K(i_I - i_J, j_I - j_J) in_J (independent of the class).
Eigen::VectorXd Definition(const Eigen::MatrixXd& kernel, int nx, int ns, const Eigen::VectorXd& in) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<long>(nx) * ns);
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nx; ++i)
      for (int jj = 0; jj < ns; ++jj)
        for (int ii = 0; ii < nx; ++ii)
          out[i + nx * j] += kernel(i - ii + nx - 1, j - jj + ns - 1) * in[ii + nx * jj];
  return out;
}

TEST(BemConvolution, FftEqualsDirectSummationForManyGridShapes) {
  std::mt19937_64 rng(14);
  const std::pair<int, int> shapes[] = {{1, 1}, {1, 7}, {9, 1}, {2, 3}, {13, 11}, {16, 16}, {17, 31}, {64, 5}};
  for (const auto& [nx, ns] : shapes) {
    const Eigen::MatrixXd kernel = RandomKernel(nx, ns, rng);
    Convolution fft(kernel, nx, ns, true), direct(kernel, nx, ns, false);
    for (int repeat = 0; repeat < 3; ++repeat) {  // the buffers are reused between calls
      const Eigen::VectorXd in = RandomField(nx * ns, rng);
      Eigen::VectorXd a, b;
      fft.Apply(in, a);
      direct.Apply(in, b);
      const Eigen::VectorXd exact = Definition(kernel, nx, ns, in);
      const double scale = kernel.cwiseAbs().sum() * in.cwiseAbs().maxCoeff();
      EXPECT_LT((a - exact).cwiseAbs().maxCoeff(), 1e-13 * scale) << nx << " x " << ns;
      EXPECT_LT((b - exact).cwiseAbs().maxCoeff(), 1e-13 * scale) << nx << " x " << ns;
    }
  }
}

TEST(BemConvolution, MovableAndUsableInOptional) {
  std::mt19937_64 rng(3);
  const int nx = 12, ns = 9;
  const Eigen::MatrixXd kernel = RandomKernel(nx, ns, rng);
  const Eigen::VectorXd in = RandomField(nx * ns, rng);
  const Eigen::VectorXd exact = Definition(kernel, nx, ns, in);
  std::optional<Convolution> holder;
  holder.emplace(kernel, nx, ns, true);
  Convolution moved(std::move(*holder));
  holder.reset();  // the moved-from object is destroyed safely
  Eigen::VectorXd out;
  moved.Apply(in, out);
  EXPECT_LT((out - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());
  Convolution other(RandomKernel(3, 4, rng), 3, 4, true);
  other = std::move(moved);  // releases other's plans, takes moved's
  other.Apply(in, out);
  EXPECT_LT((out - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());
  std::vector<Convolution> many;
  for (int k = 0; k < 5; ++k) many.emplace_back(kernel, nx, ns, true);  // reallocation moves them
  for (Convolution& c : many) {
    c.Apply(in, out);
    EXPECT_LT((out - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());
  }
}

// The spectral interface: A * u - S * v from two forward and one inverse transform equals the two Applies.
TEST(BemConvolution, SpectralSumOfTwoKernelsEqualsTheSumOfApplies) {
  std::mt19937_64 rng(11);
  const int nx = 15, ns = 22;
  const Eigen::MatrixXd ka = RandomKernel(nx, ns, rng), kb = RandomKernel(nx, ns, rng);
  const Eigen::VectorXd u = RandomField(nx * ns, rng), v = RandomField(nx * ns, rng);
  Convolution a(ka, nx, ns, true), b(kb, nx, ns, true);
  Convolution::Spectrum fu, fv, acc = a.NewSpectrum();
  a.Forward(u, fu);
  b.Forward(v, fv);  // spectra of Convolutions of the same grid are interchangeable
  a.MultiplyAdd(fu, 1.0, acc, true);
  b.MultiplyAdd(fv, -1.0, acc, false);
  Eigen::VectorXd out;
  a.Inverse(acc, out);
  const Eigen::VectorXd exact = Definition(ka, nx, ns, u) - Definition(kb, nx, ns, v);
  EXPECT_LT((out - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());
}

// FFTW's planner is not thread-safe: plan creation and destruction are serialised inside the class. Many threads
// creating, using and destroying convolutions at once must neither crash nor change a bit of the result.
TEST(BemConvolution, ConcurrentUseIsSafeAndDeterministic) {
  std::mt19937_64 rng(7);
  const int nx = 20, ns = 15;
  const Eigen::MatrixXd kernel = RandomKernel(nx, ns, rng);
  const Eigen::VectorXd in = RandomField(nx * ns, rng);
  Eigen::VectorXd serial;
  Convolution(kernel, nx, ns, true).Apply(in, serial);
  std::vector<Eigen::VectorXd> results(8);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < results.size(); ++t)
    threads.emplace_back([&, t]() {
      for (int k = 0; k < 20; ++k) {
        Convolution c(kernel, nx, ns, true);
        c.Apply(in, results[t]);
      }
    });
  for (std::thread& t : threads) t.join();
  for (const Eigen::VectorXd& r : results) EXPECT_EQ(r, serial);
}

}  // namespace
}  // namespace conforma
