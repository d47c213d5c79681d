#include "confvis/backends/wall_map_grid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <tbb/parallel_for.h>

#include "confvis/backends/detail/bilinear_sse.hpp"

namespace confvis {
namespace {

// Whether the ray from c along `direction` meets the wall's lit rectangle `lit`.
bool meetsRectangle(const Wall& lit, const glm::dvec3& c, const glm::dvec3& direction) {
  const glm::dvec3 normal = lit.normal();
  const double along = glm::dot(normal, direction);
  if (along == 0.0) return false;
  const double distance = glm::dot(normal, lit.lowerLeft - c) / along;
  if (!(distance > 0.0)) return false;
  const glm::dvec3 q = c + distance * direction - lit.lowerLeft;
  constexpr double kSlack = 1e-9;  // texel centres exactly on the rim count
  const double s = glm::dot(q, lit.right()) / lit.widthMetres();
  const double t = glm::dot(q, lit.up()) / lit.heightMetres();
  return s >= -kSlack && s <= 1.0 + kSlack && t >= -kSlack && t <= 1.0 + kSlack;
}

// The map's alpha at wall point p, except that a point is lit where a lit texel of its footprint
// shows this same wall. The bilinear alpha alone blends in the unlit texels just beyond the lit
// rectangle (the bezels between monitors) and blacked out a band half a texel wide along them
// (md230x6's top-centre monitor: 1.05 % of its pixels); testing the texels' own walls keeps a
// wall the map does not light (a map baked for fewer walls) black.
float litAlpha(const ConformalWarp& warp, const Wall& lit, const glm::dvec3& p, float alpha) {
  if (alpha >= 0.5f) return alpha;
  std::array<glm::dvec3, 4> texels;
  const int count = warp.litFootprint(p - warp.reference(), texels);
  for (int k = 0; k < count; ++k)
    if (meetsRectangle(lit, warp.reference(), texels[static_cast<std::size_t>(k)])) return 1.0f;
  return alpha;
}

}  // namespace

WallMapGrid::WallMapGrid(const ConformalWarp& warp, const Wall& wall, double spacing) {
  const Wall lit = wall.litRectangle();
  columns_ = std::max(1, static_cast<int>(std::ceil(wall.width / spacing)));
  rows_ = std::max(1, static_cast<int>(std::ceil(wall.height / spacing)));
  cellsPerPixelX_ = static_cast<float>(columns_) / static_cast<float>(wall.width);
  cellsPerPixelY_ = static_cast<float>(rows_) / static_cast<float>(wall.height);
  samples_.resize(static_cast<std::size_t>(columns_ + 1) * (rows_ + 1));
  tbb::parallel_for(0, rows_ + 1, [&](int j) {
    for (int i = 0; i <= columns_; ++i) {
      // Pixel-space py = 0 is the top edge; pointAt's t = 0 is the bottom edge.
      const glm::dvec3 p = lit.pointAt(static_cast<double>(i) / columns_,
                                       1.0 - static_cast<double>(j) / rows_);
      const ConformalWarp::Lookup v = warp.lookup(p - warp.reference());
      samples_[static_cast<std::size_t>(j) * (columns_ + 1) + i] =
          glm::vec4(glm::vec3(v.direction), litAlpha(warp, lit, p, v.alpha));
    }
  });
}

WallMapGrid::Sample WallMapGrid::at(float px, float py) const {
  const float gx = std::clamp(px * cellsPerPixelX_, 0.0f, static_cast<float>(columns_));
  const float gy = std::clamp(py * cellsPerPixelY_, 0.0f, static_cast<float>(rows_));
  const int i = std::min(static_cast<int>(gx), columns_ - 1);
  const int j = std::min(static_cast<int>(gy), rows_ - 1);
  const float tx = gx - static_cast<float>(i), ty = gy - static_cast<float>(j);
  const glm::vec4* row0 = samples_.data() + static_cast<std::size_t>(j) * (columns_ + 1) + i;
  const glm::vec4* row1 = row0 + (columns_ + 1);
  const glm::vec4 s = glm::mix(glm::mix(row0[0], row0[1], tx), glm::mix(row1[0], row1[1], tx), ty);
  return {glm::vec3(s), s.w};
}

void WallMapGrid::at(int count, const float* px, const float* py, float* x, float* y, float* z,
                     float* alpha) const {
  int k = 0;
#if defined(__SSE2__)
  // Four positions at a time: at()'s cell and weights as vectors (its clamps, truncations and
  // minimum, exact in float for grids under 2^24 samples; larger ones take at()), the four corners' blends four
  // components at a time (glm::mix(a, b, t) = a (1 - t) + b t), transposed into x, y, z, alpha.
  const __m128 columns = _mm_set1_ps(static_cast<float>(columns_));
  const __m128 rows = _mm_set1_ps(static_cast<float>(rows_));
  const __m128 lastColumn = _mm_set1_ps(static_cast<float>(columns_ - 1));
  const __m128 lastRow = _mm_set1_ps(static_cast<float>(rows_ - 1));
  const __m128 rowStride = _mm_set1_ps(static_cast<float>(columns_ + 1));
  const __m128 zero = _mm_setzero_ps();
  const bool exactInFloat = samples_.size() < (std::size_t{1} << 24);
  for (; exactInFloat && k + 4 <= count; k += 4) {
    const __m128 gx = _mm_min_ps(
        _mm_max_ps(_mm_mul_ps(_mm_loadu_ps(px + k), _mm_set1_ps(cellsPerPixelX_)), zero), columns);
    const __m128 gy = _mm_min_ps(
        _mm_max_ps(_mm_mul_ps(_mm_loadu_ps(py + k), _mm_set1_ps(cellsPerPixelY_)), zero), rows);
    const __m128 i = _mm_min_ps(_mm_cvtepi32_ps(_mm_cvttps_epi32(gx)), lastColumn);
    const __m128 j = _mm_min_ps(_mm_cvtepi32_ps(_mm_cvttps_epi32(gy)), lastRow);
    alignas(16) float takeX[4], takeY[4];
    alignas(16) int first[4];
    _mm_store_ps(takeX, _mm_sub_ps(gx, i));
    _mm_store_ps(takeY, _mm_sub_ps(gy, j));
    _mm_store_si128(reinterpret_cast<__m128i*>(first),
                    _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(j, rowStride), i)));
    __m128 s[4];
    for (int lane = 0; lane < 4; ++lane) {
      const float* row0 = &samples_[static_cast<std::size_t>(first[lane])].x;
      const float* row1 = row0 + 4 * (columns_ + 1);
      s[lane] = detail::blendCellCorners(row0, row1, 4, takeX[lane], takeY[lane]);
    }
    _MM_TRANSPOSE4_PS(s[0], s[1], s[2], s[3]);
    _mm_storeu_ps(x + k, s[0]);
    _mm_storeu_ps(y + k, s[1]);
    _mm_storeu_ps(z + k, s[2]);
    _mm_storeu_ps(alpha + k, s[3]);
  }
#endif
  for (; k < count; ++k) {
    const Sample s = at(px[k], py[k]);
    x[k] = s.direction.x;
    y[k] = s.direction.y;
    z[k] = s.direction.z;
    alpha[k] = s.alpha;
  }
}

bool WallMapGrid::litThroughout(float px0, float py0, float px1, float py1) const {
  const auto cell = [](float position, float cellsPerPixel, int cells) {
    const float g = std::clamp(position * cellsPerPixel, 0.0f, static_cast<float>(cells));
    return std::min(static_cast<int>(g), cells - 1);
  };
  const int i0 = cell(px0, cellsPerPixelX_, columns_), i1 = cell(px1, cellsPerPixelX_, columns_);
  const int j0 = cell(py0, cellsPerPixelY_, rows_), j1 = cell(py1, cellsPerPixelY_, rows_);
  constexpr float kLitWithMargin = 0.5f + 1e-5f;
  for (int j = j0; j <= j1 + 1; ++j)
    for (int i = i0; i <= i1 + 1; ++i)
      if (!(samples_[static_cast<std::size_t>(j) * (columns_ + 1) + i].w >= kLitWithMargin))
        return false;
  return true;
}

double WallMapGrid::spacingFor(const Wall& wall, const glm::dvec3& reference, int mapResolution,
                               double outputScale) {
  const Wall lit = wall.litRectangle();
  const double distance = std::max(1e-9, std::abs(glm::dot(lit.lowerLeft - reference, lit.normal())));
  const double pixelAngle =
      std::min(lit.widthMetres() / wall.width, lit.heightMetres() / wall.height) / distance;
  const double halfTexelAngle = 0.5 * glm::half_pi<double>() / mapResolution;
  return std::max(halfTexelAngle / pixelAngle, 1.0 / outputScale);
}

}  // namespace confvis
