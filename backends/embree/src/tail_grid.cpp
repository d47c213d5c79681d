#include "tail_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <tbb/parallel_for.h>

#include "camera_rays.hpp"
#include "confvis/backends/detail/bilinear_sse.hpp"

namespace confvis::embree {

namespace {

// Bilinear blend of `fields` vec4s per node at 8 positions (node units, inside the grid), the
// first three components of each written as out[(3 field + component) kPacketSize + lane].
void blendNodes(const glm::vec4* nodes, int fields, int across, int down, const float* gx,
                const float* gy, float* out) {
  for (int first = 0; first < kPacketSize; first += 4) {
#if defined(__SSE2__)
    __m128 s[3][4];
    for (int lane = 0; lane < 4; ++lane) {
      const float x = gx[first + lane], y = gy[first + lane];
      const int i = std::min(static_cast<int>(x), across - 2);
      const int j = std::min(static_cast<int>(y), down - 2);
      const float tx = x - static_cast<float>(i), ty = y - static_cast<float>(j);
      const float* n00 = &nodes[static_cast<std::size_t>(fields) * (static_cast<std::size_t>(j) * across + i)].x;
      const float* n01 = n00 + 4 * fields * across;
      for (int f = 0; f < fields; ++f)
        s[f][lane] = detail::blendCellCorners(n00 + 4 * f, n01 + 4 * f, 4 * fields, tx, ty);
    }
    for (int f = 0; f < fields; ++f) {
      _MM_TRANSPOSE4_PS(s[f][0], s[f][1], s[f][2], s[f][3]);
      for (int k = 0; k < 3; ++k) _mm_storeu_ps(out + (3 * f + k) * kPacketSize + first, s[f][k]);
    }
#else
    for (int lane = first; lane < first + 4; ++lane) {
      const int i = std::min(static_cast<int>(gx[lane]), across - 2);
      const int j = std::min(static_cast<int>(gy[lane]), down - 2);
      const float tx = gx[lane] - static_cast<float>(i), ty = gy[lane] - static_cast<float>(j);
      const glm::vec4* n00 = nodes + static_cast<std::size_t>(fields) * (static_cast<std::size_t>(j) * across + i);
      const glm::vec4* n01 = n00 + fields * across;
      for (int f = 0; f < fields; ++f) {
        const glm::vec4 v = (n00[f] * (1.0f - tx) + n00[fields + f] * tx) * (1.0f - ty) +
                            (n01[f] * (1.0f - tx) + n01[fields + f] * tx) * ty;
        for (int k = 0; k < 3; ++k) out[(3 * f + k) * kPacketSize + lane] = v[k];
      }
    }
#endif
  }
}

}  // namespace

TailGrid::TailGrid(const ConformalWarp& warp, const Wall& wall, double spacing, double margin) {
  const Wall lit = wall.litRectangle();
  const int columns = std::max(1, static_cast<int>(std::ceil(wall.width / spacing)));
  const int rows = std::max(1, static_cast<int>(std::ceil(wall.height / spacing)));
  const double stepX = static_cast<double>(wall.width) / columns;  // wall pixels
  const double stepY = static_cast<double>(wall.height) / rows;
  const double metresPerPixelX = lit.widthMetres() / wall.width;
  const double metresPerPixelY = lit.heightMetres() / wall.height;
  const int extraX = static_cast<int>(std::ceil(margin / (metresPerPixelX * stepX)));
  const int extraY = static_cast<int>(std::ceil(margin / (metresPerPixelY * stepY)));
  across_ = columns + 2 * extraX + 1;
  down_ = rows + 2 * extraY + 1;
  originX_ = static_cast<float>(-extraX * stepX);
  originY_ = static_cast<float>(-extraY * stepY);
  nodesPerPixelX_ = static_cast<float>(1.0 / stepX);
  nodesPerPixelY_ = static_cast<float>(1.0 / stepY);
  momentsAcross_ = (across_ - 1 + kMomentStride - 1) / kMomentStride + 1;
  momentsDown_ = (down_ - 1 + kMomentStride - 1) / kMomentStride + 1;
  const glm::dvec3 c = warp.reference(), right = lit.right(), up = lit.up();
  // The plane's point at F node (i, j) (fractional for moment nodes), relative to c.
  const auto fromCentre = [&](double i, double j) {
    return lit.upperLeft - c + ((i - extraX) * stepX * metresPerPixelX) * right -
           ((j - extraY) * stepY * metresPerPixelY) * up;
  };
  f_.resize(static_cast<std::size_t>(across_) * down_);
  tbb::parallel_for(0, down_, [&](int j) {
    for (int i = 0; i < across_; ++i)
      f_[static_cast<std::size_t>(j) * across_ + i] =
          glm::vec4(glm::vec3(warp.direction(fromCentre(i, j))), 0.0f);
  });
  // A = |x| dG/dr, B = |x| dG/du (G normalised), central differences one F spacing each side.
  moments_.resize(2 * static_cast<std::size_t>(momentsAcross_) * momentsDown_);
  const double deltaX = stepX * metresPerPixelX, deltaY = stepY * metresPerPixelY;
  tbb::parallel_for(0, momentsDown_, [&](int jm) {
    for (int im = 0; im < momentsAcross_; ++im) {
      const glm::dvec3 x = fromCentre(im * kMomentStride, jm * kMomentStride);
      const auto g = [&](const glm::dvec3& at) { return glm::normalize(warp.direction(at)); };
      const double distance = glm::length(x);
      const glm::dvec3 a = distance * (g(x + deltaX * right) - g(x - deltaX * right)) / (2.0 * deltaX);
      const glm::dvec3 b = distance * (g(x + deltaY * up) - g(x - deltaY * up)) / (2.0 * deltaY);
      const std::size_t at = 2 * (static_cast<std::size_t>(jm) * momentsAcross_ + im);
      moments_[at] = glm::vec4(glm::vec3(a), 0.0f);
      moments_[at + 1] = glm::vec4(glm::vec3(b), 0.0f);
    }
  });
}

double TailGrid::spacingFor(const Wall& wall, const glm::dvec3& reference, int mapResolution,
                            double outputScale) {
  return kFCoarsening * WallMapGrid::spacingFor(wall, reference, mapResolution, outputScale);
}

double TailGrid::marginFor(const Wall& wall, const glm::dvec3& reference) {
  return kMarginPerDistance * std::abs(glm::dot(reference - wall.lowerLeft, wall.normal()));
}

bool TailGrid::at(const float* qx, const float* qy, int count, float* out) const {
  alignas(32) std::array<float, kPacketSize> gx, gy, mx, my;
  const float lastX = static_cast<float>(across_ - 1), lastY = static_cast<float>(down_ - 1);
  bool inside = true;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float x = (qx[lane] - originX_) * nodesPerPixelX_;
    const float y = (qy[lane] - originY_) * nodesPerPixelY_;
    if (lane < count) inside = inside && x >= 0.0f && y >= 0.0f && x <= lastX && y <= lastY;
    gx[lane] = std::clamp(x, 0.0f, lastX);
    gy[lane] = std::clamp(y, 0.0f, lastY);
    mx[lane] = gx[lane] * (1.0f / kMomentStride);
    my[lane] = gy[lane] * (1.0f / kMomentStride);
  }
  if (!inside) return false;
  blendNodes(f_.data(), 1, across_, down_, gx.data(), gy.data(), out);
  blendNodes(moments_.data(), 2, momentsAcross_, momentsDown_, mx.data(), my.data(),
             out + 3 * kPacketSize);
  return true;
}

}  // namespace confvis::embree
