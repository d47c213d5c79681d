#include "supernodal_preconditioner.hpp"

#include <algorithm>

namespace confvis::conformal::detail {
namespace {

// Σ a[k] b[k] with four partial sums: without them the compiler may not reorder the additions,
// and one chain of dependent adds is slower than the loads.
inline double dot(const float* a, const double* b, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < n; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

}  // namespace

void SupernodalPreconditioner::build(const StrictlyLowerFactor& L) {
  const int n = L.size;
  supernodes_.clear();
  rows_.clear();
  values_.clear();
  widest_ = 0;
  std::size_t entries = 0;
  for (int j = 0; j < n; ++j) entries += L.count[j];
  values_.reserve(entries);
  inverseDiagonal_.resize(n);
  for (int j = 0; j < n; ++j) inverseDiagonal_[j] = 1 / L.diagonal[j];
  for (int first = 0; first < n;) {
    // Column j + 1 continues the supernode when it is j's parent and has one entry less: the
    // etree makes j's pattern minus its parent a subset of the parent's, so they are equal.
    int end = first + 1;
    while (end < n && L.parent[end - 1] == end && L.count[end] == L.count[end - 1] - 1) ++end;
    Supernode s;
    s.firstColumn = first;
    s.width = end - first;
    widest_ = std::max(widest_, s.width);
    // Column first + t holds rows first + t + 1 .. end - 1 (the dense triangle), then the
    // rows below the block, the same for every column.
    s.triangle = values_.size();
    for (int t = 0; t < s.width; ++t) {
      const double* column = L.values + L.start[first + t];
      values_.insert(values_.end(), column, column + (s.width - 1 - t));
    }
    const int belowCount = L.count[first] - (s.width - 1);
    s.rowBegin = static_cast<int>(rows_.size());
    const int* belowRows = L.rows + L.start[first] + (s.width - 1);
    rows_.insert(rows_.end(), belowRows, belowRows + belowCount);
    s.rowEnd = static_cast<int>(rows_.size());
    s.below = values_.size();
    values_.resize(values_.size() + static_cast<std::size_t>(belowCount) * s.width);
    float* block = values_.data() + s.below;
    for (int t = 0; t < s.width; ++t) {
      const double* column = L.values + L.start[first + t] + (s.width - 1 - t);
      for (int i = 0; i < belowCount; ++i)
        block[static_cast<std::size_t>(i) * s.width + t] = static_cast<float>(column[i]);
    }
    supernodes_.push_back(s);
    first = end;
  }
  scratch_.assign(widest_, 0.0);
}

void SupernodalPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  z = r;
  double* x = z.data();
  const int* rows = rows_.data();
  for (const Supernode& s : supernodes_) {  // L y = r
    double* xs = x + s.firstColumn;
    const float* T = values_.data() + s.triangle;
    for (int t = 0; t + 1 < s.width; ++t) {
      const double xt = xs[t];
      for (int k = t + 1; k < s.width; ++k) xs[k] -= *T++ * xt;
    }
    const float* B = values_.data() + s.below;
    if (s.width == 1) {
      const double x0 = xs[0];
      for (int i = s.rowBegin; i < s.rowEnd; ++i) x[rows[i]] -= B[i - s.rowBegin] * x0;
    } else {
      for (int i = s.rowBegin; i < s.rowEnd; ++i, B += s.width) x[rows[i]] -= dot(B, xs, s.width);
    }
  }
  for (std::size_t j = 0; j < inverseDiagonal_.size(); ++j) x[j] *= inverseDiagonal_[j];
  double* sum = scratch_.data();
  for (auto it = supernodes_.rbegin(); it != supernodes_.rend(); ++it) {  // Lᵀ x = D⁻¹ y
    const Supernode& s = *it;
    double* xs = x + s.firstColumn;
    const float* B = values_.data() + s.below;
    if (s.width == 1) {
      double s0 = 0, s1 = 0;
      int i = s.rowBegin;
      for (; i + 2 <= s.rowEnd; i += 2) {
        s0 += B[i - s.rowBegin] * x[rows[i]];
        s1 += B[i + 1 - s.rowBegin] * x[rows[i + 1]];
      }
      if (i < s.rowEnd) s0 += B[i - s.rowBegin] * x[rows[i]];
      xs[0] -= s0 + s1;
      continue;
    }
    std::fill(sum, sum + s.width, 0.0);
    for (int i = s.rowBegin; i < s.rowEnd; ++i, B += s.width) {
      const double xr = x[rows[i]];
      for (int t = 0; t < s.width; ++t) sum[t] += B[t] * xr;
    }
    for (int t = 0; t < s.width; ++t) xs[t] -= sum[t];
    // The packed triangle backwards: column t starts after the columns 0 .. t - 1.
    const float* T = values_.data() + s.triangle;
    for (int t = s.width - 2; t >= 0; --t) {
      const float* column = T + static_cast<std::size_t>(t) * (s.width - 1) -
                            static_cast<std::size_t>(t) * (t - 1) / 2;
      xs[t] -= dot(column, xs + t + 1, s.width - 1 - t);
    }
  }
}

}  // namespace confvis::conformal::detail
