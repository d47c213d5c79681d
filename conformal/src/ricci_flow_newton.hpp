#pragma once
// Internal: the Newton system of the Ricci flow and its solver. The unknowns are numbered once,
// in a fill-reducing (AMD) elimination order, so the Hessian is assembled directly in that
// order and factorised without any permutation; edge flips change the pattern but keep the
// numbering. The solver factorises rarely: between factorisations each Newton system is solved
// by conjugate gradients preconditioned with the last factor (a "frozen" LDLᵀ), which costs two
// triangular solves per step instead of a factorisation.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

#include "metric_evaluation.hpp"
#include "supernodal_preconditioner.hpp"

namespace confvis::conformal::detail {

using SparseMatrix = Eigen::SparseMatrix<double>;

class NewtonSystem {
 public:
  // Numbers the vertices other than `pinnedVertex` (-1: none) by AMD on the current pattern.
  NewtonSystem(const IntrinsicTriangulation& tri, int pinnedVertex);

  // H = ∂K/∂u at `eval` as one symmetric 3×3 block per face, for any connectivity (edge flips
  // need no new pattern), and per edge the Delaunay weight (see edgeWeights) as a by-product.
  void assemble(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                std::vector<double>& weights);
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;  // y = H x, from the blocks

  // The assembled H as an upper-triangular, column-major matrix in elimination order, for a
  // factorisation. Its pattern is rebuilt after invalidatePattern() (edges flipped).
  const SparseMatrix& upper(const IntrinsicTriangulation& tri);
  void invalidatePattern() { patternValid_ = false; }

  int unknownOf(int v) const { return unknown_[v]; }
  int size() const { return n_; }

 private:
  void buildPattern(const IntrinsicTriangulation& tri);

  std::vector<int> unknown_;
  int n_ = 0;
  // Per face: the corners' unknowns (n_ for the pinned vertex) and the block entries
  // (0,0) (1,1) (2,2) (0,1) (1,2) (2,0).
  std::vector<std::array<int, 3>> faceUnknowns_;
  std::vector<std::array<double, 6>> blocks_;
  SparseMatrix H_;
  std::vector<std::array<int, 6>> slots_;  // per face block entry, its place in H_ (-1: none)
  bool patternValid_ = false;
  mutable Eigen::VectorXd xPadded_, yPadded_;  // x and y with a zero slot for the pinned vertex
};

// Eigen's simplicial LDLᵀ fed a matrix already in elimination order: no ordering, no copy.
class PreorderedLDLT
    : public Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> {
 public:
  void analyze(const SparseMatrix& upper) { analyzePattern_preordered(upper, true); }
  void factorizeValues(const SparseMatrix& upper) { factorize_preordered<true>(upper); }
  // Floating-point work of one numeric factorisation and of one solve, from the column
  // counts of L: used to weigh conjugate-gradient steps against a fresh factorisation.
  double factorizationFlops() const;
  double solveFlops() const;
  double factorNonZeros() const;  // of L, after analyze()

  // z = (L D Lᵀ)⁻¹ r with a single-precision, supernodal copy of L: the triangular solves are
  // bound by memory traffic, and CG needs no more accuracy from a preconditioner. Dropping
  // small entries of L was measured too: half the entries at 1e-3, but twice the CG steps.
  void preparePreconditioner();
  void applyPreconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    preconditioner_.apply(r, z);
  }
  const SupernodalPreconditioner& preconditioner() const { return preconditioner_; }

 private:
  SupernodalPreconditioner preconditioner_;
};

// Solves H δ = b to relative residual `tolerance` (2-norm) by conjugate gradients
// preconditioned with `factor`, starting from δ = 0. Stops early (converged = false) after
// `maxIterations` steps or when H or the preconditioner turn out not positive definite.
struct CgResult {
  int iterations = 0;
  bool converged = false;
  double reduction = 1;  // final over initial residual norm
};
CgResult preconditionedCg(const NewtonSystem& system, const PreorderedLDLT& factor,
                          const Eigen::VectorXd& b, double tolerance, int maxIterations,
                          Eigen::VectorXd& delta);

}  // namespace confvis::conformal::detail
