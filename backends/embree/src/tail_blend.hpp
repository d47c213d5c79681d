#pragma once
// The per-sample step of TailLattice (tail_lattice.hpp): a packet's tails blended bilinearly from
// its cell's corners, masked by the samples' alpha, compiled twice like the surface kernel
// (baseline SSE2 and AVX2 without FMA contraction: the same floats, CMakeLists.txt); the lattice
// calls the variant its job's shading uses (ShadingOptions::simd).
#include <array>

#include "camera_rays.hpp"
#include "surface_shading.hpp"

namespace confvis::embree {

// One interpolated cell: its corners' unit tail direction D (components 0-2) and the start's
// offset across it O = S - (S.D) D (3-5), in the order (left, top), (right, top), (left,
// bottom), (right, bottom); the cell's top-left corner and the reciprocal of its size in wall
// pixels; the bound of its samples' reach.
struct TailCell {
  std::array<std::array<float, 6>, 4> corners{};
  float left = 0.0f, top = 0.0f, perX = 0.0f, perY = 0.0f;
  float reach = 0.0f;
  float along = 0.0f;  // how far along the blended line from O each sample starts
};

// The camera's placement of a run of tails (camera_packet.cpp's runPacket): its rotation
// (glm's column-major mat3) and where c is placed.
struct TailPlacement {
  std::array<float, 9> rotation{};
  std::array<float, 3> centre{};
};
// A packet's rays (RTCRay8's origins and directions, structure of arrays, and the lanes to
// trace): blendTails' tails placed by the camera as runPacket places a run of them, the same
// floats in the same order, without the run between (the frame's straight packets).
struct TailRays {
  float *orgX, *orgY, *orgZ, *dirX, *dirY, *dirZ;
  int* valid;
};

// Per lane (wall-pixel position px, py; alpha the map's at the sample): the blended D
// normalised, and as the start O + cell.along D on the blended line (O blended too), which the
// lattice keeps no farther from c than the cell's reach. Only lanes whose reach lies inside the
// empty ball are traced as tails, and there this start and the one on the curve lie on the same
// line inside the ball, which holds no hit: the same hits. `alpha`: nullptr where the cell is
// lit throughout (the first `count` lanes lit). Unlit lanes (alpha < 0.5): zeros and reach 0; lit
// ones: reach `cell.reach`. exactTails' run layout; returns the largest reach. blendRays: the
// same tails placed (TailPlacement) straight into `rays`, lanes traced where lit.
namespace sse2 {
float blendTails(const TailCell& cell, const float* px, const float* py, const float* alpha,
                 int count, float* run, float* reach);
void blendRays(const TailCell& cell, const float* px, const float* py, const float* alpha,
               int count, const TailPlacement& placement, const TailRays& rays);
}
namespace avx2 {
float blendTails(const TailCell& cell, const float* px, const float* py, const float* alpha,
                 int count, float* run, float* reach);
void blendRays(const TailCell& cell, const float* px, const float* py, const float* alpha,
               int count, const TailPlacement& placement, const TailRays& rays);
}

inline float blendTails(SimdLevel level, const TailCell& cell, const float* px, const float* py,
                        const float* alpha, int count, float* run, float* reach) {
#ifdef CONFVIS_EMBREE_AVX2
  if (level == SimdLevel::Avx2) return avx2::blendTails(cell, px, py, alpha, count, run, reach);
#endif
  (void)level;
  return sse2::blendTails(cell, px, py, alpha, count, run, reach);
}

inline void blendRays(SimdLevel level, const TailCell& cell, const float* px, const float* py,
                      const float* alpha, int count, const TailPlacement& placement,
                      const TailRays& rays) {
#ifdef CONFVIS_EMBREE_AVX2
  if (level == SimdLevel::Avx2) return avx2::blendRays(cell, px, py, alpha, count, placement, rays);
#endif
  (void)level;
  sse2::blendRays(cell, px, py, alpha, count, placement, rays);
}

}  // namespace confvis::embree
