#include "tail_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <tbb/parallel_for.h>

#include "camera_rays.hpp"

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
      const __m128 tx = _mm_set1_ps(x - static_cast<float>(i));
      const __m128 ty = _mm_set1_ps(y - static_cast<float>(j));
      const __m128 kx = _mm_sub_ps(_mm_set1_ps(1.0f), tx), ky = _mm_sub_ps(_mm_set1_ps(1.0f), ty);
      const float* n00 = &nodes[static_cast<std::size_t>(fields) * (static_cast<std::size_t>(j) * across + i)].x;
      const float* n01 = n00 + 4 * fields * across;
      for (int f = 0; f < fields; ++f) {
        const __m128 top = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(n00 + 4 * f), kx),
                                      _mm_mul_ps(_mm_loadu_ps(n00 + 4 * (fields + f)), tx));
        const __m128 bottom = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(n01 + 4 * f), kx),
                                         _mm_mul_ps(_mm_loadu_ps(n01 + 4 * (fields + f)), tx));
        s[f][lane] = _mm_add_ps(_mm_mul_ps(top, ky), _mm_mul_ps(bottom, ty));
      }
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

// Statistics of field `field` (of `fields` vec4 per node) of a grid `across` x `down` nodes
// `stepX`, `stepY` wall pixels apart, per region of `regionNodes` x `regionNodes` nodes (the
// region holding a node, or an interval's or a cell's first node, and for slopes also the one
// holding its last node): a region's statistics hold for every blend of nodes inside it.
void fieldStats(const glm::vec4* nodes, int fields, int field, int across, int down, float stepX,
                float stepY, int regionNodes, int regionsAcross, TailGrid::FieldStats* regions) {
  const auto node = [&](int i, int j) {
    return glm::vec3(nodes[static_cast<std::size_t>(fields) * (static_cast<std::size_t>(j) * across + i) +
                           static_cast<std::size_t>(field)]);
  };
  const auto region = [&](int i, int j) -> TailGrid::FieldStats& {
    return regions[static_cast<std::size_t>(j / regionNodes) * regionsAcross + i / regionNodes];
  };
  for (int j = 0; j < down; ++j)
    for (int i = 0; i < across; ++i) {
      const glm::vec3 at = node(i, j);
      TailGrid::FieldStats& own = region(i, j);
      own.most = std::max(own.most, glm::length(at));
      float steps[2] = {0.0f, 0.0f};  // to the next node along x and y
      if (i + 1 < across) {
        steps[0] = glm::length(node(i + 1, j) - at);
        for (TailGrid::FieldStats* r : {&own, &region(i + 1, j)})
          r->slope[0] = std::max(r->slope[0], steps[0] / stepX);
      }
      if (j + 1 < down) {
        steps[1] = glm::length(node(i, j + 1) - at);
        for (TailGrid::FieldStats* r : {&own, &region(i, j + 1)})
          r->slope[1] = std::max(r->slope[1], steps[1] / stepY);
      }
      if (i > 0 && i + 1 < across)
        own.second[0] = std::max(own.second[0], glm::length(node(i + 1, j) - 2.0f * at + node(i - 1, j)));
      if (j > 0 && j + 1 < down)
        own.second[1] = std::max(own.second[1], glm::length(node(i, j + 1) - 2.0f * at + node(i, j - 1)));
      // A blend inside the cell from this node is within one step along x and one along y of it
      // (the far corner through either neighbour: the larger detour of the two).
      if (i + 1 < across && j + 1 < down) {
        const float detour =
            std::max(steps[0] + glm::length(node(i + 1, j + 1) - node(i + 1, j)),
                     steps[1] + glm::length(node(i + 1, j + 1) - node(i, j + 1)));
        const float least = glm::length(at) - detour;
        own.least = std::min(own.least, least);
      }
    }
}

void combine(TailGrid::FieldStats& into, const TailGrid::FieldStats& from) {
  into.least = std::min(into.least, from.least);
  into.most = std::max(into.most, from.most);
  for (int k = 0; k < 2; ++k) {
    into.slope[k] = std::max(into.slope[k], from.slope[k]);
    into.second[k] = std::max(into.second[k], from.second[k]);
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
  // The check's statistics (smoothness), per region of kRegionNodes F nodes (kRegionNodes /
  // kMomentStride moment nodes: the same regions).
  // (The moment grid may reach one moment node past the last F node.)
  constexpr int kMomentRegionNodes = kRegionNodes / kMomentStride;
  regionsAcross_ = std::max((across_ - 1) / kRegionNodes, (momentsAcross_ - 1) / kMomentRegionNodes) + 1;
  regionsDown_ = std::max((down_ - 1) / kRegionNodes, (momentsDown_ - 1) / kMomentRegionNodes) + 1;
  const std::size_t regions = static_cast<std::size_t>(regionsAcross_) * regionsDown_;
  FieldStats empty;
  empty.least = std::numeric_limits<float>::infinity();
  fStats_.assign(regions, empty);
  momentStats_.assign(2 * regions, empty);
  const auto fStepX = static_cast<float>(stepX), fStepY = static_cast<float>(stepY);
  fieldStats(f_.data(), 1, 0, across_, down_, fStepX, fStepY, kRegionNodes, regionsAcross_,
             fStats_.data());
  for (int field = 0; field < 2; ++field)
    fieldStats(moments_.data(), 2, field, momentsAcross_, momentsDown_, kMomentStride * fStepX,
               kMomentStride * fStepY, kMomentRegionNodes, regionsAcross_,
               momentStats_.data() + field * regions);
}

bool TailGrid::smoothness(float x0, float y0, float x1, float y1, Smoothness& out) const {
  const float gx0 = (x0 - originX_) * nodesPerPixelX_, gy0 = (y0 - originY_) * nodesPerPixelY_;
  const float gx1 = (x1 - originX_) * nodesPerPixelX_, gy1 = (y1 - originY_) * nodesPerPixelY_;
  if (!(gx0 >= 0.0f && gy0 >= 0.0f && gx1 <= static_cast<float>(across_ - 1) &&
        gy1 <= static_cast<float>(down_ - 1) && gx0 <= gx1 && gy0 <= gy1))
    return false;
  const int r0x = static_cast<int>(gx0) / kRegionNodes, r0y = static_cast<int>(gy0) / kRegionNodes;
  const int r1x = std::min(static_cast<int>(gx1) / kRegionNodes, regionsAcross_ - 1);
  const int r1y = std::min(static_cast<int>(gy1) / kRegionNodes, regionsDown_ - 1);
  const std::size_t regions = static_cast<std::size_t>(regionsAcross_) * regionsDown_;
  const std::size_t first = static_cast<std::size_t>(r0y) * regionsAcross_ + r0x;
  out.f = fStats_[first];
  out.a = momentStats_[first];
  out.b = momentStats_[regions + first];
  for (int ry = r0y; ry <= r1y; ++ry)
    for (int rx = r0x; rx <= r1x; ++rx) {
      const std::size_t at = static_cast<std::size_t>(ry) * regionsAcross_ + rx;
      combine(out.f, fStats_[at]);
      combine(out.a, momentStats_[at]);
      combine(out.b, momentStats_[regions + at]);
    }
  out.fSpacing[0] = 1.0f / nodesPerPixelX_, out.fSpacing[1] = 1.0f / nodesPerPixelY_;
  out.momentSpacing[0] = kMomentStride * out.fSpacing[0];
  out.momentSpacing[1] = kMomentStride * out.fSpacing[1];
  return true;
}

double TailGrid::spacingFor(const Wall& wall, const glm::dvec3& reference, int mapResolution,
                            double outputScale) {
  return kFCoarsening * WallMapGrid::spacingFor(wall, reference, mapResolution, outputScale);
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
