// Mass-conserving smoothing of a depth distribution (profile_update.hpp): Whittaker smoother solved
// with CHOLMOD, then clipping of negative values and area-preserving rescaling.
#include <Eigen/SparseCore>
#include <cmath>
#include <string>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/sparse_cholesky.hpp"

namespace conforma {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

DepthSmoothingResult SmoothDepthMassConserving(const WearDistribution& depth, const DepthSmoothingOptions& options) {
  require_non_negative(options.cutoff_wavelength_m, "smoothing cutoff_wavelength_m");
  for (size_t i = 0; i < depth.depth_m.size(); ++i)
    if (!std::isfinite(depth.depth_m[i]) || depth.depth_m[i] < 0.0)
      throw InputError("depth smoothing: depth at node " + std::to_string(i) + " is negative or not finite");
  DepthSmoothingResult out;
  out.depth = depth;
  out.area_in_m2 = depth.area_m2();
  const int n = static_cast<int>(depth.size());
  const double h = depth.spacing_m;
  if (options.cutoff_wavelength_m == 0.0 || n < 3 || out.area_in_m2 <= 0.0) {
    out.area_out_m2 = out.area_in_m2;
    return out;
  }
  // gain 1/2 at the cutoff: 16 lambda sin^4(pi h / Lc) = 1 (for Lc <= 2h the smoother is nearly off)
  const double sine = std::sin(kPi * std::min(0.5, h / options.cutoff_wavelength_m));
  const double lambda = 1.0 / (16.0 * std::pow(sine, 4));
  // A = W + lambda D2^T D2 (pentadiagonal), lower triangle
  std::vector<double> w(n, 1.0);
  w.front() = w.back() = 0.5;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(3 * n);
  std::vector<double> diag(n), off1(n, 0.0), off2(n, 0.0);
  for (int i = 0; i < n; ++i) diag[i] = w[i];
  for (int r = 0; r + 2 < n; ++r) {  // row r of D2: (1, -2, 1) at columns r, r+1, r+2
    const int c[3] = {r, r + 1, r + 2};
    const double v[3] = {1.0, -2.0, 1.0};
    for (int a = 0; a < 3; ++a) {
      diag[c[a]] += lambda * v[a] * v[a];
      for (int b = a + 1; b < 3; ++b) (b - a == 1 ? off1 : off2)[c[a]] += lambda * v[a] * v[b];
    }
  }
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, diag[i]);
    if (i + 1 < n) t.emplace_back(i + 1, i, off1[i]);
    if (i + 2 < n) t.emplace_back(i + 2, i, off2[i]);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  SparseCholesky chol(A);
  if (!chol.ok()) throw std::runtime_error("depth smoothing: smoothing matrix not positive definite");
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) rhs[i] = w[i] * depth.depth_m[i];
  const Eigen::VectorXd f = chol.solve(rhs);
  for (int i = 0; i < n; ++i) {
    if (f[i] < 0.0) ++out.clipped_nodes;
    out.depth.depth_m[i] = std::max(0.0, f[i]);
  }
  const double area_clipped = out.depth.area_m2();
  const double ratio = out.area_in_m2 / area_clipped;
  for (double& v : out.depth.depth_m) v *= ratio;
  out.area_out_m2 = out.depth.area_m2();
  return out;
}

}  // namespace conforma
