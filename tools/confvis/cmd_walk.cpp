// confvis walk: the map following the head. Plays a recorded head path through a display,
// re-bakes the conformal map in the background whenever the head strays from the current map's
// reference point (MapFollower), and renders every wall of every frame through the map the
// follower hands out for that frame: DIR/frame-NNNN/ (EXR + PNG per wall, overview) and
// DIR/walk.json (per frame: time, head, the map's reference point and generation, bake state).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "backend_factory.hpp"
#include "cluster_cli.hpp"
#include "command.hpp"
#include "preset_option.hpp"
#include "confvis/runtime/map_follower.hpp"
#include "confvis/backends/edge_blend_output.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/runtime/tracker.hpp"
#include "frame_record_spool.hpp"
#include "render_options.hpp"
#include "retarget_map_source.hpp"
#include "scene_option.hpp"
#include "shipped_files.hpp"

namespace confvis::cli {
namespace {

namespace fs = std::filesystem;
using Clock = SteadyClock;

struct WalkArgs {
  std::string config, path, scene = "checker-tunnel", backend = "embree", output = "out/walk";
  std::string preset;
  int frames = 0;  // 0: one pass of the path
  int bakeResolution = 0;
  double fps = 30.0, scale = 0.1, radius = 0.10, bakeEdgeLength = 0.0, sceneScale = 1.0;
  bool noPacing = false, quiet = false, waitForBakes = false;
  ClusterCliOptions cluster;
};

nlohmann::json toJson(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json toJson(const glm::dquat& q) { return {q.w, q.x, q.y, q.z}; }

// --cluster: how long the other ranks wait for rank 0's first bake, and for its frames (rank 0
// also renders and writes every frame's images).
constexpr double kClusterBakeSeconds = 600.0;
constexpr double kFrameSeconds = 60.0;

std::string frameName(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d", index);
  return name;
}

int runWalk(const WalkArgs& args) {
  const auto start = Clock::now();
  const fs::path configPath = args.config.empty()
                                  ? shippedFile("configs/cave5.json", "display config")
                                  : fs::path(args.config);
  const fs::path pathFile = args.path.empty()
                                ? shippedFile("configs/paths/cave-walk.csv", "--path")
                                : fs::path(args.path);
  const DisplayConfig config = loadDisplayConfig(configPath);
  const RecordedPath path = RecordedPath::load(pathFile);
  const int frameCount = args.frames > 0 ? args.frames
                                         : std::max(1, static_cast<int>(std::ceil(
                                                           path.duration() * args.fps)));

  // The tracker reads the walk's own clock (frame time), so the frames are reproducible whatever
  // the render speed; pacing below keeps that clock close to the wall clock.
  double frameSeconds = path.keys().front().seconds;
  RecordedPathTracker tracker(path, /*loop=*/true, [&frameSeconds] { return frameSeconds; });

  // --cluster: rank 0 tracks, bakes and decides every frame; each rank renders its walls.
  std::optional<CliCluster> cluster;
  if (args.cluster.enabled) cluster.emplace(config, args.cluster);
  const bool root = !cluster || cluster->isRoot();  // of this rank's frame group
  const bool decider = !cluster || cluster->isWorldRoot();  // runs the follower: bakes once
  std::unique_ptr<RenderBackend> backend = makeBackend(args.backend);
  const Scene scene = loadSceneInUnits(args.scene, args.sceneScale, config);
  backend->setScene(scene);
  if (!args.quiet && decider)
    std::fprintf(stderr, "walk: baking the first map of '%s'...\n", config.name.c_str());
  std::optional<MapFollower> follower;
  if (decider)
    follower.emplace(config,
                     followerBake(args.bakeResolution, args.bakeEdgeLength,
                                  parseBakePreset(args.preset)),
                     MapFollowerOptions{.radius = args.radius});
  const double setupSeconds = secondsSince(start);
  // --cluster: this rank's frame states, on disk until the end as walk.json's records are.
  std::optional<FrameRecordSpool> rankLog;
  if (cluster) rankLog.emplace();

  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = {Eye::Center};
  settings.resolutionScale = args.scale;
  // The map's render config: the display with its reference at the map's, rebuilt when a new map
  // is swapped in (a --cluster rank other than 0 has no follower to hand it out).
  DisplayConfig frameConfig = config;
  const EdgeBlender blender(config);  // masks once: they do not depend on the head
  bool haveFrameConfig = false, haveShared = false;
  std::uint64_t frameConfigGeneration = 0, sharedGeneration = 0;
  // --cluster with frame groups: this rank's group renders frames index % groups == group.
  // Rank 0 still decides every frame (the follower sees the whole path, so maps swap on the same
  // frames as in one process, each map baked once) and sends each decision to every group's
  // root (shareDecision); rank 0 reports them all.
  const int groups = cluster ? cluster->frameGroups() : 1;
  const int group = cluster ? cluster->frameGroup() : 0;
  const bool reporter = !cluster || cluster->isWorldRoot();
  nlohmann::json errors = nlohmann::json::array();
  std::optional<FrameRecordSpool> frames;  // walk.json's per-frame records, on disk until the end
  if (reporter) frames.emplace();
  int previousBakesStarted = 0;
  const auto loopStart = Clock::now();
  RenderResult result;  // one frame's images, rendered over by the next (renderInto)
  for (int index = 0; index < frameCount; ++index) {
    const bool mine = index % groups == group;  // this rank's group renders the frame
    if (!mine && !root) continue;
    const double walkSeconds = index / args.fps;
    // A live loop: frame i begins no earlier than i / fps after the first.
    if (!args.noPacing && mine)
      std::this_thread::sleep_until(loopStart + std::chrono::duration_cast<Clock::duration>(
                                                    std::chrono::duration<double>(walkSeconds)));
    frameSeconds = path.keys().front().seconds + walkSeconds;
    ClusterFrameState state;  // what rank 0 decides for this frame
    FollowerFrame frame;
    bool bakeStarted = false;
    if (decider) {
      state.frame = static_cast<std::uint64_t>(index);
      state.seconds = frameSeconds;
      state.head = tracker.latest().value().head;
      frame = follower->beginFrame(state.head);
      state.mapGeneration = frame.generation;
      bakeStarted = follower->stats().bakesStarted > previousBakesStarted;
      previousBakesStarted = follower->stats().bakesStarted;
      // Offline determinism: a bake started now is swapped in at the next frame, whatever it costs.
      if (args.waitForBakes && frame.baking) follower->waitForBake();
    }
    if (cluster && root) {  // frame groups: rank 0's decision reaches every group's root
      frame.map = cluster->shareDecision(state, frame.map,
                                         index == 0 ? kClusterBakeSeconds : kFrameSeconds);
      frame.generation = state.mapGeneration;
    }
    if (cluster && mine) {
      if (root && (!haveShared || sharedGeneration != frame.generation)) {  // before the frame
        cluster->shareFrameMap(frame.map, frame.generation);
        sharedGeneration = frame.generation;
        haveShared = true;
      }
      cluster->exchangeFrame(state, rankLog->size() == 0 ? kClusterBakeSeconds : kFrameSeconds);
      frame.map = cluster->map();
      frame.generation = state.mapGeneration;
      rankLog->add({{"frame", state.frame}, {"seconds", state.seconds},
                    {"head", {{"position", toJson(state.head.position)},
                              {"orientation", toJson(state.head.orientation)}}},
                    {"map_generation", state.mapGeneration}});
    }
    const HeadPose head = state.head;
    const glm::dvec3 reference(frame.map->reference.x, frame.map->reference.y,
                               frame.map->reference.z);
    if (!haveFrameConfig || frameConfigGeneration != frame.generation) {
      frameConfig = withReference(config, reference);
      frameConfigGeneration = frame.generation;
      haveFrameConfig = true;
    }
    const fs::path directory = fs::path(args.output) / frameName(index);

    // The centre eye at the tracked head; the virtual camera sits at the map's reference point,
    // so the virtual world (camera + (p - reference)) stays put when the reference moves.
    settings.head = head;
    settings.camera.position = reference;
    try {  // into the previous frame's images (written out already): no fresh output memory
      if (!mine) {
        // another group renders it; this root only took part in the decision
      } else if (!cluster) {
        backend->renderInto(frameConfig, frame.map.get(), settings, result);
      } else if (auto all = cluster->render(*backend, frameConfig, frame.map.get(), settings)) {
        result = std::move(*all);
      } else {
        continue;  // rank 0 writes the frame
      }
    } catch (const Error& error) {
      throw Error(error.code(), "frame " + std::to_string(index) + " (t = " +
                                    std::to_string(frameSeconds) + " s): " + error.what());
    }
    if (mine) {
      blender.apply(result.images);  // overlapping projectors, when configured
      writeRenderOutput(directory, frameConfig, settings, result,
                        {{"walk", {{"frame", index}, {"seconds", frameSeconds}}}});
    }

    if (follower)
      for (const std::string& message : follower->takeErrors()) {
        errors.push_back({{"frame", index}, {"message", message}});
        std::fprintf(stderr, "walk: frame %d: re-bake failed, keeping the old map: %s\n",
                     index, message.c_str());
      }
    if (frames)
      frames->add({{"frame", index},
                   {"seconds", frameSeconds},
                   {"directory", directory.filename().string()},
                   {"head", {{"position", toJson(head.position)},
                             {"orientation", toJson(head.orientation)}}},
                   {"map", {{"reference", toJson(reference)},
                            {"generation", frame.generation},
                            {"swapped", frame.swapped}}},
                   {"head_to_reference_m", glm::length(head.position - reference)},
                   {"bake_started", bakeStarted},
                   {"baking", frame.baking}});
    if (!args.quiet && reporter)
      std::fprintf(stderr,
                   "frame %d/%d  t %.2f s  head (%.2f, %.2f, %.2f)  map %llu around (%.2f, %.2f, "
                   "%.2f)%s%s\n",
                   index + 1, frameCount, frameSeconds, head.position.x, head.position.y,
                   head.position.z, static_cast<unsigned long long>(frame.generation),
                   reference.x, reference.y, reference.z, frame.swapped ? "  [swapped in]" : "",
                   frame.baking ? (bakeStarted ? "  [re-bake started]" : "  [baking]") : "");
  }

  if (cluster) {  // every rank's frame states, to show they all saw the same frames
    const nlohmann::json log = {{"rank", cluster->rank()},
                                {"walls", cluster->walls()},
                                {"runs_follower", follower.has_value()},  // bakes: rank 0 only
                                {"frames", FrameRecordSpool::kPlaceholder}};
    writeTextAtomically(fs::path(args.output) /
                            ("cluster-rank-" + std::to_string(cluster->rank()) + ".json"),
                        rankLog->spliceInto(log.dump(2)) + "\n");
    if (!reporter) return 0;
  }
  // No waiting for a running bake before the report: it is counted as still running.
  const MapFollowerStats stats = follower->stats();
  const int stillRunning = stats.bakesStarted - stats.bakesSucceeded - stats.bakesFailed;
  nlohmann::json report = {
      {"display", {{"name", config.name}, {"config", configPath.string()}}},
      {"path", pathFile.string()},
      {"scene", args.scene},
      {"backend", backend->name()},
      {"fps", args.fps},
      {"radius_m", args.radius},
      {"scale", args.scale},
      {"paced", !args.noPacing},
      {"wait_for_bakes", args.waitForBakes},
      {"cluster", cluster ? cluster->report() : nlohmann::json(nullptr)},
      {"frames", FrameRecordSpool::kPlaceholder},
      {"rebakes", {{"started", stats.bakesStarted},
                   {"swapped_in", stats.bakesSucceeded},
                   {"failed", stats.bakesFailed},
                   {"running_at_end", stillRunning}}},
      {"errors", errors},
      {"timings", {{"setup_seconds", setupSeconds}, {"frames_seconds", secondsSince(loopStart)}}}};
  writeTextAtomically(fs::path(args.output) / "walk.json",
                      frames->spliceInto(report.dump(2)) + "\n");
  std::printf("%s: %d frames of '%s' along %s -> %s; re-bakes: %d started, %d swapped in, %d "
              "failed, %d still running\n",
              config.name.c_str(), frameCount, scene.name.c_str(),
              pathFile.filename().string().c_str(), args.output.c_str(), stats.bakesStarted,
              stats.bakesSucceeded, stats.bakesFailed, stillRunning);
  return 0;  // ~MapFollower still joins a running bake: bakes cannot be cancelled
}

const RegisterCommand registration{Command{
    "walk",
    "Walk a scene along a recorded head path; the conformal map follows the head (EXR + PNG "
    "frames)",
    [](CLI::App& sub) {
      auto args = std::make_shared<WalkArgs>();
      addDisplayConfigArgument(sub, args->config);
      sub.add_option("--path", args->path,
                     "Head path CSV (seconds,x,y,z,qw,qx,qy,qz); default: "
                     "configs/paths/cave-walk.csv");
      addSceneOption(sub, args->scene);
      addSceneScaleOption(sub, args->sceneScale);
      sub.add_option("--frames", args->frames, "Frames to render; default: one pass of the path")
          ->check(CLI::Range(1, 1000000));
      sub.add_option("--fps", args->fps, "Frames per second of path time")
          ->check(CLI::Range(0.01, 1000.0))
          ->capture_default_str();
      addOutputScaleOption(sub, args->scale);
      addRebakeRadiusOption(sub, args->radius);
      addPresetOption(sub, args->preset, kLiveBakePreset);
      sub.add_option("--bake-resolution", args->bakeResolution,
                     "Cube texels per face of the baked maps; default: the config's")
          ->check(CLI::Range(8, 4096));
      sub.add_option("--bake-edge-length", args->bakeEdgeLength,
                     "Mesh edge length of the bakes (metres); default: the config's")
          ->check(kPositiveNumber);
      addBackendOption(sub, args->backend);
      sub.add_flag("--no-pacing", args->noPacing,
                   "Render as fast as possible instead of frame i no earlier than i/fps seconds "
                   "after the first (with it, bakes rarely finish within the walk)");
      sub.add_flag("--wait-for-bakes", args->waitForBakes,
                   "Wait for every re-bake, so it is swapped in at the next frame: the same frames "
                   "at any speed (offline runs, --cluster comparisons)");
      sub.add_option("-o,--output", args->output, "Output directory")->capture_default_str();
      sub.add_flag("-q,--quiet", args->quiet, "No per-frame progress lines");
      addClusterOptions(sub, args->cluster);
      addFrameGroupOption(sub, args->cluster);
      return [args] { return runWalk(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
