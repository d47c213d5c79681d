// Alignment benchmark (run by hand, never in CI): where a baked map puts the virtual forward
// direction on the display (wall, s and t across the wall, pixels from the point straight ahead),
// whether up stays up there, and the map's mirror asymmetry in wall pixels (x: left/right mirror,
// y: top/bottom mirror, or any plane normal), as measured by map_alignment_quality.hpp.
//
//   build/confvis_bench_alignment CONFIG [--map DIR] [--edge-length M] [--resolution N]
//                                 [--mirror x|y|X,Y,Z]... [--route spherical|euclidean]
// Without --map the config is baked in memory (no cache); with it, a bake directory written by
// `confvis bake` (of any version) is measured: how before/after figures are compared.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/map_alignment_quality.hpp"
#include "confvis/engine/display_config.hpp"

using namespace confvis;

namespace {

Vec3d parseNormal(const std::string& text) {
  if (text == "x") return {1, 0, 0};
  if (text == "y") return {0, 1, 0};
  if (text == "z") return {0, 0, 1};
  std::stringstream in(text);
  Vec3d n{};
  char comma = 0;
  in >> n.x >> comma >> n.y >> comma >> n.z;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"confvis alignment benchmark: gaze and mirror symmetry of a baked map"};
  std::string configPath, mapDir;
  double edgeLength = 0;
  int resolution = 0;
  std::vector<std::string> mirrors;
  app.add_option("config", configPath, "Display config")->required();
  app.add_option("--map", mapDir, "Bake directory to measure instead of baking");
  app.add_option("--edge-length", edgeLength, "Bake with this edge length (metres)");
  app.add_option("--resolution", resolution, "Bake at this cube face size");
  app.add_option("--mirror", mirrors, "Mirror planes: x, y, z or a normal X,Y,Z (default x, y)");
  std::string route = "spherical";
  app.add_option("--route", route, "Disk-map route when baking: spherical | euclidean")
      ->check(CLI::IsMember({"spherical", "euclidean"}))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    DisplayConfig config = loadDisplayConfig(configPath);
    RetargetMap map;
    if (!mapDir.empty()) {
      map = loadBakeDirectory(mapDir).map;
    } else {
      DisplayMapOptions options;
      options.edgeLength = edgeLength;
      if (route == "euclidean") options.route = DisplayMapRoute::Euclidean;
      const DisplayMap displayMap = computeDisplayMap(config, options);
      BakeOptions bake;
      bake.reference = {config.reference.x, config.reference.y, config.reference.z};
      map = bakeRetargetMap(displayMap, resolution > 0 ? resolution : config.cubeResolution, bake);
    }
    const glm::dvec3 axis =
        config.source == SourceField::Hemisphere ? config.hemisphereAxis : glm::dvec3(0, 0, -1);
    const GazeAlignment gaze = measureGazeAlignment(map, config, {axis.x, axis.y, axis.z});
    std::printf("%s: forward shown on wall %s at s = %.4f, t = %.4f", config.name.c_str(),
                gaze.wall.c_str(), gaze.s, gaze.t);
    if (gaze.offsetPixels) std::printf(", %.2f px from straight ahead", *gaze.offsetPixels);
    if (gaze.upTiltDegrees) std::printf(", up tilted %.3f deg", *gaze.upTiltDegrees);
    std::printf("\n");
    if (mirrors.empty()) mirrors = {"x", "y"};
    for (const std::string& m : mirrors) {
      const MirrorAsymmetry a = measureMirrorAsymmetry(map, config, parseNormal(m));
      std::printf("  mirror %-8s %6zu pairs: asymmetry p50 %.4f, p99 %.4f, max %.4f px (%s)\n",
                  m.c_str(), a.samples, a.p50, a.p99, a.max, a.worstWall.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
