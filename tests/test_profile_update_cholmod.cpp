// The CHOLMOD wrapper used by the mass-conserving smoothing: solves against a dense Eigen reference,
// reports a matrix that is not positive definite.
// test-links: base  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <random>

#include "conforma/error.hpp"
#include "conforma/sparse_cholesky.hpp"

using namespace conforma;

TEST(SparseCholesky, SolvesAnSpdBandSystemLikeDenseLlt) {
  const int n = 300;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {  // 1 + lambda D2^T D2-like pentadiagonal, both triangles given
    t.emplace_back(i, i, 7.0 + 0.01 * i);
    if (i + 1 < n) { t.emplace_back(i + 1, i, -4.0); t.emplace_back(i, i + 1, -4.0); }
    if (i + 2 < n) { t.emplace_back(i + 2, i, 1.0); t.emplace_back(i, i + 2, 1.0); }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = g(rng);
  SparseCholesky chol(A);
  ASSERT_TRUE(chol.ok());
  EXPECT_EQ(chol.rows(), n);
  const Eigen::VectorXd x = chol.solve(b);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  const Eigen::VectorXd ref = dense.llt().solve(b);
  EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm());
  EXPECT_LT((dense * x - b).norm(), 1e-10 * b.norm());
  // moved-from and moved-to objects behave
  SparseCholesky moved(std::move(chol));
  EXPECT_LT((moved.solve(b) - ref).norm(), 1e-10 * ref.norm());
}

TEST(SparseCholesky, IndefiniteAndBadInput) {
  Eigen::SparseMatrix<double> A(3, 3);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = -2.0;
  A.insert(2, 2) = 1.0;
  SparseCholesky chol(A);
  EXPECT_FALSE(chol.ok());
  EXPECT_THROW(chol.solve(Eigen::VectorXd::Ones(3)), std::logic_error);
  Eigen::SparseMatrix<double> rect(3, 2);
  EXPECT_THROW(SparseCholesky{rect}, InputError);
}
