// Compiled twice (see tail_blend.hpp and surface_shading.cpp): CONFVIS_SIMD_NAMESPACE names the
// variant; nothing here is an inline function shared with other translation units. Written
// with GCC's vector extensions over the 8 lanes (one AVX register, or two SSE ones in the
// baseline build): the auto-vectorised loop used masked loads of the inputs, which waited for
// the scalar stores that wrote them, and copied its results out through general registers.
#include "tail_blend.hpp"

#include <cstring>

#include <immintrin.h>

#ifndef CONFVIS_SIMD_NAMESPACE
#define CONFVIS_SIMD_NAMESPACE sse2
#endif

namespace confvis::embree::CONFVIS_SIMD_NAMESPACE {

namespace {

// The baseline build passes these 32-byte vectors between its own local (inlined) helpers
// only, never across translation units: GCC's note that the AVX build would pass them
// differently does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

typedef float Floats __attribute__((vector_size(32)));
typedef int Ints __attribute__((vector_size(32)));
static_assert(kPacketSize == 8);

Floats load(const float* from) {
  Floats v;
  std::memcpy(&v, from, sizeof v);
  return v;
}

void store(const Floats& v, float* to) { std::memcpy(to, &v, sizeof v); }

Floats squareRoot(Floats x) {
#if defined(__AVX__)
  return reinterpret_cast<Floats>(_mm256_sqrt_ps(reinterpret_cast<__m256>(x)));
#else
  __m128 low, high;
  std::memcpy(&low, &x, sizeof low);
  std::memcpy(&high, reinterpret_cast<const char*>(&x) + sizeof low, sizeof high);
  low = _mm_sqrt_ps(low), high = _mm_sqrt_ps(high);
  std::memcpy(&x, &low, sizeof low);
  std::memcpy(reinterpret_cast<char*>(&x) + sizeof low, &high, sizeof high);
  return x;
#endif
}

// v where `mask` (all bits), +0 elsewhere.
Floats select(const Ints& mask, const Floats& v) {
  return reinterpret_cast<Floats>(mask & reinterpret_cast<Ints>(v));
}

// The blended tails of lit lanes (unit direction, start), zeros elsewhere, and the lit mask.
struct Blended {
  Floats direction[3], start[3];
  Ints lit;
};

// Inlined into both callers: a call returns the 7 vectors through memory (measured: the
// fused path was ~2 % of a moving-head frame slower than the run and runPacket with it).
[[gnu::always_inline]] inline Blended blend(const TailCell& cell, const float* px,
                                            const float* py, const float* alpha, int count) {
  const Floats tx = (load(px) - cell.left) * cell.perX;
  const Floats ty = (load(py) - cell.top) * cell.perY;
  const Floats w00 = (1.0f - tx) * (1.0f - ty), w10 = tx * (1.0f - ty);
  const Floats w01 = (1.0f - tx) * ty, w11 = tx * ty;
  const auto& c = cell.corners;
  Floats blended[6];
  for (std::size_t k = 0; k < 6; ++k)
    blended[k] = w00 * c[0][k] + w10 * c[1][k] + w01 * c[2][k] + w11 * c[3][k];
  const Floats inverseLength = 1.0f / squareRoot(blended[0] * blended[0] +
                                                 blended[1] * blended[1] + blended[2] * blended[2]);
  // Lit lanes: alpha >= 0.5, or (no alpha) the first `count`; unlit ones get zeros (lit ones
  // have a unit direction) and reach 0.
  const Ints lane = {0, 1, 2, 3, 4, 5, 6, 7};
  const Ints lit = alpha ? (load(alpha) >= 0.5f) : (lane < count);
  const Floats along = cell.along + Floats{};
  Blended out;
  out.lit = lit;
  for (std::size_t k = 0; k < 3; ++k) {
    const Floats direction = blended[k] * inverseLength;
    out.direction[k] = select(lit, direction);
    out.start[k] = select(lit, blended[3 + k] + along * direction);
  }
  return out;
}

}  // namespace

float blendTails(const TailCell& cell, const float* px, const float* py, const float* alpha,
                 int count, float* run, float* reach) {
  const Blended b = blend(cell, px, py, alpha, count);
  for (std::size_t k = 0; k < 3; ++k) {
    store(b.direction[k], run + k * kPacketSize);
    store(b.start[k], run + (3 + k) * kPacketSize);
  }
  store(select(b.lit, cell.reach + Floats{}), reach);
  for (std::size_t k = 0; k < kPacketSize; ++k)
    if (b.lit[k]) return cell.reach;
  return 0.0f;
}

void blendRays(const TailCell& cell, const float* px, const float* py, const float* alpha,
               int count, const TailPlacement& placement, const TailRays& rays) {
  const Blended b = blend(cell, px, py, alpha, count);
  const auto& m = placement.rotation;  // m[3 column + row]
  // runPacket's expressions: m[0][r] x + m[1][r] y + m[2][r] z, origins c + that.
  const auto turned = [&](const Floats* v, int row) {
    return m[row] * v[0] + m[3 + row] * v[1] + m[6 + row] * v[2];
  };
  float* const directions[3] = {rays.dirX, rays.dirY, rays.dirZ};
  float* const origins[3] = {rays.orgX, rays.orgY, rays.orgZ};
  for (int row = 0; row < 3; ++row) {
    store(turned(b.direction, row), directions[row]);
    store(placement.centre[static_cast<std::size_t>(row)] + turned(b.start, row), origins[row]);
  }
  const Ints traced = (b.direction[0] != 0.0f) | (b.direction[1] != 0.0f) | (b.direction[2] != 0.0f);
  std::memcpy(rays.valid, &traced, sizeof traced);
}

}  // namespace confvis::embree::CONFVIS_SIMD_NAMESPACE
