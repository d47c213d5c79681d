#pragma once
// Internal: a single-precision copy of a sparse LDLᵀ factor, grouped into supernodes, applied as
// the conjugate-gradient preconditioner of the Ricci flow's Newton systems.
//
// The triangular solves are bound by memory traffic. A simplicial copy reads a row index with
// every value; here consecutive columns with the same pattern below their diagonal block (a
// fundamental supernode: about 90% of the entries at 100k unknowns sit in supernodes two or
// more columns wide, 70% in ones eight or more wide) share one list of row indices, and their
// values are stored as a dense triangle and a dense row-major block.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace confvis::conformal::detail {

// L in the layout of Eigen's simplicial factors: strictly lower triangular, column-major, column
// j's row indices sorted in rows[start[j] .. start[j] + count[j]), unit diagonal implied.
struct StrictlyLowerFactor {
  int size = 0;
  const int* start = nullptr;
  const int* count = nullptr;
  const int* rows = nullptr;
  const double* values = nullptr;
  const double* diagonal = nullptr;  // D
  const int* parent = nullptr;       // elimination tree, -1 at roots
};

class SupernodalPreconditioner {
 public:
  void build(const StrictlyLowerFactor& factor);
  // z = (L D Lᵀ)⁻¹ r, to single precision in L.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

  int supernodeCount() const { return static_cast<int>(supernodes_.size()); }
  int widestSupernode() const { return widest_; }

 private:
  struct Supernode {
    int firstColumn = 0, width = 0;
    int rowBegin = 0, rowEnd = 0;  // the rows below the diagonal block, in rows_
    std::size_t triangle = 0;      // in values_: strictly lower diagonal block, packed by columns
    std::size_t below = 0;         // in values_: (rowEnd - rowBegin) × width, row-major
  };
  std::vector<Supernode> supernodes_;
  std::vector<int> rows_;
  std::vector<float> values_;
  std::vector<double> inverseDiagonal_;
  int widest_ = 0;
  mutable std::vector<double> scratch_;
};

}  // namespace confvis::conformal::detail
