// Texture::sampleWrapped computes floor and the wrap with integer arithmetic where that is exact;
// these tests hold it to the defining rule (double floor, fmod, then wrap) bit for bit, so that
// renders through either path keep identical pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "confvis/engine/scene.hpp"

using namespace confvis;

namespace {

int wrapped(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// The rule as written before the integer path: bilinear, repeat wrap, texel centres at
// integers, in double up to the weights.
glm::vec4 byFloorAndFmod(const Texture& texture, glm::vec2 uv) {
  const double x = static_cast<double>(uv.x) * texture.width - 0.5;
  const double y = static_cast<double>(uv.y) * texture.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int ix = wrapped(static_cast<int>(std::fmod(x0, texture.width)), texture.width);
  const int iy = wrapped(static_cast<int>(std::fmod(y0, texture.height)), texture.height);
  const glm::vec4 top = glm::mix(texture.texel(ix, iy), texture.texel(ix + 1, iy), fx);
  const glm::vec4 bottom = glm::mix(texture.texel(ix, iy + 1), texture.texel(ix + 1, iy + 1), fx);
  return glm::mix(top, bottom, fy);
}

// Every texel a different, non-round value, so a wrong texel or weight shows in the bits.
Texture distinctTexels(int width, int height) {
  Texture texture{width, height, {}};
  for (int i = 0; i < width * height * 4; ++i)
    texture.rgba.push_back(std::sqrt(static_cast<float>(i + 2)) * 0.37f);
  return texture;
}

// Counts the uvs where sampleWrapped's bits differ from the rule's; describes the first.
struct Mismatches {
  int count = 0;
  std::string first;

  void check(const Texture& texture, glm::vec2 uv) {
    const glm::vec4 got = texture.sampleWrapped(uv), expected = byFloorAndFmod(texture, uv);
    if (std::memcmp(&got, &expected, sizeof got) == 0) return;
    if (count++ == 0)
      first = std::to_string(texture.width) + " x " + std::to_string(texture.height) +
              " texels, uv (" + std::to_string(uv.x) + ", " + std::to_string(uv.y) + "): red " +
              std::to_string(got.r) + ", expected " + std::to_string(expected.r);
  }
};

}  // namespace

TEST(TextureWrap, BordersAndRepeatsMatchTheFloorAndFmodRuleBitForBit) {
  Mismatches mismatches;
  for (const auto& [width, height] : {std::pair{5, 3}, std::pair{16, 16}, std::pair{2, 7}}) {
    const Texture texture = distinctTexels(width, height);
    // Steps of 1/64 texel from four periods below 0 to four above 1: every border, negative
    // coordinates (where truncation is not floor), texel centres and edges exactly.
    for (int i = -4 * 64 * width; i <= 5 * 64 * width; i += 7)
      for (int j = -4 * 64 * height; j <= 5 * 64 * height; j += 61)
        mismatches.check(texture,
                         {static_cast<float>(i) / (64.0f * static_cast<float>(width)),
                          static_cast<float>(j) / (64.0f * static_cast<float>(height))});
  }
  EXPECT_EQ(mismatches.count, 0) << "first: " << mismatches.first;
}

TEST(TextureWrap, LargeHugeAndSignedZeroCoordinatesMatchTheRule) {
  const Texture texture = distinctTexels(5, 3);
  Mismatches mismatches;
  const std::vector<float> values = {-0.0f,   0.0f,    0.1f,   -0.1f,  1.0f,   -1.0f,
                                     123.4f,  -123.4f, 1e6f,   -1e6f,  3e7f,   -3e7f,
                                     4.5e8f,  -4.5e8f, 1e17f,  -1e17f, 1e30f,  -1e30f};
  for (float u : values)
    for (float v : values) mismatches.check(texture, {u, v});
  EXPECT_EQ(mismatches.count, 0) << "first: " << mismatches.first;
}
