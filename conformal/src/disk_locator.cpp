#include "disk_locator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "confvis/base/error.hpp"

namespace confvis::detail {

namespace {

// Barycentric coordinates may be this far below 0 and still count as inside: points on a shared
// edge must be found by one of its triangles despite rounding.
constexpr double kInsideTolerance = 1e-12;
constexpr int kMaxWalkSteps = 64;

}  // namespace

DiskLocator::DiskLocator(const std::vector<std::complex<double>>& disk,
                         const std::vector<std::array<int, 3>>& triangles)
    : disk_(disk), triangles_(triangles) {
  const int count = static_cast<int>(triangles.size());
  affine_.resize(count);
  double minX = std::numeric_limits<double>::infinity(), minY = minX, maxX = -minX, maxY = -minX;
  int validCount = 0;
  for (int t = 0; t < count; ++t) {
    const auto& tri = triangles[t];
    const std::complex<double> p0 = disk[tri[0]], e1 = disk[tri[1]] - p0, e2 = disk[tri[2]] - p0;
    const double det = e1.real() * e2.imag() - e1.imag() * e2.real();
    const double scale = std::norm(e1) + std::norm(e2);
    Affine& a = affine_[t];
    a.valid = std::abs(det) > 1e-14 * scale && std::isfinite(det);
    a.x0 = p0.real();
    a.y0 = p0.imag();
    if (a.valid) {
      a.m11 = e2.imag() / det;
      a.m12 = -e2.real() / det;
      a.m21 = -e1.imag() / det;
      a.m22 = e1.real() / det;
      ++validCount;
    } else {
      a.m11 = a.m12 = a.m21 = a.m22 = 0;
    }
    for (int v : tri) {
      minX = std::min(minX, disk[v].real());
      maxX = std::max(maxX, disk[v].real());
      minY = std::min(minY, disk[v].imag());
      maxY = std::max(maxY, disk[v].imag());
    }
  }
  if (validCount == 0)
    throw Error(ErrorCode::InvalidInput, "disk map has no triangle of non-zero area");

  // Neighbours across edges, and the boundary edges (edges with one triangle): the triangle
  // across edge (a, b) of t is the other triangle around a that has b. Vertex-to-triangle lists,
  // not a hash map of edges: this runs at every bake (100k triangles: ~40 ms less).
  neighbour_.assign(count, {-1, -1, -1});
  std::vector<int> aroundStart(disk.size() + 1, 0), around(3 * static_cast<std::size_t>(count));
  for (const auto& tri : triangles)
    for (int v : tri) ++aroundStart[v + 1];
  for (std::size_t v = 1; v < aroundStart.size(); ++v) aroundStart[v] += aroundStart[v - 1];
  {
    std::vector<int> fill(aroundStart.begin(), aroundStart.end() - 1);
    for (int t = 0; t < count; ++t)
      for (int v : triangles[t]) around[fill[v]++] = t;
  }
  for (int t = 0; t < count; ++t)
    for (int i = 0; i < 3; ++i) {
      if (neighbour_[t][i] >= 0) continue;
      const int a = triangles[t][(i + 1) % 3], b = triangles[t][(i + 2) % 3];
      for (int k = aroundStart[a]; k < aroundStart[a + 1]; ++k) {
        const int u = around[k];
        if (u == t) continue;
        const auto& other = triangles[u];
        int opposite = -1;
        bool hasB = false;
        for (int j = 0; j < 3; ++j) {
          hasB |= other[j] == b;
          if (other[j] != a && other[j] != b) opposite = j;
        }
        if (!hasB || opposite < 0 || neighbour_[u][opposite] >= 0) continue;
        neighbour_[t][i] = u;
        neighbour_[u][opposite] = t;
        break;
      }
    }
  for (int t = 0; t < count; ++t)
    for (int i = 0; i < 3; ++i)
      if (neighbour_[t][i] < 0 && affine_[t].valid) boundaryEdges_.push_back({t, i});

  // About two triangles per cell on average.
  grid_ = std::clamp(static_cast<int>(std::sqrt(validCount / 2.0)), 1, 1024);
  minX_ = minX;
  minY_ = minY;
  cell_ = std::max({maxX - minX, maxY - minY, 1e-300}) / grid_;
  std::vector<int> counts(static_cast<std::size_t>(grid_) * grid_ + 1, 0);
  auto forCells = [&](int t, auto&& f) {
    const auto& tri = triangles[t];
    double x0 = disk[tri[0]].real(), x1 = x0, y0 = disk[tri[0]].imag(), y1 = y0;
    for (int k = 1; k < 3; ++k) {
      x0 = std::min(x0, disk[tri[k]].real());
      x1 = std::max(x1, disk[tri[k]].real());
      y0 = std::min(y0, disk[tri[k]].imag());
      y1 = std::max(y1, disk[tri[k]].imag());
    }
    auto index = [&](double v, double lo) {
      return std::clamp(static_cast<int>(std::floor((v - lo) / cell_)), 0, grid_ - 1);
    };
    for (int cy = index(y0, minY_); cy <= index(y1, minY_); ++cy)
      for (int cx = index(x0, minX_); cx <= index(x1, minX_); ++cx) f(cy * grid_ + cx);
  };
  for (int t = 0; t < count; ++t)
    if (affine_[t].valid) forCells(t, [&](int c) { ++counts[c + 1]; });
  for (std::size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
  cellStart_ = counts;
  cellTriangles_.resize(counts.back());
  for (int t = 0; t < count; ++t)
    if (affine_[t].valid) forCells(t, [&](int c) { cellTriangles_[counts[c]++] = t; });
}

std::array<double, 3> DiskLocator::barycentric(int t, std::complex<double> z) const {
  const Affine& a = affine_[t];
  const double dx = z.real() - a.x0, dy = z.imag() - a.y0;
  const double l1 = a.m11 * dx + a.m12 * dy, l2 = a.m21 * dx + a.m22 * dy;
  return {1.0 - l1 - l2, l1, l2};
}

bool DiskLocator::walk(std::complex<double> z, int start, Hit& hit) const {
  int t = start;
  for (int step = 0; step < kMaxWalkSteps; ++step) {
    if (!affine_[t].valid) return false;
    const std::array<double, 3> b = barycentric(t, z);
    const int worst = static_cast<int>(std::min_element(b.begin(), b.end()) - b.begin());
    if (b[worst] >= -kInsideTolerance) {
      hit = {t, b};
      return true;
    }
    const int next = neighbour_[t][worst];
    // Off a boundary edge: z is outside the (convex) polygon; let the clamp find the nearest
    // boundary point, which need not be on this edge.
    if (next < 0) return false;
    t = next;
  }
  return false;  // a cycle (possible around flipped triangles) or a long way: use the grid
}

bool DiskLocator::searchGrid(std::complex<double> z, Hit& hit) const {
  const int cx = static_cast<int>(std::floor((z.real() - minX_) / cell_));
  const int cy = static_cast<int>(std::floor((z.imag() - minY_) / cell_));
  if (cx < 0 || cy < 0 || cx >= grid_ || cy >= grid_) return false;
  const int c = cy * grid_ + cx;
  for (int k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
    const int t = cellTriangles_[k];
    const std::array<double, 3> b = barycentric(t, z);
    if (std::min({b[0], b[1], b[2]}) >= -kInsideTolerance) {
      hit = {t, b};
      return true;
    }
  }
  return false;
}

DiskLocator::Hit DiskLocator::clampToBoundary(std::complex<double> z) const {
  Hit best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto& [t, corner] : boundaryEdges_) {
    const int a = triangles_[t][(corner + 1) % 3], b = triangles_[t][(corner + 2) % 3];
    const std::complex<double> pa = disk_[a], e = disk_[b] - pa;
    const double len2 = std::norm(e);
    const double s = len2 > 0 ? std::clamp(((z - pa) * std::conj(e)).real() / len2, 0.0, 1.0) : 0.0;
    const double distance = std::norm(z - (pa + s * e));
    if (distance < bestDistance) {
      bestDistance = distance;
      best.triangle = t;
      best.barycentric = {0, 0, 0};
      best.barycentric[(corner + 1) % 3] = 1 - s;
      best.barycentric[(corner + 2) % 3] = s;
    }
  }
  if (best.triangle < 0) {  // no boundary edge (cannot happen for a disk): any valid triangle
    for (int t = 0; t < static_cast<int>(affine_.size()) && best.triangle < 0; ++t)
      if (affine_[t].valid) best = {t, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
  }
  return best;
}

DiskLocator::Hit DiskLocator::locate(std::complex<double> z, int& hint) const {
  Hit hit;
  if (!(std::isfinite(z.real()) && std::isfinite(z.imag()))) z = 0;
  const bool found = (hint >= 0 && hint < static_cast<int>(affine_.size()) && walk(z, hint, hit)) ||
                     searchGrid(z, hit);
  if (!found) {
    hit = clampToBoundary(z);
    hit.inside = false;
  }
  // Inside tolerance: renormalise tiny negative coordinates away.
  for (double& b : hit.barycentric) b = std::max(b, 0.0);
  const double sum = hit.barycentric[0] + hit.barycentric[1] + hit.barycentric[2];
  for (double& b : hit.barycentric) b /= sum;
  hint = hit.triangle;
  return hit;
}

}  // namespace confvis::detail
