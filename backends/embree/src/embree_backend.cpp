#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/headlight.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "camera_rays.hpp"
#include "clearance.hpp"
#include "direction_table.hpp"
#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "tail_grid.hpp"
#include "tile_renderer.hpp"

namespace confvis {

struct EmbreeBackend::Impl {
  explicit Impl(const EmbreeOptions& o) : options(o) {}

  // The map seen from `wall` (see WallMapGrid), built once per map, wall and output size.
  const WallMapGrid& wallGrid(const ConformalWarp& warp, std::uint64_t mapFingerprint,
                              const Wall& wall, double scale) {
    const std::uint64_t key = gridKey(warp, mapFingerprint, wall, scale);
    auto found = grids.find(key);
    if (found != grids.end()) {
      found->second.lastUsed = renders;
      return *found->second.grid;
    }
    if (grids.size() >= 64) grids.clear();  // a bounded cache: displays have few walls
    auto grid = std::make_unique<WallMapGrid>(warp, wall, spacingFor(warp, wall, scale));
    return *grids.emplace(key, GridEntry{std::move(grid), renders, nullptr}).first->second.grid;
  }

  // The exact stereo tails' grid of `wall` (tail_grid.hpp), built with the first exact stereo
  // frame of a map and kept with its WallMapGrid; `buildSeconds` accumulates the build time.
  const embree::TailGrid& tailGrid(const ConformalWarp& warp, std::uint64_t mapFingerprint,
                                   const Wall& wall, double scale, double& buildSeconds) {
    wallGrid(warp, mapFingerprint, wall, scale);
    GridEntry& entry = grids.at(gridKey(warp, mapFingerprint, wall, scale));
    if (!entry.tails) {
      const auto start = SteadyClock::now();
      entry.tails = std::make_unique<embree::TailGrid>(
          warp, wall,
          embree::TailGrid::spacingFor(wall, warp.reference(), warp.map().resolution(), scale),
          embree::TailGrid::marginFor(wall, warp.reference()));
      buildSeconds += secondsSince(start);
    }
    return *entry.tails;
  }

  // Gives back the grids and tables of images not rendered in the last kIdleRenders renders:
  // a walk that swaps in a new map every few seconds would otherwise keep every old map's
  // tables, up to kMaxTableBytes (found by tools/soak/walk_soak.py: +0.7 MB per re-bake).
  void dropIdleEntries() {
    const auto idle = [&](std::uint64_t lastUsed) { return renders - lastUsed > kIdleRenders; };
    std::erase_if(grids, [&](const auto& item) { return idle(item.second.lastUsed); });
    std::erase_if(tables, [&](const auto& item) {
      if (!idle(item.second.lastUsed)) return false;
      if (item.second.table) tableBytes -= item.second.table->bytes();
      return true;
    });
  }

  // The straight rays of one image (see DirectionTable), or null: the centre eye's directions,
  // or a stereo eye's (fast rays' directions, exact rays' tails). Built on the second render of
  // the same image (the same map, wall, eye, output size and samples): a one-shot render, or a
  // tracked head that moves every frame, would pay a full map lookup per sample for the table
  // on top of the frame. Bounded to kMaxTableBytes in all; `buildSeconds` accumulates the build
  // time.
  const embree::DirectionTable* rayTable(const WallMapGrid& grid, std::uint64_t gridKey,
                                         const glm::dvec3& reference,
                                         const embree::CameraRays& rays, const WallView& view,
                                         StereoRays stereoRays, const embree::TileJob& job,
                                         double& buildSeconds) {
    const bool centre = rays.centreEyeConformal();
    const bool withOrigins = !centre && stereoRays == StereoRays::Exact;
    // Fast stereo rays' targets W(p) do not depend on the eye; one sample a pixel sits at its
    // centre whatever the image's seed, so both eyes share that table (and a moving head reads
    // it).
    const bool anyEye = !centre && stereoRays == StereoRays::Fast;
    std::uint64_t key = gridKey;
    const int seed = anyEye && job.samplesPerPixel == 1 ? -1 : static_cast<int>(job.seed);
    for (int value : {job.width, job.height, job.samplesPerPixel, seed,
                      centre ? 0 : 1 + static_cast<int>(stereoRays)})
      key = mixHash(key, static_cast<double>(value));
    if (!centre && !anyEye)  // the eye's place relative to the warp's centre decides the rays
      for (int i = 0; i < 3; ++i) key = mixHash(key, view.eye_position[i] - reference[i]);
    TableEntry& entry = tables[key];
    // Renders, not lookups, count: the second image of a frame that shares a table (both eyes)
    // must not build it on the first frame.
    if (entry.lastUsed != renders) ++entry.renders;
    entry.lastUsed = renders;
    if (entry.table || entry.renders < 2) return entry.table.get();
    const std::size_t bytes = static_cast<std::size_t>(job.width) *
                              static_cast<std::size_t>(job.height) *
                              static_cast<std::size_t>(job.samplesPerPixel) *
                              (withOrigins ? 6 : 3) * sizeof(float);
    if (bytes > kMaxTableBytes) return nullptr;
    if (tableBytes + bytes > kMaxTableBytes) {  // make room: drop every built table
      for (auto& [k, other] : tables) other.table.reset();
      tableBytes = 0;
    }
    const auto start = SteadyClock::now();
    if (centre) {
      entry.table = std::make_unique<embree::DirectionTable>(grid, job);
    } else if (withOrigins) {
      entry.table = std::make_unique<embree::DirectionTable>(job, rays);
    } else {
      entry.table = std::make_unique<embree::DirectionTable>(
          job,
          [&rays](const float* px, const float* py, int count, float* run) {
            rays.fastTargets(px, py, count, run);
            return 0.0f;
          },
          false);
    }
    buildSeconds += secondsSince(start);
    tableBytes += entry.table->bytes();
    return entry.table.get();
  }

  static double spacingFor(const ConformalWarp& warp, const Wall& wall, double scale) {
    return WallMapGrid::spacingFor(wall, warp.reference(), warp.map().resolution(), scale);
  }

  static std::uint64_t gridKey(const ConformalWarp& warp, std::uint64_t mapFingerprint,
                               const Wall& wall, double scale) {
    std::uint64_t key = mapFingerprint;
    for (const glm::dvec3& corner : {wall.lowerLeft, wall.lowerRight, wall.upperLeft})
      for (int i = 0; i < 3; ++i) key = mixHash(key, corner[i]);
    for (double value : {wall.bezel.left, wall.bezel.right, wall.bezel.bottom, wall.bezel.top,
                         static_cast<double>(wall.width), static_cast<double>(wall.height),
                         spacingFor(warp, wall, scale)})
      key = mixHash(key, value);
    return key;
  }

  // 576 MB: 48M centre-eye samples (five 1920^2 walls at 2 spp, or one frame's worth of a large
  // display at 1 spp), or 24M exact stereo samples (five 1920^2 walls' two eyes at 1 spp hold
  // 37M: over the cap, so full-resolution exact stereo computes its tails every frame).
  static constexpr std::size_t kMaxTableBytes = std::size_t{576} << 20;
  static constexpr std::uint64_t kIdleRenders = 8;
  struct TableEntry {
    int renders = 0;
    std::uint64_t lastUsed = 0;  // `renders` of Impl when last looked up
    std::unique_ptr<embree::DirectionTable> table;
  };
  struct GridEntry {
    std::unique_ptr<WallMapGrid> grid;
    std::uint64_t lastUsed = 0;
    std::unique_ptr<embree::TailGrid> tails;  // exact stereo only
  };

  EmbreeOptions options;
  embree::SimdLevel simd =
      options.baselineShading ? embree::SimdLevel::Sse2 : embree::detectedSimdLevel();
  EmbreeDevice device;
  std::unique_ptr<EmbreeScene> scene;
  std::map<std::uint64_t, GridEntry> grids;
  std::map<std::uint64_t, TableEntry> tables;
  std::size_t tableBytes = 0;  // held by `tables`
  std::uint64_t renders = 0;   // renderInto calls so far
};

EmbreeBackend::EmbreeBackend(const EmbreeOptions& options)
    : impl_(std::make_unique<Impl>(options)) {
  if (options.tileSize < 1)
    throw Error(ErrorCode::InvalidInput, "Embree tile size must be positive");
  if (options.ambientOcclusionSamples < 1 || options.ambientOcclusionDistance < 0.0)
    throw Error(ErrorCode::InvalidInput,
                "ambient occlusion needs at least one sample and a distance >= 0");
}

EmbreeBackend::~EmbreeBackend() = default;

void EmbreeBackend::setScene(const Scene& scene) {
  impl_->scene.reset();
  impl_->scene = std::make_unique<EmbreeScene>(impl_->device, scene);
}

RenderResult EmbreeBackend::render(const DisplayConfig& config, const RetargetMap* map,
                                   const RenderSettings& settings) {
  RenderResult result;
  renderInto(config, map, settings, result);
  return result;
}

void EmbreeBackend::renderInto(const DisplayConfig& config, const RetargetMap* map,
                               const RenderSettings& settings, RenderResult& result) {
  if (!impl_->scene)
    throw Error(ErrorCode::InvalidInput, "Embree backend: setScene must come before render");
  const RenderPlan plan = planRender(config, map, settings);
  // The previous frame's images: their pixel storage is rendered over where the size agrees.
  std::vector<WallImage> previous = std::move(result.images);
  result = RenderResult{};
  std::optional<ConformalWarp> warp;
  std::uint64_t mapFingerprint = 0;
  ++impl_->renders;
  const auto setupStart = SteadyClock::now();
  if (settings.mode == RenderMode::Conformal) {
    warp.emplace(*map);
    mapFingerprint = warp->fingerprint();
    for (const PlannedImage& image : plan.images)
      impl_->wallGrid(*warp, mapFingerprint, *image.view.wall, settings.resolutionScale);
  }
  double mapBuildSeconds =  // a plain frame builds no map tables
      warp ? secondsSince(setupStart)
           : 0.0;
  std::uint64_t tableSamples = 0;  // camera samples whose map direction came from a table
  double tableBuildSeconds = 0.0;  // inside the render loop, but not rendering

  const EmbreeScene& scene = *impl_->scene;
  embree::TileJob job;
  job.samplesPerPixel = settings.samplesPerPixel;
  job.tileSize = impl_->options.tileSize;
  job.shading.ambientOcclusion = settings.ambientOcclusion;
  job.shading.occlusionSamples = impl_->options.ambientOcclusionSamples;
  job.shading.simd = impl_->simd;
  const double distance = impl_->options.ambientOcclusionDistance > 0.0
                              ? impl_->options.ambientOcclusionDistance
                              : 0.05 * scene.diagonal();
  job.shading.occlusionDistance = static_cast<float>(distance);
  job.shading.surfaceOffset = static_cast<float>(std::max(1e-6, 1e-5 * scene.diagonal()));

  std::size_t totalTiles = 0;
  for (const PlannedImage& image : plan.images)
    totalTiles += embree::tileCount(image.width, image.height, job.tileSize);
  Progress progress("render", totalTiles, settings.showProgress);

  std::optional<tbb::global_control> threadLimit;
  if (impl_->options.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<std::size_t>(impl_->options.threads));

  embree::RayCounters counters;
  EmbreeFrameStats stats;
  const auto start = SteadyClock::now();
  for (std::size_t i = 0; i < plan.images.size(); ++i) {
    const PlannedImage& planned = plan.images[i];
    const Wall& wall = *planned.view.wall;
    const WallMapGrid* grid =
        warp ? &impl_->wallGrid(*warp, mapFingerprint, wall, settings.resolutionScale) : nullptr;
    const ViewOverride* custom = planned.custom ? &*planned.custom : nullptr;
    embree::CameraRays rays =
        warp ? embree::CameraRays(planned.view, settings.camera, *warp, *grid, settings.stereoRays,
                                  impl_->options.curvedRaySegments, custom)
             : embree::CameraRays(planned.view, settings.camera, config.reference, custom);
    if (!rays.straight()) {
      // Exact stereo: the curves bend within the ball around the warp's centre that the scene
      // keeps out of (a margin for float rounding); only what leaves it is traced.
      // The query's radius caps its answer: a little beyond the reach, so that a scene keeping
      // farther than every curve bends gets a ball that holds them all (the margins below).
      const double reach = rays.curvedReach();
      const double empty = embree::clearance(scene, glm::vec3(settings.camera.position),
                                             static_cast<float>(1.01 * reach));
      rays.setEmptyRadius((1.0 - 1e-4) * empty - 1e-6 * reach);
      if (!rays.overridden())
        rays.setTailGrid(&impl_->tailGrid(*warp, mapFingerprint, wall, settings.resolutionScale,
                                          tableBuildSeconds));
    }
    job.width = planned.width;
    job.height = planned.height;
    job.pixelToWall = {static_cast<double>(wall.width) / planned.width,
                       static_cast<double>(wall.height) / planned.height};
    job.seed = static_cast<std::uint32_t>(planned.wallIndex * 3 + static_cast<int>(planned.eye));
    job.directions = nullptr;
    // Conformal frames light from the eye's headlight position, as Vulkan does; for rays that
    // start there (the eye at c, fast stereo) that is the light along the ray.
    job.shading.pointHeadlight = warp.has_value() && custom == nullptr;
    if (job.shading.pointHeadlight)
      job.shading.headlight = glm::vec3(
          headlightPosition(planned.view.eye_position, config, map, settings.camera));
    // An override's pixel is not the wall's pixel at the same position: no per-wall-pixel table.
    if (warp && !rays.overridden()) {
      job.directions = impl_->rayTable(
          *grid, Impl::gridKey(*warp, mapFingerprint, wall, settings.resolutionScale),
          warp->reference(), rays,
          planned.view, settings.stereoRays, job, tableBuildSeconds);
      if (job.directions) tableSamples += job.directions->sampleCount();
    }
    WallImage out;
    if (i < previous.size()) out.image = std::move(previous[i].image);
    out.wall = planned.view.wall->name;
    out.eye = planned.eye;
    const auto imageStart = SteadyClock::now();
    embree::renderTiles(scene, rays, job, out.image, progress, counters);
    const double seconds =
        secondsSince(imageStart);
    stats.images.push_back({out.wall, out.eye, job.width, job.height, seconds});
    result.images.push_back(std::move(out));
  }
  const double seconds =
      secondsSince(start) -
      tableBuildSeconds;
  mapBuildSeconds += tableBuildSeconds;
  impl_->dropIdleEntries();
  progress.finish();
  impl_->device.check("rendering");

  stats.threads = impl_->options.threads > 0 ? impl_->options.threads
                                              : tbb::this_task_arena::max_concurrency();
  stats.bvhBuildSeconds = scene.buildSeconds();
  stats.mapBuildSeconds = mapBuildSeconds;
  stats.directionTableSamples = tableSamples;
  stats.cachedDirectionTableBytes = impl_->tableBytes;
  stats.cachedWallGrids = impl_->grids.size();
  stats.cameraRays = counters.camera.load();
  stats.occlusionRays = counters.occlusion.load();
  stats.retracedRays = counters.retraced.load();
  stats.shadingSimd = embree::simdName(impl_->simd);
  stats.raysPerSecond =
      seconds > 0.0 ? static_cast<double>(stats.cameraRays + stats.occlusionRays) / seconds : 0.0;
  if (settings.mode == RenderMode::Conformal && plan.hasOffCentreEyes)
    stats.curvedRaySegments =
        settings.stereoRays == StereoRays::Exact ? impl_->options.curvedRaySegments : 1;
  result.stats.backend = name();
  result.stats.seconds = seconds;
  result.stats.sceneTriangles = scene.scene().triangleCount();
  result.stats.embree = std::move(stats);
}

}  // namespace confvis
