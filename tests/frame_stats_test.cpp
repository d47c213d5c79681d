// The typed frame statistics each backend fills in (RenderResult::stats): the figures known in
// advance are checked against their closed forms (one image per wall and eye, one camera ray per
// pixel of a plain mono frame and one per retrace, the scene's triangle count, the pre-pass
// reused by an unchanged second frame), and render.json's "backend" object is the struct,
// key by key.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/frame_stats.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace confvis {
namespace {

constexpr int kPixels = 16;  // walls render kPixels x kPixels (cave5's walls are square)

TEST(FrameStats, EmbreeCountsOneCameraRayPerPixelOfAPlainMonoFrame) {
  const DisplayConfig config = test::loadConfig("cave5");
  const Scene scene = builtinScene("checker-sphere");
  EmbreeBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(config, kPixels);
  const FrameStats stats = backend.render(config, nullptr, settings).stats;
  EXPECT_EQ(stats.backend, "embree");
  EXPECT_GT(stats.seconds, 0.0);
  EXPECT_EQ(stats.sceneTriangles, scene.triangleCount());
  EXPECT_FALSE(stats.vulkan);
  ASSERT_TRUE(stats.embree);
  const EmbreeFrameStats& embree = *stats.embree;
  const std::uint64_t pixels = kPixels * kPixels * config.walls.size();
  EXPECT_EQ(embree.cameraRays, pixels + embree.retracedRays);
  EXPECT_LT(embree.retracedRays, pixels / 10);
  EXPECT_EQ(embree.occlusionRays, 0u);  // no ambient occlusion asked for
  EXPECT_NEAR(embree.raysPerSecond, embree.cameraRays / stats.seconds, 1e-6 * embree.raysPerSecond);
  EXPECT_GE(embree.threads, 1);
  EXPECT_TRUE(embree.shadingSimd == "sse2" || embree.shadingSimd == "avx2") << embree.shadingSimd;
  EXPECT_EQ(embree.directionTableSamples, 0u);  // plain mode looks up no map
  EXPECT_EQ(embree.mapBuildSeconds, 0.0);
  EXPECT_FALSE(embree.curvedRaySegments);
  // One image per wall, in config order, each timed within the frame.
  ASSERT_EQ(embree.images.size(), config.walls.size());
  double imageSeconds = 0.0;
  for (std::size_t i = 0; i < embree.images.size(); ++i) {
    EXPECT_EQ(embree.images[i].wall, config.walls[i].name);
    EXPECT_EQ(embree.images[i].eye, Eye::Center);
    EXPECT_EQ(embree.images[i].width, kPixels);
    EXPECT_EQ(embree.images[i].height, kPixels);
    EXPECT_GT(embree.images[i].seconds, 0.0);
    imageSeconds += embree.images[i].seconds;
  }
  EXPECT_LE(imageSeconds, stats.seconds);
}

TEST(FrameStats, EmbreeStereoThroughAMapHasAnImagePerWallAndEyeAndItsCurvedRays) {
  const DisplayConfig config = test::loadConfig("cave5");
  EmbreeOptions options;
  options.curvedRaySegments = 7;
  EmbreeBackend backend(options);
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.eyes = {Eye::Left, Eye::Right};
  settings.resolutionScale = test::scaleFor(config, kPixels);
  const RetargetMap map = ceilinglessDilationMap(1.6, 16, config.reference);
  RenderResult result;
  backend.renderInto(config, &map, settings, result);
  backend.renderInto(config, &map, settings, result);  // the second frame reads cached tables
  const FrameStats& stats = result.stats;
  ASSERT_TRUE(stats.embree);
  EXPECT_EQ(stats.embree->curvedRaySegments.value_or(0), 7);
  ASSERT_EQ(stats.embree->images.size(), config.walls.size() * 2);
  for (std::size_t i = 0; i < result.images.size(); ++i) {
    EXPECT_EQ(stats.embree->images[i].wall, result.images[i].wall);
    EXPECT_EQ(stats.embree->images[i].eye, result.images[i].eye);
  }
  EXPECT_EQ(stats.embree->images[0].eye, Eye::Left);
  EXPECT_EQ(stats.embree->images[1].eye, Eye::Right);
  // Stereo eyes are off centre: at least one ray per pixel and eye, more for curved ones.
  EXPECT_GE(stats.embree->cameraRays, 2u * kPixels * kPixels * config.walls.size());
}

TEST(FrameStats, VulkanReportsItsDeviceAndTheReusedPrepass) {
  const DisplayConfig config = test::loadConfig("cave5");
  const Scene scene = builtinScene("checker-sphere");
  VulkanOptions options;
  options.device = test::testDevice();
  options.tessellationErrorPixels = 0.75;
  const std::unique_ptr<RenderBackend> backend = makeVulkanBackend(options);
  backend->setScene(scene);
  RenderSettings settings;
  settings.resolutionScale = test::scaleFor(config, kPixels);
  const RetargetMap map = ceilinglessDilationMap(1.6, 16, config.reference);
  RenderResult result;
  backend->renderInto(config, &map, settings, result);
  const FrameStats first = result.stats;
  backend->renderInto(config, &map, settings, result);  // nothing changed: the pre-pass is kept
  const FrameStats second = result.stats;
  EXPECT_EQ(first.backend, "vulkan");
  EXPECT_GT(first.seconds, 0.0);
  EXPECT_EQ(first.sceneTriangles, scene.triangleCount());
  EXPECT_FALSE(first.embree);  // a rasterizer shoots no rays
  ASSERT_TRUE(first.vulkan && second.vulkan);
  const VulkanFrameStats& vulkan = *first.vulkan;
  EXPECT_NE(vulkan.device.find(test::testDevice()), std::string::npos) << vulkan.device;
  EXPECT_TRUE(vulkan.conformal);
  EXPECT_EQ(vulkan.walls, config.walls.size());
  EXPECT_EQ(vulkan.viewsPerPass, 1);  // mono
  EXPECT_GT(vulkan.gpuSeconds.value_or(1.0), 0.0);  // where the queue has timestamps
  ASSERT_TRUE(vulkan.conformalPrepass && second.vulkan->conformalPrepass);
  const VulkanConformalStats& prepass = *vulkan.conformalPrepass;
  EXPECT_EQ(prepass.tessellationErrorPixels, 0.75);
  EXPECT_TRUE(prepass.tessellation);
  EXPECT_FALSE(prepass.prepassReused);
  EXPECT_TRUE(second.vulkan->conformalPrepass->prepassReused);
  EXPECT_GT(prepass.prepassSeconds, 0.0);
  EXPECT_GT(prepass.trianglesDrawnFlat + prepass.trianglesTessellated, 0u);
  EXPECT_LE(prepass.trianglesThroughGeometryShader, prepass.trianglesTessellated);

  settings.mode = RenderMode::Plain;
  settings.eyes = {Eye::Left, Eye::Right};
  backend->renderInto(config, nullptr, settings, result);
  ASSERT_TRUE(result.stats.vulkan);
  EXPECT_FALSE(result.stats.vulkan->conformal);
  EXPECT_FALSE(result.stats.vulkan->conformalPrepass);  // no pre-pass in plain mode
  EXPECT_EQ(result.stats.vulkan->viewsPerPass, result.stats.vulkan->multiview ? 2 : 1);
}

// render.json's "backend" is toJson(stats), and toJson writes each field under its documented key.
TEST(FrameStats, RenderJsonIsTheStructKeyByKey) {
  const DisplayConfig config = test::loadConfig("cave5");
  EmbreeBackend backend;
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.eyes = {Eye::Left, Eye::Right};
  settings.resolutionScale = test::scaleFor(config, 8);
  const RetargetMap map = ceilinglessDilationMap(1.6, 16, config.reference);
  const RenderResult result = backend.render(config, &map, settings);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("confvis_frame_stats_" + std::to_string(getpid()));
  writeRenderOutput(dir, config, settings, result);
  const nlohmann::json written =
      nlohmann::json::parse(readTextFile(dir / "render.json")).at("backend");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(written, toJson(result.stats));

  const FrameStats& s = result.stats;
  const EmbreeFrameStats& e = *s.embree;
  EXPECT_EQ(written.at("backend"), s.backend);
  EXPECT_EQ(written.at("render_seconds").get<double>(), s.seconds);
  EXPECT_EQ(written.at("scene_triangles").get<std::uint64_t>(), s.sceneTriangles);
  EXPECT_EQ(written.at("threads").get<int>(), e.threads);
  EXPECT_EQ(written.at("bvh_build_seconds").get<double>(), e.bvhBuildSeconds);
  EXPECT_EQ(written.at("map_build_seconds").get<double>(), e.mapBuildSeconds);
  EXPECT_EQ(written.at("direction_table_samples").get<std::uint64_t>(), e.directionTableSamples);
  EXPECT_EQ(written.at("camera_rays").get<std::uint64_t>(), e.cameraRays);
  EXPECT_EQ(written.at("occlusion_rays").get<std::uint64_t>(), e.occlusionRays);
  EXPECT_EQ(written.at("retraced_rays").get<std::uint64_t>(), e.retracedRays);
  EXPECT_EQ(written.at("shading_simd"), e.shadingSimd);
  EXPECT_EQ(written.at("rays_per_second").get<double>(), e.raysPerSecond);
  EXPECT_EQ(written.at("curved_ray_segments").get<int>(), e.curvedRaySegments.value());
  ASSERT_EQ(written.at("images").size(), e.images.size());
  for (std::size_t i = 0; i < e.images.size(); ++i) {
    const nlohmann::json& image = written.at("images")[i];
    EXPECT_EQ(image.at("wall"), e.images[i].wall);
    EXPECT_EQ(image.at("eye"), eyeName(e.images[i].eye));
    EXPECT_EQ(image.at("width").get<int>(), e.images[i].width);
    EXPECT_EQ(image.at("height").get<int>(), e.images[i].height);
    EXPECT_EQ(image.at("seconds").get<double>(), e.images[i].seconds);
  }
}

TEST(FrameStats, VulkanJsonNamesEveryFieldAndLeavesOutWhatWasNotMeasured) {
  FrameStats stats;
  stats.backend = "vulkan";
  stats.seconds = 0.5;
  stats.sceneTriangles = 12;
  VulkanFrameStats& v = stats.vulkan.emplace();
  v.device = "gpu";
  v.conformal = false;
  v.walls = 3;
  v.viewsPerPass = 2;
  v.multiview = true;
  nlohmann::json json = toJson(stats);
  EXPECT_EQ(json, nlohmann::json({{"backend", "vulkan"},
                                  {"seconds", 0.5},
                                  {"triangles", 12},
                                  {"device", "gpu"},
                                  {"mode", "plain"},
                                  {"walls", 3},
                                  {"views_per_pass", 2},
                                  {"stereo_passes", "multiview"}}));
  v.gpuSeconds = 0.25;
  VulkanConformalStats& c = v.conformalPrepass.emplace();
  c.tessellationErrorPixels = 0.5;
  c.trianglesSplitBeforeWarp = 1;
  c.trianglesDrawnFlat = 2;
  c.trianglesTessellated = 3;
  c.trianglesThroughGeometryShader = 4;
  c.trianglesSplitAlongCut = 5;
  c.prepassSeconds = 0.125;
  c.prepassGpuSeconds = 0.0625;
  c.prepassReused = true;
  c.passGpuSeconds = {{"warp_vertices", 0.03125}};
  json = toJson(stats);
  EXPECT_EQ(json.at("gpu_seconds"), 0.25);
  EXPECT_EQ(json.at("tessellation_error_pixels"), 0.5);
  EXPECT_EQ(json.at("tessellation"), true);
  EXPECT_EQ(json.at("triangles_split_before_warp"), 1);
  EXPECT_EQ(json.at("triangles_drawn_flat"), 2);
  EXPECT_EQ(json.at("triangles_tessellated"), 3);
  EXPECT_EQ(json.at("triangles_through_geometry_shader"), 4);
  EXPECT_EQ(json.at("triangles_split_along_cut"), 5);
  EXPECT_EQ(json.at("prepass_seconds"), 0.125);
  EXPECT_EQ(json.at("prepass_gpu_seconds"), 0.0625);
  EXPECT_EQ(json.at("prepass_reused"), true);
  EXPECT_EQ(json.at("prepass_pass_gpu_seconds"), nlohmann::json({{"warp_vertices", 0.03125}}));
  EXPECT_EQ(json.size(), 8u + 12u);  // nothing beyond the documented keys
}

}  // namespace
}  // namespace confvis
