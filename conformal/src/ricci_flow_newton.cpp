#include "ricci_flow_newton.hpp"

#include <Eigen/OrderingMethods>

#include <algorithm>

#include "confvis/base/error.hpp"

namespace confvis::conformal::detail {
namespace {

// Corner pairs of a face in the order of NewtonSystem::slots_.
constexpr std::array<std::array<int, 2>, 6> kCornerPairs{
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

// Symmetric pattern (both triangles and the diagonal) of the vertex adjacency, over unknowns.
SparseMatrix symmetricPattern(const IntrinsicTriangulation& tri, const std::vector<int>& unknown,
                              int n) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(2 * tri.edgeCount() + n);
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 1.0);
  for (const auto& ev : tri.edgeVertices) {
    const int a = unknown[ev[0]], b = unknown[ev[1]];
    if (a < 0 || b < 0 || a == b) continue;
    entries.emplace_back(a, b, 1.0);
    entries.emplace_back(b, a, 1.0);
  }
  SparseMatrix pattern(n, n);
  pattern.setFromTriplets(entries.begin(), entries.end());
  return pattern;
}

}  // namespace

NewtonSystem::NewtonSystem(const IntrinsicTriangulation& tri, int pinnedVertex) {
  unknown_.assign(tri.vertexCount, -1);
  n_ = 0;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (v != pinnedVertex) unknown_[v] = n_++;
  // AMD returns the elimination order (position → unknown); number the unknowns by it.
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(symmetricPattern(tri, unknown_, n_), order);
  if (order.size() == n_) {
    std::vector<int> position(n_);
    for (int k = 0; k < n_; ++k) position[order.indices()[k]] = k;
    for (int& u : unknown_)
      if (u >= 0) u = position[u];
  }
  rebuildPattern(tri);
}

void NewtonSystem::rebuildPattern(const IntrinsicTriangulation& tri) {
  // Upper triangle, column-major: entry (row, col) with row ≤ col, the diagonal always present.
  // Counting sort of the edges by column, then sort and deduplicate each (short) column.
  std::vector<int> outer(n_ + 1, 0);
  for (int k = 0; k < n_; ++k) outer[k + 1] = 1;
  for (const auto& ev : tri.edgeVertices) {
    const int a = unknown_[ev[0]], b = unknown_[ev[1]];
    if (a >= 0 && b >= 0 && a != b) ++outer[std::max(a, b) + 1];
  }
  for (int k = 0; k < n_; ++k) outer[k + 1] += outer[k];
  std::vector<int> inner(outer[n_]);
  std::vector<int> fill(outer.begin(), outer.end() - 1);
  for (int k = 0; k < n_; ++k) inner[fill[k]++] = k;
  for (const auto& ev : tri.edgeVertices) {
    const int a = unknown_[ev[0]], b = unknown_[ev[1]];
    if (a >= 0 && b >= 0 && a != b) inner[fill[std::max(a, b)]++] = std::min(a, b);
  }
  int nonZeros = 0;
  for (int k = 0; k < n_; ++k) {
    int* begin = inner.data() + outer[k];
    int* end = inner.data() + outer[k + 1];
    std::sort(begin, end);
    end = std::unique(begin, end);  // intrinsic triangulations may have multi-edges
    const int start = nonZeros;
    for (int* it = begin; it != end; ++it) inner[nonZeros++] = *it;
    outer[k] = start;
  }
  outer[n_] = nonZeros;
  H_ = SparseMatrix(n_, n_);
  H_.resizeNonZeros(nonZeros);
  std::copy(outer.begin(), outer.end(), H_.outerIndexPtr());
  std::copy(inner.begin(), inner.begin() + nonZeros, H_.innerIndexPtr());
  std::fill(H_.valuePtr(), H_.valuePtr() + nonZeros, 0.0);

  const int* rows = H_.innerIndexPtr();
  auto slotOf = [&](int row, int col) {
    for (int p = outer[col]; p < outer[col + 1]; ++p)
      if (rows[p] == row) return p;
    throw Error(ErrorCode::Internal, "Hessian pattern misses an entry");
  };
  slots_.resize(tri.faceCount());
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int p = 0; p < 6; ++p) {
      const int ra = unknown_[tri.faceVertices[f][kCornerPairs[p][0]]];
      const int rb = unknown_[tri.faceVertices[f][kCornerPairs[p][1]]];
      slots_[f][p] = (ra < 0 || rb < 0) ? -1 : slotOf(std::min(ra, rb), std::max(ra, rb));
    }
}

void NewtonSystem::assemble(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                            std::vector<double>& weights) {
  double* values = H_.valuePtr();
  std::fill(values, values + H_.nonZeros(), 0.0);
  weights.assign(tri.edgeCount(), 0.0);
  std::array<std::array<double, 3>, 3> J;
  for (int f = 0; f < tri.faceCount(); ++f) {
    faceAngleJacobian(tri, eval, f, J);
    const auto& fv = tri.faceVertices[f];
    const auto& fe = tri.faceEdges[f];
    for (int c = 0; c < 3; ++c) weights[fe[c]] += J[(c + 1) % 3][(c + 2) % 3];
    for (int p = 0; p < 6; ++p) {
      const int slot = slots_[f][p];
      if (slot < 0) continue;
      const int a = kCornerPairs[p][0], b = kCornerPairs[p][1];
      // K = 2π - Σθ. An off-diagonal pair whose corners are the same vertex (possible in an
      // intrinsic triangulation) lands on the diagonal from both sides.
      const double weight = (a != b && fv[a] == fv[b]) ? 1.0 : 0.5;
      values[slot] -= weight * (J[a][b] + J[b][a]);
    }
  }
}

void NewtonSystem::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.setZero(n_);
  const int* outer = H_.outerIndexPtr();
  const int* inner = H_.innerIndexPtr();
  const double* values = H_.valuePtr();
  for (int col = 0; col < n_; ++col) {
    double sum = 0;
    const double xc = x[col];
    for (int p = outer[col]; p < outer[col + 1]; ++p) {
      const int row = inner[p];
      sum += values[p] * x[row];
      if (row != col) y[row] += values[p] * xc;
    }
    y[col] += sum;
  }
}

double PreorderedLDLT::factorizationFlops() const {
  double flops = 0;
  for (Eigen::Index k = 0; k < m_nonZerosPerCol.size(); ++k) {
    const double c = m_nonZerosPerCol[k];
    flops += c * (c + 3);
  }
  return flops;
}

double PreorderedLDLT::solveFlops() const {
  double nonZeros = 0;
  for (Eigen::Index k = 0; k < m_nonZerosPerCol.size(); ++k) nonZeros += m_nonZerosPerCol[k];
  return 4 * nonZeros + static_cast<double>(m_nonZerosPerCol.size());
}

CgResult preconditionedCg(const NewtonSystem& system, const PreorderedLDLT& factor,
                          const Eigen::VectorXd& b, double tolerance, int maxIterations,
                          Eigen::VectorXd& delta) {
  CgResult result;
  delta.setZero(b.size());
  const double bNorm = b.norm();
  if (bNorm == 0) {
    result.converged = true;
    return result;
  }
  Eigen::VectorXd r = b, z(b.size()), p, q(b.size());
  z = factor.solve(r);
  double rz = r.dot(z);
  if (!(rz > 0)) return result;
  p = z;
  const double target = tolerance * bNorm;
  while (result.iterations < maxIterations) {
    ++result.iterations;
    system.multiply(p, q);
    const double pq = p.dot(q);
    if (!(pq > 0)) return result;  // H is not positive definite along p
    const double alpha = rz / pq;
    delta += alpha * p;
    r -= alpha * q;
    const double rNorm = r.norm();
    result.reduction = rNorm / bNorm;
    if (rNorm <= target) {
      result.converged = true;
      return result;
    }
    z = factor.solve(r);
    const double rzNext = r.dot(z);
    if (!(rzNext > 0)) return result;  // the frozen factor is not positive definite
    p = z + (rzNext / rz) * p;
    rz = rzNext;
  }
  return result;
}

}  // namespace confvis::conformal::detail
