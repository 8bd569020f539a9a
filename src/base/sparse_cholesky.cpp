#include "conforma/sparse_cholesky.hpp"

#include <cholmod.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "conforma/error.hpp"

namespace conforma {

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_sparse* matrix = nullptr;
  cholmod_factor* factor = nullptr;
  int n = 0;
  bool ok = false;

  Impl() {
    cholmod_start(&common);
    common.print = 0;          // no console output from CHOLMOD
    common.error_handler = nullptr;
    // Simplicial factorisation: no BLAS calls, so results do not depend on the BLAS thread count (the
    // banded smoothing systems gain nothing from supernodes).
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.final_ll = 1;       // LL^T: a matrix that is not positive definite is reported (LDL^T would pass)
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    if (matrix) cholmod_free_sparse(&matrix, &common);
    cholmod_finish(&common);
  }
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A) : impl_(std::make_unique<Impl>()) {
  if (A.rows() != A.cols())
    throw InputError("SparseCholesky: matrix must be square, got " + std::to_string(A.rows()) + " x " +
                     std::to_string(A.cols()));
  Impl& m = *impl_;
  m.n = static_cast<int>(A.rows());
  // Lower triangle in compressed-column form (CHOLMOD stype = -1).
  size_t nnz = 0;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
      if (it.row() >= it.col()) {
        if (!std::isfinite(it.value())) throw InputError("SparseCholesky: matrix entry is not finite");
        ++nnz;
      }
  cholmod_triplet* t = cholmod_allocate_triplet(m.n, m.n, nnz, -1, CHOLMOD_REAL, &m.common);
  if (!t) throw std::runtime_error("SparseCholesky: CHOLMOD could not allocate the matrix");
  int* ti = static_cast<int*>(t->i);
  int* tj = static_cast<int*>(t->j);
  double* tx = static_cast<double*>(t->x);
  size_t e = 0;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
      if (it.row() >= it.col()) {
        ti[e] = static_cast<int>(it.row());
        tj[e] = static_cast<int>(it.col());
        tx[e] = it.value();
        ++e;
      }
  t->nnz = e;
  m.matrix = cholmod_triplet_to_sparse(t, e, &m.common);
  cholmod_free_triplet(&t, &m.common);
  if (!m.matrix) throw std::runtime_error("SparseCholesky: CHOLMOD could not convert the matrix");
  m.factor = cholmod_analyze(m.matrix, &m.common);
  if (!m.factor) return;
  cholmod_factorize(m.matrix, m.factor, &m.common);
  m.ok = m.common.status == CHOLMOD_OK && m.factor->minor == m.factor->n;
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

bool SparseCholesky::ok() const { return impl_ && impl_->ok; }
int SparseCholesky::rows() const { return impl_ ? impl_->n : 0; }

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) {
  if (!ok()) throw std::logic_error("SparseCholesky::solve: the matrix is not positive definite");
  Impl& m = *impl_;
  if (b.size() != m.n) throw InputError("SparseCholesky::solve: right-hand side has the wrong size");
  cholmod_dense* rhs = cholmod_allocate_dense(m.n, 1, m.n, CHOLMOD_REAL, &m.common);
  if (!rhs) throw std::runtime_error("SparseCholesky: CHOLMOD could not allocate the right-hand side");
  double* r = static_cast<double*>(rhs->x);
  for (int i = 0; i < m.n; ++i) r[i] = b[i];
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, m.factor, rhs, &m.common);
  cholmod_free_dense(&rhs, &m.common);
  if (!x) throw std::runtime_error("SparseCholesky: CHOLMOD solve failed");
  Eigen::VectorXd out(m.n);
  const double* xv = static_cast<const double*>(x->x);
  for (int i = 0; i < m.n; ++i) out[i] = xv[i];
  cholmod_free_dense(&x, &m.common);
  return out;
}

}  // namespace conforma
