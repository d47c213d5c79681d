// A tracked head that moves every frame (issue 23): the stereo eyes' rays are computed per packet
// in float (exact rays' tails, fast rays' targets W(p), which a table shares across heads), and
// every frame must show its own head's rays: compared with a reference tracing in double (the
// cube map itself, the whole curve) of that head, the pixels agree; compared with the previous
// frame's head they must not (a frame a head move late is caught), nor may a render that reads
// a table built for the previous head.
#include <gtest/gtest.h>

#include <array>

#include "../src/camera_rays.hpp"
#include "../src/clearance.hpp"
#include "../src/direction_table.hpp"
#include "../src/tile_renderer.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/backends/wall_map_grid.hpp"
#include "render_test_support.hpp"

namespace confvis::embree {
namespace {

constexpr double kSphereRadius = 10.0;  // the checker-sphere's, around c
constexpr int kWallPixels = 64;

using test::dilationMap;

// Where the ray of the eye of `view` through its wall (physical direction d, reaching the wall at
// t = 1) meets the checker-sphere, traced in double with the cube map's own lookups: exact rays
// along the curve W(e + t u) (curvedRay, its bound to the dense curve is CurvedRayBound's),
// fast rays straight from the eye towards W(p). nullopt where no display is lit.
test::DirectionMap referenceTracing(const ConformalWarp& warp, const WallView& view,
                                    StereoRays rays) {
  return [&warp, view, rays](const glm::dvec3& d) -> std::optional<glm::dvec3> {
    const glm::dvec3 e = view.eye_position, c = warp.reference(), p = e + d;
    if (!(warp.lookup(p - c).alpha >= 0.5f)) return std::nullopt;
    if (rays == StereoRays::Fast) {
      const glm::dvec3 target = c + glm::length(p - c) * glm::normalize(warp.direction(p - c));
      return test::curveAtDistance({e - c}, glm::normalize(target - e), kSphereRadius);
    }
    std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
    glm::dvec3 tail;
    const int count = curvedRay(warp, e, glm::normalize(d), 12, vertices.data(), tail);
    std::vector<glm::dvec3> relative;
    for (int i = 0; i < count; ++i) relative.push_back(vertices[static_cast<std::size_t>(i)] - c);
    return test::curveAtDistance(relative, tail, kSphereRadius);
  };
}

RenderSettings stereoSettings(StereoRays rays, const glm::dvec3& head) {
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = {Eye::Left, Eye::Right};
  settings.stereoRays = rays;
  settings.walls = {"front", "left"};  // the left wall faces along the eyes' baseline
  settings.resolutionScale = test::scaleFor(kWallPixels);
  settings.head.position = head;
  return settings;
}

// The largest fraction of pixels, over the frame's images, that differ from the reference
// tracing of the eyes of `settings` (its head).
double worstMismatch(const RenderResult& frame, const DisplayConfig& config,
                     const RenderSettings& settings) {
  const ConformalWarp warp(dilationMap());
  const RenderPlan plan = planRender(config, &dilationMap(), settings);
  EXPECT_EQ(plan.images.size(), frame.images.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < plan.images.size() && i < frame.images.size(); ++i)
    worst = std::max(worst, test::checkerMismatch(frame.images[i].image, plan.images[i].view,
                                                  settings.resolutionScale,
                                                  referenceTracing(warp, plan.images[i].view,
                                                                   settings.stereoRays)));
  return worst;
}

// Five frames rendered into the last (as a frame loop does): the head still twice (the second
// frame reads the still head's tables), then moving 6 cm a frame.
TEST(EmbreeMovingHead, EveryFrameShowsItsOwnHeadsRays) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const std::vector<glm::dvec3> heads = {
      {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.06, 0.0, 0.0}, {0.06, 0.04, -0.04}, {0.0, 0.04, -0.1}};
  for (StereoRays rays : {StereoRays::Exact, StereoRays::Fast}) {
    SCOPED_TRACE(stereoRaysName(rays));
    EmbreeBackend backend;
    backend.setScene(builtinScene("checker-sphere"));
    RenderResult frame;
    for (std::size_t k = 0; k < heads.size(); ++k) {
      SCOPED_TRACE(k);
      const RenderSettings settings = stereoSettings(rays, heads[k]);
      backend.renderInto(config, &dilationMap(), settings, frame);
      const double own = worstMismatch(frame, config, settings);
      RecordProperty(std::string(stereoRaysName(rays)) + "_frame_" + std::to_string(k) +
                         "_mismatch",
                     std::to_string(own));
      EXPECT_LT(own, 0.01);
      if (k < 2) continue;
      // The previous frame's head: the comparison catches a frame that lags a move.
      EXPECT_GT(worstMismatch(frame, config, stereoSettings(rays, heads[k - 1])), 0.05);
    }
    // The fast rays' table serves every head; exact tails are per head and moving heads get none.
    const std::uint64_t tableSamples = frame.stats.embree.value().directionTableSamples;
    if (rays == StereoRays::Fast)
      EXPECT_GT(tableSamples, 0u);
    else
      EXPECT_EQ(tableSamples, 0u);
  }
}

// At the level of the tile renderer: the exact tails' table of the head's own rays draws the
// per-sample frame's pixels bit for bit and matches the reference; the previous head's table,
// read with this head's camera, fails it.
TEST(EmbreeMovingHead, APreviousHeadsExactTableFailsTheReference) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const ConformalWarp warp(dilationMap());
  EmbreeDevice device;
  const EmbreeScene scene(device, builtinScene("checker-sphere"));
  RenderSettings settings = stereoSettings(StereoRays::Exact, {0.06, 0.04, -0.04});
  settings.walls = {"front"};
  const PlannedImage planned = planRender(config, &dilationMap(), settings).images[0];
  settings.head.position = {0.0, 0.0, 0.0};
  const WallView previousView = planRender(config, &dilationMap(), settings).images[0].view;
  const Wall& wall = *planned.view.wall;
  const WallMapGrid grid(warp, wall,
                         WallMapGrid::spacingFor(wall, warp.reference(),
                                                 dilationMap().resolution(),
                                                 settings.resolutionScale));
  const auto camera = [&](const WallView& view) {
    CameraRays rays(view, settings.camera, warp, grid, StereoRays::Exact, 12);
    const double reach = rays.curvedReach();
    const double empty = clearance(scene, glm::vec3(settings.camera.position),
                                   static_cast<float>(1.01 * reach));
    rays.setEmptyRadius((1.0 - 1e-4) * empty - 1e-6 * reach);
    return rays;
  };
  const CameraRays rays = camera(planned.view), previousRays = camera(previousView);
  TileJob job;
  job.width = planned.width;
  job.height = planned.height;
  job.pixelToWall = {static_cast<double>(wall.width) / planned.width,
                     static_cast<double>(wall.height) / planned.height};
  const auto tableOf = [&](const CameraRays& of) {
    return DirectionTable(job, of);
  };
  const DirectionTable own = tableOf(rays), stale = tableOf(previousRays);
  const auto render = [&](const DirectionTable* table) {
    TileJob withTable = job;
    withTable.directions = table;
    ImageRGBA image;
    Progress progress("test", 1, false);
    RayCounters counters;
    renderTiles(scene, rays, withTable, image, progress, counters);
    return image;
  };
  const ImageRGBA perSample = render(nullptr), fromOwn = render(&own), fromStale = render(&stale);
  EXPECT_EQ(fromOwn.pixels, perSample.pixels);
  const test::DirectionMap reference = referenceTracing(warp, planned.view, StereoRays::Exact);
  EXPECT_LT(test::checkerMismatch(fromOwn, planned.view, settings.resolutionScale, reference),
            0.01);
  EXPECT_GT(test::checkerMismatch(fromStale, planned.view, settings.resolutionScale, reference),
            0.05);
}

}  // namespace
}  // namespace confvis::embree
