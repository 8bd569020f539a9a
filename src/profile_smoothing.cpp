// Parametric cubic smoothing spline for noisy profile points, solved with SuiteSparse CHOLMOD.
// Reinsch (1967) algorithm in the notation of Green & Silverman (1994) §2.3: with knot spacings h_i,
// Q (n x n-2) and R (n-2 x n-2) tridiagonal, the natural smoothing spline has second derivatives gamma at the
// interior knots solving (R + lambda Q^T Q) gamma = Q^T y and values f = y - lambda Q gamma.
#include "profile_smoothing.hpp"

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "conforma/error.hpp"

namespace conforma::profile_smoothing {

namespace {

// Owns a cholmod_common and the objects allocated with it.
class Cholmod {
 public:
  Cholmod() { cholmod_start(&c_); c_.print = 0; }
  ~Cholmod() {
    if (L_) cholmod_free_factor(&L_, &c_);
    if (A_) cholmod_free_sparse(&A_, &c_);
    cholmod_finish(&c_);
  }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;
  cholmod_common c_;
  cholmod_sparse* A_ = nullptr;
  cholmod_factor* L_ = nullptr;
};

struct Fit {
  std::vector<double> fy, fz, gy, gz;  // values and second derivatives at all knots (natural: 0 at the ends)
  double rms = 0.0;
};

// Smoothing spline with parameter lambda on knots t for the two coordinates.
class SmoothingSystem {
 public:
  SmoothingSystem(const std::vector<double>& t, const std::vector<Eigen::Vector2d>& p, const std::string& source)
      : t_(t), p_(p), source_(source), n_(t.size()), m_(n_ - 2) {
    h_.resize(n_ - 1);
    for (size_t i = 0; i + 1 < n_; ++i) h_[i] = t[i + 1] - t[i];
    a_.resize(m_); b_.resize(m_); c_.resize(m_);
    for (size_t j = 0; j < m_; ++j) {  // column j of Q (interior knot j+1): rows j, j+1, j+2
      a_[j] = 1.0 / h_[j];
      b_[j] = -1.0 / h_[j] - 1.0 / h_[j + 1];
      c_[j] = 1.0 / h_[j + 1];
    }
    // lower triangle of the pentadiagonal matrix, column-major: rows j, j+1, j+2
    const size_t nnz = 3 * m_;
    cm_.A_ = cholmod_allocate_sparse(m_, m_, nnz, 1, 1, -1, CHOLMOD_REAL, &cm_.c_);
    if (!cm_.A_) throw InputError(source_, 0, "smoothing: CHOLMOD could not allocate the matrix");
    auto* Ap = static_cast<int*>(cm_.A_->p);
    auto* Ai = static_cast<int*>(cm_.A_->i);
    int k = 0;
    for (size_t j = 0; j < m_; ++j) {
      Ap[j] = k;
      for (size_t r = j; r <= std::min(j + 2, m_ - 1); ++r) Ai[k++] = static_cast<int>(r);
    }
    Ap[m_] = k;
    fill(1.0);
    cm_.L_ = cholmod_analyze(cm_.A_, &cm_.c_);
    if (!cm_.L_) throw InputError(source_, 0, "smoothing: CHOLMOD analysis failed");
  }

  Fit solve(double lambda) {
    fill(lambda);
    cholmod_factorize(cm_.A_, cm_.L_, &cm_.c_);
    if (cm_.c_.status != CHOLMOD_OK)
      throw InputError(source_, 0, "smoothing: the spline system is not positive definite (points too close?)");
    cholmod_dense* B = cholmod_allocate_dense(m_, 2, m_, CHOLMOD_REAL, &cm_.c_);
    auto* bx = static_cast<double*>(B->x);
    for (size_t j = 0; j < m_; ++j) {  // Q^T y for both coordinates
      bx[j] = a_[j] * p_[j].x() + b_[j] * p_[j + 1].x() + c_[j] * p_[j + 2].x();
      bx[m_ + j] = a_[j] * p_[j].y() + b_[j] * p_[j + 1].y() + c_[j] * p_[j + 2].y();
    }
    cholmod_dense* X = cholmod_solve(CHOLMOD_A, cm_.L_, B, &cm_.c_);
    cholmod_free_dense(&B, &cm_.c_);
    if (!X) throw InputError(source_, 0, "smoothing: CHOLMOD solve failed");
    const auto* x = static_cast<const double*>(X->x);
    Fit f;
    f.gy.assign(n_, 0.0);
    f.gz.assign(n_, 0.0);
    for (size_t j = 0; j < m_; ++j) { f.gy[j + 1] = x[j]; f.gz[j + 1] = x[m_ + j]; }
    cholmod_free_dense(&X, &cm_.c_);
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
  void fill(double lambda) {  // R + lambda Q^T Q
    auto* Ax = static_cast<double*>(cm_.A_->x);
    int k = 0;
    for (size_t j = 0; j < m_; ++j) {
      Ax[k++] = (h_[j] + h_[j + 1]) / 3.0 + lambda * (a_[j] * a_[j] + b_[j] * b_[j] + c_[j] * c_[j]);
      if (j + 1 < m_) Ax[k++] = h_[j + 1] / 6.0 + lambda * (b_[j] * a_[j + 1] + c_[j] * b_[j + 1]);
      if (j + 2 < m_) Ax[k++] = lambda * c_[j] * a_[j + 2];
    }
  }
  const std::vector<double>& t_;
  const std::vector<Eigen::Vector2d>& p_;
  std::string source_;
  size_t n_, m_;
  std::vector<double> h_, a_, b_, c_;
  Cholmod cm_;
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
