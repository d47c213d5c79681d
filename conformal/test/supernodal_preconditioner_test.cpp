// The supernodal single-precision copy of the flow's LDLᵀ factor must apply the same inverse as
// the double-precision factor it was made from, to single precision.
#include "../src/supernodal_preconditioner.hpp"

#include <gtest/gtest.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <vector>

#include "../src/ricci_flow_newton.hpp"

using namespace confvis::conformal::detail;

namespace {

// Upper triangle of P A Pᵀ, with A the 5-point Laplacian of an n × n grid plus `shift` on the
// diagonal and P Eigen's AMD order: the layout the flow hands to PreorderedLDLT, with the
// supernodes AMD produces on a 2D mesh.
SparseMatrix amdOrderedGridLaplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      t.emplace_back(id(i, j), id(i, j), 4 + shift);
      if (i + 1 < n) t.emplace_back(id(i, j), id(i + 1, j), -1), t.emplace_back(id(i + 1, j), id(i, j), -1);
      if (j + 1 < n) t.emplace_back(id(i, j), id(i, j + 1), -1), t.emplace_back(id(i, j + 1), id(i, j), -1);
    }
  SparseMatrix A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(A, order);
  SparseMatrix permuted;
  permuted = A.twistedBy(order.inverse());
  return permuted.triangularView<Eigen::Upper>();
}

TEST(SupernodalPreconditioner, AppliesTheFactorsInverseToSinglePrecision) {
  const SparseMatrix upper = amdOrderedGridLaplacian(40, 1e-3);
  PreorderedLDLT factor;
  factor.analyze(upper);
  factor.factorizeValues(upper);
  ASSERT_EQ(factor.info(), Eigen::Success);
  factor.preparePreconditioner();
  const auto& preconditioner = factor.preconditioner();
  // AMD on a grid leaves wide supernodes near the top of the elimination tree: the dense
  // (triangle + block) path is exercised, not only single columns.
  EXPECT_GT(preconditioner.widestSupernode(), 8);
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd r = Eigen::VectorXd::Random(upper.rows());
    const Eigen::VectorXd exact = factor.solve(r);
    Eigen::VectorXd z;
    factor.applyPreconditioner(r, z);
    // Condition number ~600 (eigenvalues 0.013 .. 8): single-precision entries of L leave a
    // relative error of at most ~1e-7 × 600; a misplaced entry would leave one near 1.
    EXPECT_LT((z - exact).norm(), 1e-4 * exact.norm()) << "trial " << trial;
  }
}

}  // namespace
