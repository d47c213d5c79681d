#pragma once
// Exact stereo rays' tails of one tile, interpolated (issue 23). A tail (its direction F(u) and
// its start W(last vertex)) costs two map lookups a sample; across a few pixels it is smooth
// except for the start's spin around the ray near the eye's axis (where the curve is short).
// The tile is cut into cells of kTailCellPixels x kTailCellPixels output pixels; the tails are
// evaluated exactly (CameraRays::tailsAt) at the cells' corners, and a cell's samples are
// interpolated bilinearly from its corners only where the lattice's second differences along x
// and y bound the blend's error within the stated bound; elsewhere each
// sample gets its own tails (CameraRays::exactTails).
//
// What is interpolated is what decides the traced line: the unit direction D and the start's
// offset across it, O = S - (S.D) D (about J_F(u) (e - c)_perp: smooth, where S itself spins
// with the eye's offset across the ray). Each sample starts on its own line at O + along D, one
// `along` a cell that keeps the start within the corners' nearest |S| of c (tail_blend.hpp),
// and every sample of the cell reports the cell's largest reach (from the corners' least h
// plus the cell's angular diameter times |e - c|; no closed form per sample): a packet is traced
// as straight tails only where that bound lies inside the empty ball, and there the true start
// and the blended one lie on the same line inside the ball, which holds no hit. Cells that may
// hold a sample on a line through c (infinite reach) are not interpolated. A line moved by dO
// and turned by dD
// moves a hit at distance r from c by about |dO| / r + |dD| in angle, and every hit a tail
// traces lies beyond the sample's reach (else the curve is marched): the check bounds
// |dD| + |dO| / R, with R the smallest reach in the cell (from the corners' largest h less the
// cell's angular diameter times |e - c|), by kTailTolerancePixels of the cell's pixel angle.
//
// A renderer's tile and a DirectionTable's tile build the same lattice, so a table draws the
// pixels a frame without one draws.
#include <vector>

#include "camera_packet.hpp"
#include "camera_rays.hpp"
#include "surface_shading.hpp"
#include "tail_blend.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

inline constexpr int kTailCellPixels = 4;
// The bound the centre check keeps, in output pixels (the curves' own bound is 0.25 px).
inline constexpr float kTailTolerancePixels = 0.05f;

class TailLattice {
 public:
  // The tile [x0, x1) x [y0, y1) of `job`'s image. Nothing is evaluated until the first tails().
  // A tolerance of infinity interpolates every cell (tests: what the check rejects).
  TailLattice(const CameraRays& rays, const TileJob& job, int x0, int y0, int x1, int y1,
              float tolerancePixels = kTailTolerancePixels);

  // CameraRays::exactTails for a packet of this tile (its positions px, py): interpolated where
  // its cell passed the check (each lane's reach then the cell's bound, at least its own), else
  // exactTails itself.
  float tails(const PacketSamples& samples, const float* px, const float* py, float* run,
              float* reach);

  // A straight packet's rays at once (blendRays: tails() placed as runPacket places them), where
  // the packet's cell is interpolated and its reach lies inside `emptyRadius`; else false and
  // nothing written (the caller takes tails()).
  bool straightRays(const PacketSamples& samples, const float* px, const float* py,
                    double emptyRadius, const TailRays& rays);

  // Whether the cell holding output pixel (x, y) of the tile is interpolated (builds the lattice).
  bool interpolated(int x, int y);

 private:
  void build();
  int cellIndex(int x, int y) const {
    return ((y - y0_) / kTailCellPixels) * cellsAcross_ + (x - x0_) / kTailCellPixels;
  }

  const CameraRays& rays_;
  glm::vec2 pixelToWall_{1.0f};
  int x0_ = 0, y0_ = 0, cellsAcross_ = 0, cellsDown_ = 0;
  float tolerancePixels_ = kTailTolerancePixels;
  TailPlacement placement_;  // the camera's (CameraRays::rotation, placedCentre)
  SimdLevel simd_ = SimdLevel::Sse2;  // which variant of the blend runs (tail_blend.hpp)
  bool usable_ = false;  // tiles aligned to whole cells only
  bool built_ = false;
  std::vector<char> pass_;    // per cell: interpolated
  std::vector<char> lit_;     // per cell: every sample lit (WallMapGrid::litThroughout)
  // per cell: its corners, place, an upper bound of its samples' reach (exactTails') and how far
  // along their lines they start, for the blend
  std::vector<TailCell> cells_;
};

}  // namespace confvis::embree
