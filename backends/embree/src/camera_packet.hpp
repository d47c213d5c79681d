#pragma once
// The camera rays of one packet of samples (up to 8 neighbouring pixels of a tile row, the same
// sample index each), traced. Straight cameras write their rays straight into the packet: plain
// and direction-table rays as whole structure-of-arrays packets, other straight rays lane by
// lane; exact stereo rays go through RayPaths.
#include <array>
#include <cstdint>

#include "camera_rays.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#include "packet_tracer.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

struct PacketSamples {
  int x = 0, y = 0;  // output pixels x .. x + count - 1 of row y
  int count = 0;     // 1 .. kPacketSize
  int sample = 0;    // index of the sample within each pixel
  std::array<std::uint32_t, kPacketSize> pixelSeeds{};  // pixelSeed() per lane, if samples > 1
};

// Fills `hits` for the packet; returns the number of camera rays cast (see traceStraight).
std::uint64_t traceCameraPacket(const EmbreeScene& scene, const CameraRays& rays,
                                const TileJob& job, const PacketSamples& samples,
                                PacketHits& hits);

}  // namespace confvis::embree
