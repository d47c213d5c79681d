#include "raw_intersect_loop.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../../backends/embree/src/affine_directions.hpp"
#include "../../backends/embree/src/camera_packet.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/backends/wall_map_grid.hpp"
#include "confvis/engine/view.hpp"

namespace confvis::bench {

namespace {

int scaled(int pixels, double scale) {
  return std::max(1, static_cast<int>(std::lround(pixels * scale)));
}

// One wall's output pixels and plain rays, as the renderer's CameraRays make them: the
// direction is affine in the wall-pixel position, evaluated in float and normalised per ray.
struct WallRays {
  std::size_t wall = 0;
  int width = 0, height = 0;
  double sx = 1, sy = 1;  // wall pixels per output pixel
  glm::vec3 origin{0.0f};
  embree::AffineDirections directions;
};

// The fields every raw ray shares (origin, bounds, flags) and an empty hit, lanes [0, N).
template <int N, typename RayHitN>
void setCommonFields(RayHitN& rh, const glm::vec3& origin) {
  for (int lane = 0; lane < N; ++lane) {
    rh.ray.org_x[lane] = origin.x;
    rh.ray.org_y[lane] = origin.y;
    rh.ray.org_z[lane] = origin.z;
    rh.ray.tnear[lane] = 0.0f;
    rh.ray.tfar[lane] = std::numeric_limits<float>::infinity();
    rh.ray.time[lane] = 0.0f;
    rh.ray.mask[lane] = ~0u;
    rh.ray.id[lane] = static_cast<unsigned>(lane);
    rh.ray.flags[lane] = 0;
    rh.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
  }
}

// Adds the traced lanes and those that hit to `rays` and `hits`.
template <int N, typename RayHitN>
void countLanes(const int* valid, const RayHitN& rh, std::uint64_t& rays, std::uint64_t& hits) {
  for (int lane = 0; lane < N; ++lane)
    if (valid[lane]) {
      ++rays;
      hits += rh.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID;
    }
}

// Wall w's output size at `scale` and its plain rays.
WallRays raysOfWall(const DisplayConfig& config, std::size_t w, double scale) {
  const Wall& wall = config.walls[w];
  const WallView view = makeWallView(wall, config.reference);
  WallRays rays;
  rays.wall = w;
  rays.width = scaled(wall.width, scale), rays.height = scaled(wall.height, scale);
  rays.sx = static_cast<double>(wall.width) / rays.width;
  rays.sy = static_cast<double>(wall.height) / rays.height;
  rays.origin = glm::vec3(view.eye_position);
  const glm::dvec3 base = view.rayDirection(0.0, 0.0);
  rays.directions = {glm::vec3(base), glm::vec3(view.rayDirection(1.0, 0.0) - base),
                     glm::vec3(view.rayDirection(0.0, 1.0) - base)};
  return rays;
}

// The renderer's layout for every wall: 16-pixel tiles in parallel (TBB), each traced by
// traceTile(wall, context, x0, y0, x1, y1, rays, hits).
template <typename TraceTile>
RawLoopResult forEachTile(const DisplayConfig& config, double scale, TraceTile traceTile) {
  constexpr int kTile = 16;  // the renderer's default tile (EmbreeOptions::tileSize)
  std::atomic<std::uint64_t> rays{0}, hits{0};
  const auto start = SteadyClock::now();
  for (std::size_t w = 0; w < config.walls.size(); ++w) {
    const WallRays wallRays = raysOfWall(config, w, scale);
    const int across = (wallRays.width + kTile - 1) / kTile;
    const int tiles = across * ((wallRays.height + kTile - 1) / kTile);
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      std::uint64_t tileRays = 0, tileHits = 0;
      for (int tile = r.begin(); tile != r.end(); ++tile) {
        const int x0 = (tile % across) * kTile, y0 = (tile / across) * kTile;
        traceTile(wallRays, context, x0, y0, std::min(x0 + kTile, wallRays.width),
                  std::min(y0 + kTile, wallRays.height), tileRays, tileHits);
      }
      rays += tileRays;
      hits += tileHits;
    });
  }
  return {rays.load(), hits.load(),
          secondsSince(start)};
}

}  // namespace

DirectionTables conformalDirections(const RetargetMap& map, const DisplayConfig& config,
                                        double scale) {
  const ConformalWarp warp(map);
  DirectionTables out;
  for (const Wall& wall : config.walls) {
    const int width = scaled(wall.width, scale), height = scaled(wall.height, scale);
    const WallMapGrid grid(warp, wall,
                           WallMapGrid::spacingFor(wall, warp.reference(), map.ray.faceSize, scale));
    const double sx = static_cast<double>(wall.width) / width;
    const double sy = static_cast<double>(wall.height) / height;
    std::vector<glm::vec3> directions(static_cast<std::size_t>(width) * height, glm::vec3(0.0f));
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const WallMapGrid::Sample s = grid.at(static_cast<float>((x + 0.5) * sx),
                                              static_cast<float>((y + 0.5) * sy));
        if (s.alpha >= 0.5f)
          directions[static_cast<std::size_t>(y) * width + x] = glm::normalize(s.direction);
      }
    out.walls.push_back(std::move(directions));
  }
  return out;
}

namespace {

// The rays of the packet of 4 x 2 pixels (embree::PacketSamples) at (x, y) in a tile ending at
// (x1, y1), as the renderer makes them: 8 lanes of directions (lanes from the block's pixel count
// on repeat its last pixel) and -1 in `valid` for the lanes to trace; plain directions or, given
// `table`, the conformal frame's (its unlit pixels not traced).
void blockRays(const WallRays& w, const glm::vec3* table, int x, int y, int x1, int y1, float* dx,
               float* dy, float* dz, int* valid) {
  const embree::PacketSamples block = embree::blockAt(x, y, x1, y1);
  const int columns = block.columns, count = block.count;
  for (int lane = 0; lane < 8; ++lane) valid[lane] = lane < count ? -1 : 0;
  if (table) {
    for (int lane = 0; lane < 8; ++lane) {
      const int l = std::min(lane, count - 1);
      const glm::vec3 d =
          table[static_cast<std::size_t>(y + l / columns) * w.width + x + l % columns];
      dx[lane] = d.x, dy[lane] = d.y, dz[lane] = d.z;
      if (d == glm::vec3(0.0f)) valid[lane] = 0;  // unlit
    }
  } else {
    alignas(32) std::array<float, 8> px{}, py{};
    embree::pixelCentres(x, y, columns, count, w.sx, w.sy, px, py);
    w.directions.at(px, py, dx, dy, dz);
  }
}

}  // namespace

DirectionTables plainDirections(const DisplayConfig& config, double scale) {
  DirectionTables out;
  for (std::size_t w = 0; w < config.walls.size(); ++w) {
    const WallRays rays = raysOfWall(config, w, scale);
    std::vector<glm::vec3> directions(static_cast<std::size_t>(rays.width) * rays.height);
    for (int y = 0; y < rays.height; ++y)
      for (int x = 0; x < rays.width; ++x) {
        std::array<float, 1> px{}, py{};  // the renderer's centre and float arithmetic
        embree::pixelCentres(x, y, 1, 1, rays.sx, rays.sy, px, py);
        glm::vec3& d = directions[static_cast<std::size_t>(y) * rays.width + x];
        rays.directions.at(px, py, &d.x, &d.y, &d.z);
      }
    out.walls.push_back(std::move(directions));
  }
  return out;
}

RawLoopResult rawIntersectLoop(const EmbreeScene& scene, const DisplayConfig& config,
                               double scale, const DirectionTables* tables) {
  // Within a tile packets of 4 x 2 pixels (embree::PacketSamples), rows of them.
  return forEachTile(config, scale, [&](const WallRays& w, RTCIntersectContext& context, int x0,
                                        int y0, int x1, int y1, std::uint64_t& rays,
                                        std::uint64_t& hits) {
    const glm::vec3* table = tables ? tables->walls[w.wall].data() : nullptr;
    for (int y = y0; y < y1; y += embree::kBlockRows)
      for (int x = x0; x < x1; x += embree::kBlockColumns) {
        alignas(32) int valid[8];
        alignas(32) RTCRayHit8 rh;
        blockRays(w, table, x, y, x1, y1, rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z, valid);
        setCommonFields<8>(rh, w.origin);
        rtcIntersect8(valid, scene.handle(), &context, &rh);
        countLanes<8>(valid, rh, rays, hits);
      }
  });
}

RawLoopResult rawIntersect16Loop(const EmbreeScene& scene, const DisplayConfig& config,
                                 double scale, const DirectionTables* tables) {
  return forEachTile(config, scale, [&](const WallRays& w, RTCIntersectContext& context, int x0,
                                        int y0, int x1, int y1, std::uint64_t& rays,
                                        std::uint64_t& hits) {
    const glm::vec3* table = tables ? tables->walls[w.wall].data() : nullptr;
    for (int y = y0; y < y1; y += 2 * embree::kBlockRows)
      for (int x = x0; x < x1; x += embree::kBlockColumns) {
        alignas(64) int valid[16];
        alignas(64) RTCRayHit16 rh;
        for (int half = 0; half < 2; ++half) {  // the renderer's two packets, lanes 0-7 and 8-15
          const int top = y + half * embree::kBlockRows, first = 8 * half;
          if (top < y1) {
            blockRays(w, table, x, top, x1, y1, rh.ray.dir_x + first, rh.ray.dir_y + first,
                      rh.ray.dir_z + first, valid + first);
            continue;
          }
          for (int lane = first; lane < first + 8; ++lane) {  // past the tile: not traced
            valid[lane] = 0;
            rh.ray.dir_x[lane] = rh.ray.dir_y[lane] = 0.0f, rh.ray.dir_z[lane] = 1.0f;
          }
        }
        setCommonFields<16>(rh, w.origin);
        rtcIntersect16(valid, scene.handle(), &context, &rh);
        countLanes<16>(valid, rh, rays, hits);
      }
  });
}

}  // namespace confvis::bench
