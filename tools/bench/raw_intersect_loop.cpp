#include "raw_intersect_loop.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../../backends/embree/src/affine_directions.hpp"
#include "../../backends/embree/src/camera_packet.hpp"
#include "confvis/backends/wall_map_grid.hpp"
#include "confvis/engine/view.hpp"

namespace confvis::bench {

namespace {

int scaled(int pixels, double scale) {
  return std::max(1, static_cast<int>(std::lround(pixels * scale)));
}

}  // namespace

ConformalDirections conformalDirections(const RetargetMap& map, const DisplayConfig& config,
                                        double scale) {
  const ConformalWarp warp(map);
  ConformalDirections out;
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

RawLoopResult rawIntersectLoop(const EmbreeScene& scene, const DisplayConfig& config,
                               double scale, const ConformalDirections* conformal) {
  constexpr int kTile = 16;  // the renderer's default tile (EmbreeOptions::tileSize)
  std::atomic<std::uint64_t> rays{0}, hits{0};
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t w = 0; w < config.walls.size(); ++w) {
    const Wall& wall = config.walls[w];
    const glm::vec3* table = conformal ? conformal->walls[w].data() : nullptr;
    const WallView view = makeWallView(wall, config.reference);
    const int width = scaled(wall.width, scale), height = scaled(wall.height, scale);
    const double sx = static_cast<double>(wall.width) / width;
    const double sy = static_cast<double>(wall.height) / height;
    const glm::vec3 origin(view.eye_position);
    // The direction is affine in the wall-pixel position; like the renderer's plain rays
    // (CameraRays), evaluate it in float and normalise per ray, a packet at a time.
    const glm::dvec3 base = view.rayDirection(0.0, 0.0);
    const embree::AffineDirections directions{glm::vec3(base),
                                              glm::vec3(view.rayDirection(1.0, 0.0) - base),
                                              glm::vec3(view.rayDirection(0.0, 1.0) - base)};
    const int across = (width + kTile - 1) / kTile, tiles = across * ((height + kTile - 1) / kTile);
    // The renderer's layout: tiles in parallel, within a tile packets of 4 x 2 pixels
    // (embree::PacketSamples), rows of them.
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      std::uint64_t tileRays = 0, tileHits = 0;
      for (int tile = r.begin(); tile != r.end(); ++tile) {
        const int x0 = (tile % across) * kTile, y0 = (tile / across) * kTile;
        const int x1 = std::min(x0 + kTile, width), y1 = std::min(y0 + kTile, height);
        for (int y = y0; y < y1; y += embree::kBlockRows)
          for (int x = x0; x < x1; x += embree::kBlockColumns) {
            alignas(32) int valid[8];
            alignas(32) RTCRayHit8 rh;
            alignas(32) std::array<float, 8> px{}, py{};
            const int columns = std::min(embree::kBlockColumns, x1 - x);
            const int count = columns * std::min(embree::kBlockRows, y1 - y);
            for (int lane = 0; lane < 8; ++lane) valid[lane] = lane < count ? -1 : 0;
            if (table) {
              for (int lane = 0; lane < 8; ++lane) {
                const int l = std::min(lane, count - 1);
                const glm::vec3 d = table[static_cast<std::size_t>(y + l / columns) * width + x +
                                          l % columns];
                rh.ray.dir_x[lane] = d.x, rh.ray.dir_y[lane] = d.y, rh.ray.dir_z[lane] = d.z;
                if (d == glm::vec3(0.0f)) valid[lane] = 0;  // unlit
              }
            } else {
              embree::pixelCentres(x, y, columns, count, sx, sy, px, py);
              directions.at(px, py, rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
            }
            for (int lane = 0; lane < 8; ++lane) {
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
            rtcIntersect8(valid, scene.handle(), &context, &rh);
            for (int lane = 0; lane < 8; ++lane)
              if (valid[lane]) {
                ++tileRays;
                tileHits += rh.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID;
              }
          }
      }
      rays += tileRays;
      hits += tileHits;
    });
  }
  return {rays.load(), hits.load(),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

RawLoopResult rawIntersect16Loop(const EmbreeScene& scene, const DisplayConfig& config,
                                 double scale) {
  constexpr int kTile = 16;
  std::atomic<std::uint64_t> rays{0}, hits{0};
  const auto start = std::chrono::steady_clock::now();
  for (const Wall& wall : config.walls) {
    const WallView view = makeWallView(wall, config.reference);
    const int width = scaled(wall.width, scale), height = scaled(wall.height, scale);
    const double sx = static_cast<double>(wall.width) / width;
    const double sy = static_cast<double>(wall.height) / height;
    const glm::vec3 origin(view.eye_position);
    const glm::dvec3 base = view.rayDirection(0.0, 0.0);
    const embree::AffineDirections directions{glm::vec3(base),
                                              glm::vec3(view.rayDirection(1.0, 0.0) - base),
                                              glm::vec3(view.rayDirection(0.0, 1.0) - base)};
    const int across = (width + kTile - 1) / kTile, tiles = across * ((height + kTile - 1) / kTile);
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      std::uint64_t tileRays = 0, tileHits = 0;
      for (int tile = r.begin(); tile != r.end(); ++tile) {
        const int x0 = (tile % across) * kTile, y0 = (tile / across) * kTile;
        const int x1 = std::min(x0 + kTile, width), y1 = std::min(y0 + kTile, height);
        for (int y = y0; y < y1; y += 2 * embree::kBlockRows)
          for (int x = x0; x < x1; x += embree::kBlockColumns) {
            alignas(64) int valid[16];
            alignas(64) RTCRayHit16 rh;
            const int columns = std::min(embree::kBlockColumns, x1 - x);
            for (int half = 0; half < 2; ++half) {
              const int top = y + half * embree::kBlockRows;
              const int count = top < y1 ? columns * std::min(embree::kBlockRows, y1 - top) : 0;
              alignas(32) std::array<float, 8> px{}, py{};
              alignas(32) float dx[8], dy[8], dz[8];
              if (count > 0) {
                embree::pixelCentres(x, top, columns, count, sx, sy, px, py);
                directions.at(px, py, dx, dy, dz);
              }
              for (int lane = 0; lane < 8; ++lane) {
                const int at = 8 * half + lane;
                valid[at] = lane < count ? -1 : 0;
                rh.ray.dir_x[at] = count > 0 ? dx[lane] : 0.0f;
                rh.ray.dir_y[at] = count > 0 ? dy[lane] : 0.0f;
                rh.ray.dir_z[at] = count > 0 ? dz[lane] : 1.0f;
              }
            }
            for (int lane = 0; lane < 16; ++lane) {
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
            rtcIntersect16(valid, scene.handle(), &context, &rh);
            for (int lane = 0; lane < 16; ++lane)
              if (valid[lane]) {
                ++tileRays;
                tileHits += rh.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID;
              }
          }
      }
      rays += tileRays;
      hits += tileHits;
    });
  }
  return {rays.load(), hits.load(),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

}  // namespace confvis::bench
