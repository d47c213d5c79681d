#pragma once
// Deterministic per-pixel random numbers and stratified sample positions: a render is
// reproducible bit for bit, and a plain and a conformal render with the same settings use the
// same sub-pixel positions (which the equality tests rely on).
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace confvis::embree {

// PCG-style integer hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020).
inline std::uint32_t hashU32(std::uint32_t v) {
  const std::uint32_t state = v * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

class Random {
 public:
  Random() = default;
  Random(std::uint32_t a, std::uint32_t b, std::uint32_t c)
      : state_(hashU32(a ^ hashU32(b ^ hashU32(c)))) {}
  std::uint32_t nextU32() {
    state_ = hashU32(state_);
    return state_;
  }
  float next() { return static_cast<float>(nextU32() >> 8) * 0x1p-24f; }  // [0, 1)

 private:
  std::uint32_t state_ = 0;
};

// Sub-pixel position of sample `index` of `count` (both per pixel), in [0, 1)^2. One sample sits
// at the pixel centre. A square count gets a jittered grid; any other count a jittered Latin
// hypercube (one sample per row and per column stratum), the permutation drawn from `rng`.
inline glm::dvec2 stratifiedSample(int index, int count, std::uint32_t pixelSeed) {
  if (count <= 1) return {0.5, 0.5};
  Random rng(pixelSeed, static_cast<std::uint32_t>(index), 0x5eedu);
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  if (side * side == count)
    return {((index % side) + rng.next()) / side, ((index / side) + rng.next()) / side};
  // Latin hypercube: column stratum = index, row stratum = a per-pixel permutation of index
  // (an affine permutation mod count with a multiplier coprime to count).
  Random pixelRng(pixelSeed, 0x9e3779b9u, 1u);
  int multiplier = 1 + static_cast<int>(pixelRng.nextU32() % static_cast<std::uint32_t>(count));
  auto gcd = [](int x, int y) {
    while (y) {
      const int t = x % y;
      x = y;
      y = t;
    }
    return x;
  };
  while (gcd(multiplier, count) != 1) ++multiplier;
  const int offset = static_cast<int>(pixelRng.nextU32() % static_cast<std::uint32_t>(count));
  const int row = (multiplier * index + offset) % count;
  return {(index + rng.next()) / count, (row + rng.next()) / count};
}

}  // namespace confvis::embree
