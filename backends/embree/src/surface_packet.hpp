#pragma once
// The surface under each lane of a traced packet: the shading normal (vertex normals
// interpolated with Embree's barycentrics, or the geometric normal where the mesh has none or
// they cancel; not normalised) and the base colour (Scene::baseColorAt: material factor times
// the bilinear texture sample). Lanes without a hit get zeros.
#include <array>

#include "confvis/backends/embree/embree_scene.hpp"
#include "packet_tracer.hpp"

namespace confvis::embree {

struct SurfacePacket {
  alignas(32) std::array<float, kPacketSize> nx, ny, nz;
  alignas(32) std::array<float, kPacketSize> red, green, blue;
};

// The tracers' lanes without a hit must carry zero barycentrics and normal (they do).
void surfaceAt(const EmbreeScene& scene, const PacketHits& hits, SurfacePacket& surface);

}  // namespace confvis::embree
