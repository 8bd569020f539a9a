// Parametric cubic smoothing spline for noisy profile points, solved with SuiteSparse CHOLMOD (sparse_cholesky.hpp).
// Reinsch (1967) algorithm in the notation of Green & Silverman (1994) §2.3: with knot spacings h_i,
// Q (n x n-2) and R (n-2 x n-2) tridiagonal, the natural smoothing spline has second derivatives gamma at the
// interior knots solving (R + lambda Q^T Q) gamma = Q^T y and values f = y - lambda Q gamma.
#include "profile_smoothing.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <memory>

#include "conforma/error.hpp"
#include "conforma/sparse_cholesky.hpp"

namespace conforma::profile_smoothing {

namespace {

struct Fit {
  std::vector<double> fy, fz, gy, gz;  // values and second derivatives at all knots (natural: 0 at the ends)
  double rms = 0.0;
};

// Smoothing spline with parameter lambda on knots t for the two coordinates.
class SmoothingSystem {
 public:
  SmoothingSystem(const std::vector<double>& t, const std::vector<Eigen::Vector2d>& p, const std::string& source)
      : p_(p), source_(source), n_(t.size()), m_(n_ - 2) {
    h_.resize(n_ - 1);
    for (size_t i = 0; i + 1 < n_; ++i) h_[i] = t[i + 1] - t[i];
    a_.resize(m_); b_.resize(m_); c_.resize(m_);
    for (size_t j = 0; j < m_; ++j) {  // column j of Q (interior knot j+1): rows j, j+1, j+2
      a_[j] = 1.0 / h_[j];
      b_[j] = -1.0 / h_[j] - 1.0 / h_[j + 1];
      c_[j] = 1.0 / h_[j + 1];
    }
  }

  Fit solve(double lambda) const {
    SparseCholesky cholesky(system(lambda));
    if (!cholesky.ok())
      throw InputError(source_, 0, "smoothing: the spline system is not positive definite (points too close?)");
    Eigen::VectorXd by(m_), bz(m_);
    for (size_t j = 0; j < m_; ++j) {  // Q^T y for both coordinates
      by[j] = a_[j] * p_[j].x() + b_[j] * p_[j + 1].x() + c_[j] * p_[j + 2].x();
      bz[j] = a_[j] * p_[j].y() + b_[j] * p_[j + 1].y() + c_[j] * p_[j + 2].y();
    }
    const Eigen::VectorXd xy = cholesky.solve(by), xz = cholesky.solve(bz);
    Fit f;
    f.gy.assign(n_, 0.0);
    f.gz.assign(n_, 0.0);
    for (size_t j = 0; j < m_; ++j) { f.gy[j + 1] = xy[j]; f.gz[j + 1] = xz[j]; }
    // f = y - lambda Q gamma
    f.fy.resize(n_);
    f.fz.resize(n_);
    double sum2 = 0.0;
    for (size_t i = 0; i < n_; ++i) {
      double qy = 0.0, qz = 0.0;
      if (i < m_) { qy += a_[i] * f.gy[i + 1]; qz += a_[i] * f.gz[i + 1]; }
      if (i >= 1 && i - 1 < m_) { qy += b_[i - 1] * f.gy[i]; qz += b_[i - 1] * f.gz[i]; }
      if (i >= 2 && i - 2 < m_) { qy += c_[i - 2] * f.gy[i - 1]; qz += c_[i - 2] * f.gz[i - 1]; }
      f.fy[i] = p_[i].x() - lambda * qy;
      f.fz[i] = p_[i].y() - lambda * qz;
      sum2 += (p_[i] - Eigen::Vector2d(f.fy[i], f.fz[i])).squaredNorm();
    }
    f.rms = std::sqrt(sum2 / n_);
    return f;
  }

 private:
  // R + lambda Q^T Q (pentadiagonal; lower triangle, which is all SparseCholesky reads)
  Eigen::SparseMatrix<double> system(double lambda) const {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(3 * m_);
    for (size_t j = 0; j < m_; ++j) {
      const int r = static_cast<int>(j);
      entries.emplace_back(r, r, (h_[j] + h_[j + 1]) / 3.0 + lambda * (a_[j] * a_[j] + b_[j] * b_[j] + c_[j] * c_[j]));
      if (j + 1 < m_) entries.emplace_back(r + 1, r, h_[j + 1] / 6.0 + lambda * (b_[j] * a_[j + 1] + c_[j] * b_[j + 1]));
      if (j + 2 < m_) entries.emplace_back(r + 2, r, lambda * c_[j] * a_[j + 2]);
    }
    Eigen::SparseMatrix<double> A(static_cast<int>(m_), static_cast<int>(m_));
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
  }
  const std::vector<Eigen::Vector2d>& p_;
  std::string source_;
  size_t n_, m_;
  std::vector<double> h_, a_, b_, c_;
};

double eval_spline(const std::vector<double>& t, const std::vector<double>& f, const std::vector<double>& g, double x) {
  size_t i = std::upper_bound(t.begin(), t.end(), x) - t.begin();
  i = std::clamp<size_t>(i, 1, t.size() - 1) - 1;
  const double h = t[i + 1] - t[i], a = (t[i + 1] - x) / h, b = (x - t[i]) / h;
  return a * f[i] + b * f[i + 1] + ((a * a * a - a) * g[i] + (b * b * b - b) * g[i + 1]) * h * h / 6.0;
}

}  // namespace

std::vector<Eigen::Vector2d> smooth(const std::vector<Eigen::Vector2d>& p, double rms_m, double spacing_m,
                                    const std::string& source) {
  const size_t n = p.size();
  if (n < 4) throw InputError(source, 0, "smoothing needs at least 4 points");
  // knots: chord length of the points (pass 1), then of the smoothed values (pass 2); a floor on the increments
  // keeps the system well conditioned where noisy duplicates nearly coincide after smoothing
  std::vector<double> t(n, 0.0);
  for (size_t i = 1; i < n; ++i) t[i] = t[i - 1] + (p[i] - p[i - 1]).norm();
  Fit fit;
  for (int pass = 0; pass < 2; ++pass) {
    const double floor = 1e-3 * t.back() / (n - 1);
    for (size_t i = 1; i < n; ++i) t[i] = std::max(t[i], t[i - 1] + floor);
    SmoothingSystem sys(t, p, source);
    // lambda [m^3] by bisection on log10 so that the RMS residual equals rms_m (it grows with lambda)
    double lo = -30.0, hi = 3.0;
    fit = sys.solve(std::pow(10.0, hi));
    if (fit.rms > rms_m) {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (sys.solve(std::pow(10.0, mid)).rms > rms_m) hi = mid; else lo = mid;
      }
      fit = sys.solve(std::pow(10.0, lo));
    }
    if (pass == 0)
      for (size_t i = 1; i < n; ++i)
        t[i] = t[i - 1] + std::hypot(fit.fy[i] - fit.fy[i - 1], fit.fz[i] - fit.fz[i - 1]);
  }
  const int m = std::max(4, static_cast<int>(std::ceil(t.back() / spacing_m)) + 1);
  std::vector<Eigen::Vector2d> out(m);
  for (int k = 0; k < m; ++k) {
    const double x = t.back() * k / (m - 1);
    out[k] = {eval_spline(t, fit.fy, fit.gy, x), eval_spline(t, fit.fz, fit.gz, x)};
  }
  return out;
}

}  // namespace conforma::profile_smoothing
