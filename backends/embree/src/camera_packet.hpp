#pragma once
// The camera rays of one packet of samples (up to 8 neighbouring pixels of a tile row, the same
// sample index each), traced. Straight cameras write their rays straight into the packet: plain
// and direction-table rays as whole structure-of-arrays packets, other straight rays lane by
// lane; exact stereo rays go through RayPaths.
#include <algorithm>
#include <array>
#include <cstdint>

#include "camera_rays.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#include "packet_tracer.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class TailLattice;

// A packet's pixels: a block of up to kBlockColumns x kBlockRows output pixels inside a tile,
// read row by row (lane i: pixel (x + i % columns, y + i / columns)). Two rows of four rather
// than a row of eight: the rays of a packet then span about half the angle, which where the map
// squeezes (the missing ceiling) and on finely meshed scenes lets Embree's packet traversal
// visit fewer nodes: a raw rtcIntersect8 loop over 1M triangles runs ~15 % faster (conformal
// rays: ~17 %).
constexpr int kBlockColumns = 4, kBlockRows = 2;
static_assert(kBlockColumns * kBlockRows == kPacketSize);

struct PacketSamples {
  int x = 0, y = 0;  // the block's top-left output pixel
  int columns = 0;   // 1 .. kBlockColumns: the block's pixels per row inside the tile
  int count = 0;     // 1 .. kPacketSize: columns x the block's rows inside the tile
  int sample = 0;    // index of the sample within each pixel
  std::array<std::uint32_t, kPacketSize> pixelSeeds{};  // pixelSeed() per lane, if samples > 1

  int laneX(int lane) const { return x + lane % columns; }
  int laneY(int lane) const { return y + lane / columns; }
};

// The packet of the block whose top-left pixel is (x, y), in a tile ending before (x1, y1): the
// one definition of the layout the renderer, its direction table and the raw benchmark loop share.
inline PacketSamples blockAt(int x, int y, int x1, int y1) {
  PacketSamples samples;
  samples.x = x;
  samples.y = y;
  samples.columns = std::min(kBlockColumns, x1 - x);
  samples.count = samples.columns * std::min(kBlockRows, y1 - y);
  return samples;
}

// The wall-pixel positions of the packet's samples, in float (lanes from samples.count on repeat
// the last sample): the pixel centres at 1 spp (pixelCentres), else samplePosition with the
// lanes' pixelSeeds. The renderer and its direction tables sample at these.
void packetPositions(const TileJob& job, const PacketSamples& samples,
                     std::array<float, kPacketSize>& px, std::array<float, kPacketSize>& py);

// Fills `hits` for the packet; returns the number of camera rays cast (see traceStraight).
// `tails`: the tile's TailLattice, which exact stereo rays without a table take their tails
// from (null: CameraRays::exactTails per sample).
std::uint64_t traceCameraPacket(const EmbreeScene& scene, const CameraRays& rays,
                                const TileJob& job, const PacketSamples& samples,
                                PacketHits& hits, TailLattice* tails = nullptr);

// Two packets (of a tile's 4 x 4 pixels) at once: straight rays in one 16-wide intersection
// (traceStraightPair), curved ones packet by packet. samples[1].count may be 0 (the tile's last
// row of blocks), which traces nothing there.
std::uint64_t traceCameraPacketPair(const EmbreeScene& scene, const CameraRays& rays,
                                    const TileJob& job, const std::array<PacketSamples, 2>& samples,
                                    std::array<PacketHits, 2>& hits,
                                    TailLattice* tails = nullptr);

}  // namespace confvis::embree
