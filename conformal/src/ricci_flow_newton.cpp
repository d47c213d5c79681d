#include "ricci_flow_newton.hpp"

#include <Eigen/OrderingMethods>

#include <algorithm>

#include "confvis/base/error.hpp"
#include "ricci_flow_parallel.hpp"

namespace confvis::conformal::detail {
namespace {

// Corner pairs of a face in the order of NewtonSystem::slots_.
constexpr std::array<std::array<int, 2>, 6> kCornerPairs{
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

// Compressed columns of a pattern given as (row, column) pairs: sorted, duplicates merged.
void compressPattern(int n, const std::vector<std::array<int, 2>>& entries, std::vector<int>& outer,
                     std::vector<int>& inner) {
  outer.assign(n + 1, 0);
  for (const auto& rc : entries) ++outer[rc[1] + 1];
  for (int k = 0; k < n; ++k) outer[k + 1] += outer[k];
  inner.resize(entries.size());
  std::vector<int> fill(outer.begin(), outer.end() - 1);
  for (const auto& rc : entries) inner[fill[rc[1]]++] = rc[0];
  int nonZeros = 0;
  for (int k = 0; k < n; ++k) {
    int* begin = inner.data() + outer[k];
    int* end = inner.data() + outer[k + 1];
    std::sort(begin, end);
    end = std::unique(begin, end);  // intrinsic triangulations may have multi-edges
    const int start = nonZeros;
    for (int* it = begin; it != end; ++it) inner[nonZeros++] = *it;
    outer[k] = start;
  }
  outer[n] = nonZeros;
  inner.resize(nonZeros);
}

// Pattern of the Hessian over the unknowns: both triangles (`upperOnly` false) or the upper one,
// with the diagonal, as a compressed column-major matrix of zeros.
SparseMatrix hessianPattern(const IntrinsicTriangulation& tri, const std::vector<int>& unknown,
                            int n, bool upperOnly) {
  std::vector<std::array<int, 2>> entries;
  entries.reserve(n + (upperOnly ? 1 : 2) * tri.edgeCount());
  for (int k = 0; k < n; ++k) entries.push_back({k, k});
  for (const auto& ev : tri.edgeVertices) {
    const int a = unknown[ev[0]], b = unknown[ev[1]];
    if (a < 0 || b < 0 || a == b) continue;
    entries.push_back({std::min(a, b), std::max(a, b)});
    if (!upperOnly) entries.push_back({std::max(a, b), std::min(a, b)});
  }
  std::vector<int> outer, inner;
  compressPattern(n, entries, outer, inner);
  SparseMatrix pattern(n, n);
  pattern.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern.innerIndexPtr());
  std::fill(pattern.valuePtr(), pattern.valuePtr() + inner.size(), 0.0);
  return pattern;
}

}  // namespace

NewtonSystem::NewtonSystem(const IntrinsicTriangulation& tri, int pinnedVertex) {
  unknown_.assign(tri.vertexCount, -1);
  n_ = 0;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (v != pinnedVertex) unknown_[v] = n_++;
  // AMD (Eigen's, on the full symmetric pattern as its SimplicialLDLT would build it) returns
  // the elimination order, position → unknown; number the unknowns by it.
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  {
    SparseMatrix symmetric = hessianPattern(tri, unknown_, n_, false);
    Eigen::internal::minimum_degree_ordering(symmetric, order);
  }
  if (order.size() >= n_) {
    std::vector<int> position(n_);
    for (int k = 0; k < n_; ++k) position[order.indices()[k]] = k;
    for (int& u : unknown_)
      if (u >= 0) u = position[u];
  }
}

void NewtonSystem::buildPattern(const IntrinsicTriangulation& tri) {
  H_ = hessianPattern(tri, unknown_, n_, true);
  const int* outer = H_.outerIndexPtr();
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
  patternValid_ = true;
}

void NewtonSystem::assemble(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                            std::vector<double>& weights) {
  const int faces = tri.faceCount();
  faceUnknowns_.resize(faces);
  blocks_.resize(faces);
  parallelFor(faces, [&](int begin, int end, int) {
    std::array<std::array<double, 3>, 3> J;
    for (int f = begin; f < end; ++f) {
      faceAngleJacobian(tri, eval, f, J);
      const auto& fv = tri.faceVertices[f];
      for (int c = 0; c < 3; ++c) {
        const int k = unknown_[fv[c]];
        faceUnknowns_[f][c] = k < 0 ? n_ : k;
      }
      for (int p = 0; p < 6; ++p) {  // K = 2π - Σθ
        const int a = kCornerPairs[p][0], b = kCornerPairs[p][1];
        blocks_[f][p] = -0.5 * (J[a][b] + J[b][a]);
      }
    }
  });
  // Edge weights from the blocks: the pair opposite corner c is entry 3 + (c + 1) % 3.
  weights.resize(tri.edgeCount());
  parallelFor(tri.edgeCount(), [&](int begin, int end, int) {
    for (int e = begin; e < end; ++e) {
      double weight = 0;
      for (int f : tri.edgeFaces[e])
        if (f >= 0) weight -= blocks_[f][3 + (tri.cornerOpposite(f, e) + 1) % 3];
      weights[e] = weight;
    }
  });
}

void NewtonSystem::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  xPadded_.resize(n_ + 1);
  xPadded_.head(n_) = x;
  xPadded_[n_] = 0;
  yPadded_.setZero(n_ + 1);
  const double* in = xPadded_.data();
  double* out = yPadded_.data();
  for (std::size_t f = 0; f < blocks_.size(); ++f) {
    const auto& k = faceUnknowns_[f];
    const auto& h = blocks_[f];
    const double x0 = in[k[0]], x1 = in[k[1]], x2 = in[k[2]];
    out[k[0]] += h[0] * x0 + h[3] * x1 + h[5] * x2;
    out[k[1]] += h[3] * x0 + h[1] * x1 + h[4] * x2;
    out[k[2]] += h[5] * x0 + h[4] * x1 + h[2] * x2;
  }
  y = yPadded_.head(n_);
}

const SparseMatrix& NewtonSystem::upper(const IntrinsicTriangulation& tri) {
  if (!patternValid_) buildPattern(tri);
  double* values = H_.valuePtr();
  std::fill(values, values + H_.nonZeros(), 0.0);
  for (std::size_t f = 0; f < blocks_.size(); ++f)
    for (int p = 0; p < 6; ++p) {
      const int slot = slots_[f][p];
      if (slot < 0) continue;
      // An off-diagonal pair whose corners are the same vertex (possible in an intrinsic
      // triangulation) lands on the diagonal from both sides.
      const int a = kCornerPairs[p][0], b = kCornerPairs[p][1];
      const bool folded = a != b && tri.faceVertices[f][a] == tri.faceVertices[f][b];
      values[slot] += folded ? 2 * blocks_[f][p] : blocks_[f][p];
    }
  return H_;
}

double PreorderedLDLT::factorizationFlops() const {
  double flops = 0;
  for (Eigen::Index k = 0; k < m_nonZerosPerCol.size(); ++k) {
    const double c = m_nonZerosPerCol[k];
    flops += c * (c + 3);
  }
  return flops;
}

double PreorderedLDLT::factorNonZeros() const {
  double nonZeros = 0;
  for (Eigen::Index k = 0; k < m_nonZerosPerCol.size(); ++k) nonZeros += m_nonZerosPerCol[k];
  return nonZeros;
}

double PreorderedLDLT::solveFlops() const {
  return 4 * factorNonZeros() + static_cast<double>(m_nonZerosPerCol.size());
}

void PreorderedLDLT::preparePreconditioner() {
  StrictlyLowerFactor L;
  L.size = static_cast<int>(m_diag.size());
  L.start = m_matrix.outerIndexPtr();
  L.count = m_nonZerosPerCol.data();
  L.rows = m_matrix.innerIndexPtr();
  L.values = m_matrix.valuePtr();
  L.diagonal = m_diag.data();
  L.parent = m_parent.data();
  preconditioner_.build(L);
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
  factor.applyPreconditioner(r, z);
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
    factor.applyPreconditioner(r, z);
    const double rzNext = r.dot(z);
    if (!(rzNext > 0)) return result;  // the frozen factor is not positive definite
    p = z + (rzNext / rz) * p;
    rz = rzNext;
  }
  return result;
}

}  // namespace confvis::conformal::detail
