#pragma once
// Ray directions affine in the pixel position (plain off-axis rays): base + px stepX + py stepY,
// normalised in float, and the pixel centres of a packet they are evaluated at. Shared by the
// renderer's plain rays and the render benchmark's raw rtcIntersect8 loop, so that both generate
// the same rays at the same cost.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <glm/glm.hpp>

namespace confvis::embree {

struct AffineDirections {
  glm::vec3 base{0.0f}, stepX{0.0f}, stepY{0.0f};

  // One unit direction: glm::normalize(base + px stepX + py stepY).
  glm::vec3 at(float px, float py) const {
    return glm::normalize(base + px * stepX + py * stepY);
  }
  // N of them as structure of arrays: the same floats as at() (the same operations in the same
  // order), in a loop the compiler vectorises (with -fno-math-errno, see CMakeLists.txt).
  template <std::size_t N>
  void at(const std::array<float, N>& px, const std::array<float, N>& py, float* dx, float* dy,
          float* dz) const {
    for (std::size_t i = 0; i < N; ++i) {
      const float x = base.x + px[i] * stepX.x + py[i] * stepY.x;
      const float y = base.y + px[i] * stepX.y + py[i] * stepY.y;
      const float z = base.z + px[i] * stepX.z + py[i] * stepY.z;
      const float inverseLength = 1.0f / std::sqrt(x * x + y * y + z * z);
      dx[i] = x * inverseLength;
      dy[i] = y * inverseLength;
      dz[i] = z * inverseLength;
    }
  }
};

// Wall-pixel positions of the centres of a packet's output pixels: lane i < count is pixel
// (x + i % columns, y + i / columns), a block `columns` wide read row by row (lanes from `count`
// on repeat the last pixel); `pixelToWall` wall pixels per output pixel: (x + 0.5) s in double,
// then float. One sample per pixel sits at the centre (stratifiedSample).
template <std::size_t N>
void pixelCentres(int x, int y, int columns, int count, double pixelToWallX, double pixelToWallY,
                  std::array<float, N>& px, std::array<float, N>& py) {
  if (N == 8 && columns == 4 && count == 8) {  // a whole block: constant lane offsets (vectorises)
    for (std::size_t i = 0; i < N; ++i) {
      px[i] = static_cast<float>((x + static_cast<int>(i % 4) + 0.5) * pixelToWallX);
      py[i] = static_cast<float>((y + static_cast<int>(i / 4) + 0.5) * pixelToWallY);
    }
    return;
  }
  for (std::size_t i = 0; i < N; ++i) {
    const int lane = std::min(static_cast<int>(i), count - 1);
    px[i] = static_cast<float>((x + lane % columns + 0.5) * pixelToWallX);
    py[i] = static_cast<float>((y + lane / columns + 0.5) * pixelToWallY);
  }
}

}  // namespace confvis::embree
