// Two 8-ray packets traced with one rtcIntersect16 (traceStraightPair, where the device traces
// 16-ray packets natively) must give exactly the hits of two rtcIntersect8 calls: the rays are
// packed into and the hits unpacked from the wide packet lane by lane, and a lane put at the
// wrong offset, or a field left out, changes hits here.
#include <gtest/gtest.h>

#include <random>

#include "../src/packet_tracer.hpp"
#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace confvis {
namespace {

using embree::kPacketSize;
using embree::PacketHits;

// Two packets of rays from near the origin in random directions; the second packet's last
// `unused` lanes are not traced.
std::array<PacketHits, 2> randomPackets(std::mt19937& random, int unused) {
  std::normal_distribution<float> normal;
  std::uniform_real_distribution<float> offset(-0.2f, 0.2f);
  std::array<PacketHits, 2> hits{};
  for (int half = 0; half < 2; ++half)
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const glm::vec3 direction = glm::normalize(glm::vec3(normal(random), normal(random),
                                                           normal(random)));
      hits[half].setStraightRay(lane, {offset(random), offset(random), offset(random)},
                                direction);
      if (half == 1 && lane >= kPacketSize - unused) hits[half].valid[lane] = 0;
    }
  return hits;
}

TEST(EmbreePacketPair, SixteenWideTraceGivesTheHitsOfTwoEightWideOnes) {
  EmbreeDevice device;
  BuiltinSceneOptions options;
  const EmbreeScene scene(device, builtinScene("graph", options));  // silhouettes: misses too
  std::mt19937 random(7);
  int hitLanes = 0, missLanes = 0;
  for (int round = 0; round < 1500; ++round) {
    const int unused = round % 3 == 0 ? round % kPacketSize : 0;
    std::array<PacketHits, 2> wide = randomPackets(random, unused), narrow = wide;
    const std::array<int, 2> count = {kPacketSize, kPacketSize - unused};
    const std::array<int, 2> columns = {4, 4};
    const std::uint64_t wideRays = embree::traceStraightPair(scene.handle(), count, columns, wide,
                                                             true);
    const std::uint64_t narrowRays =
        embree::traceStraightPair(scene.handle(), count, columns, narrow, false);
    ASSERT_EQ(wideRays, narrowRays);
    for (int half = 0; half < 2; ++half)
      for (int lane = 0; lane < kPacketSize; ++lane) {
        SCOPED_TRACE(testing::Message() << "round " << round << " packet " << half << " lane "
                                        << lane);
        const RTCRayHit8& a = wide[half].rayhit;
        const RTCRayHit8& b = narrow[half].rayhit;
        ASSERT_EQ(wide[half].hit[lane], narrow[half].hit[lane]);
        if (!narrow[half].hit[lane]) {
          ++missLanes;
          continue;
        }
        ++hitLanes;
        EXPECT_EQ(a.hit.geomID[lane], b.hit.geomID[lane]);
        EXPECT_EQ(a.hit.primID[lane], b.hit.primID[lane]);
        EXPECT_EQ(a.hit.u[lane], b.hit.u[lane]);
        EXPECT_EQ(a.hit.v[lane], b.hit.v[lane]);
        EXPECT_EQ(a.ray.tfar[lane], b.ray.tfar[lane]);
        EXPECT_EQ(a.hit.Ng_x[lane], b.hit.Ng_x[lane]);
        EXPECT_EQ(a.hit.Ng_y[lane], b.hit.Ng_y[lane]);
        EXPECT_EQ(a.hit.Ng_z[lane], b.hit.Ng_z[lane]);
      }
  }
  // Both outcomes occur, so the comparison covers hits and misses.
  EXPECT_GT(hitLanes, 500);
  EXPECT_GT(missLanes, 500);
}

}  // namespace
}  // namespace confvis
