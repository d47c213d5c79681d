// An application of views and maps only, built with find_package(confvis COMPONENTS conformal)
// while Embree, TBB and Vulkan are off limits (run_consumer_test.cmake disables finding them):
// loads the shipped CAVE, computes a wall view, and bakes the CAVE's conformal map (coarse).
#include <confvis/conformal/bake_display.hpp>
#include <confvis/engine/display_config.hpp>
#include <confvis/engine/view.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const confvis::DisplayConfig cave = confvis::loadDisplayConfig(argv[1]);
  const confvis::WallView front =
      confvis::makeViews(cave, confvis::HeadPose{}, confvis::Eye::Center).front();
  confvis::BakeDisplayOptions options;
  options.resolution = 16;
  options.edgeLength = 0.5;
  options.reference = glm::dvec3(0.0, 0.0, 0.25);
  options.useCache = false;
  const confvis::RetargetMap map = confvis::bakeDisplay(cave, options).map;
  // Straight ahead is on the front wall: the map has a virtual direction for it.
  const bool ahead = map.toVirtual(glm::dvec3(0.0, 0.0, -1.0)).has_value();
  std::printf("maps-only %s %.3f map %d reference %.2f ahead %s\n", front.wall->name.c_str(),
              front.nearDistance, map.resolution(), map.reference.z, ahead ? "shown" : "missing");
  return 0;
}
