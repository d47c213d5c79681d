#pragma once
// The straight camera rays of one image, one per camera sample, kept across frames so that a
// conformal frame does no map lookup at all (only the rotation and translation by the virtual
// camera, as a plain frame does):
//   - conformal centre eye: F(dir(p)) read from the WallMapGrid;
//   - fast stereo rays: W(p) relative to the warp's centre, p the sample's wall point
//     (CameraRays::fastTargets): the same for every eye position, so a moving head reads it too;
//   - exact stereo rays: the straight tail of the bent ray, its start relative to the warp's
//     centre and its direction (CameraRays::exactTails), with each packet's reach: the farthest
//     from c any of its curves bends, so that a render whose scene keeps farther than that
//     (CameraRays::setEmptyRadius) traces the packet as straight rays from the table.
// Unlit samples hold the zero direction. All in the physical frame, before the camera.
//
// Stored in the order the tile renderer reads it: tile by tile, within a tile sample by sample,
// then its packets (blocks of 4 x 2 pixels, PacketSamples) row of blocks by row of blocks, each
// as structure of arrays: 8 x, 8 y, 8 z (lanes in PacketSamples' order; zeros past the block's
// pixels inside the tile), then, for tables with origins, 8 x, 8 y, 8 z of the origin. A frame
// streams the table once (12 or 24 bytes a sample, far beyond the caches at full resolution),
// so each tile reads one contiguous block, and a packet loads its components as vectors.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/wall_map_grid.hpp"
#include "camera_packet.hpp"
#include "packet_tracer.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class DirectionTable {
 public:
  // Fills one packet's run (the layout of packet(): 3 or 6 x kPacketSize floats, zeros where
  // unlit) for `count` samples at wall-pixel positions (px, py) (packetPositions: lanes from
  // `count` on repeat the last); returns the packet's reach (tables with origins: the farthest
  // from c any of its curves bends; infinity: a curve must be traced whole).
  using PacketSampler =
      std::function<float(const float* px, const float* py, int count, float* run)>;

  // Conformal centre eye: F at job.width x job.height pixels x job.samplesPerPixel at
  // samplePosition(job, ...), in tiles of job.tileSize.
  DirectionTable(const WallMapGrid& grid, const TileJob& job);
  // Any straight rays, one per sample, packet by packet from `sampler`; `withOrigins`: each its
  // own origin.
  DirectionTable(const TileJob& job, const PacketSampler& sampler, bool withOrigins);
  // Exact stereo rays' tails, with origins, tile by tile through the tile's TailLattice (as a
  // frame without a table takes them, so the table draws the same pixels).
  DirectionTable(const TileJob& job, const CameraRays& exactRays);

  // The packet of sample `sample` of the block whose top-left pixel is (x, y) (a tile's corner
  // plus multiples of the block size): the direction's x components at [0, 8), y at [8, 16), z at
  // [16, 24), then (withOrigins) the origin's likewise at [24, 48); zeros where unlit or past the
  // tile.
  const float* packet(int x, int y, int sample) const {
    return &components_[stride() * packetIndex(x, y, sample)];
  }
  // Tables with origins: the farthest from c any curve of the packet bends.
  float reach(int x, int y, int sample) const { return reach_[packetIndex(x, y, sample)]; }
  bool hasOrigins() const { return withOrigins_; }
  std::size_t sampleCount() const { return samples_; }
  std::size_t bytes() const { return components_.size() * sizeof(float); }

 private:
  DirectionTable(const TileJob& job, const PacketSampler& sampler, bool withOrigins,
                 const CameraRays* exactRays);
  std::size_t stride() const { return (withOrigins_ ? 6 : 3) * kPacketSize; }
  // `exactRays`: the tails from each tile's TailLattice instead of `sampler`.
  void fill(const TileJob& job, const PacketSampler& sampler, const CameraRays* exactRays);
  // The packet holding sample `sample` of pixel (x, y), and the pixel's lane in it.
  std::size_t packetIndex(int x, int y, int sample) const {
    const int tileX = x / tileSize_, tileY = y / tileSize_;
    const int x0 = tileX * tileSize_, y0 = tileY * tileSize_;
    const int tileWidth = std::min(tileSize_, width_ - x0);
    const int tileHeight = std::min(tileSize_, height_ - y0);
    const int blocksAcross = (tileWidth + kBlockColumns - 1) / kBlockColumns;
    const int blocksDown = (tileHeight + kBlockRows - 1) / kBlockRows;
    const std::size_t tile = static_cast<std::size_t>(tileY) * tilesAcross_ + tileX;
    return tileFirstPacket_[tile] +
           static_cast<std::size_t>((sample * blocksDown + (y - y0) / kBlockRows) * blocksAcross +
                                    (x - x0) / kBlockColumns);
  }

  int width_ = 0, height_ = 0, samplesPerPixel_ = 1, tileSize_ = 1, tilesAcross_ = 1;
  bool withOrigins_ = false;
  std::vector<std::size_t> tileFirstPacket_;  // per tile (row-major), its first packet
  std::size_t samples_ = 0;
  std::vector<float> components_;
  std::vector<float> reach_;  // per packet, tables with origins only
};

}  // namespace confvis::embree
