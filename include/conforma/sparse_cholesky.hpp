#pragma once
// Sparse symmetric positive definite solves with SuiteSparse CHOLMOD (simplicial LL^T Cholesky,
// fill-reducing ordering chosen by CHOLMOD). A thin RAII owner of the CHOLMOD workspace and factor:
// CHOLMOD types stay in the .cpp, so users of this header need neither cholmod.h nor its include path.
//
// Thread safety: every instance owns its own cholmod_common, so different instances may be used from
// different threads at the same time; one instance must not be used by two threads at once.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace conforma {

class SparseCholesky {
 public:
  // Factorises the symmetric matrix A (only its lower triangle is read; A must be square).
  // Throws InputError if A is not square or has non-finite entries. A matrix that is not positive
  // definite is not an exception: ok() is false and solve() throws std::logic_error.
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  bool ok() const;     // factorisation succeeded (A positive definite)
  int rows() const;
  // x = A^{-1} b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace conforma
