// An application of views and maps only, built with find_package(confvis COMPONENTS runtime)
// while Embree, TBB and Vulkan are off limits (run_consumer_test.cmake disables finding them):
// loads the shipped CAVE, computes a wall view, and follows a head with a stand-in bake.
#include <confvis/conformal/retarget_map.hpp>
#include <confvis/engine/display_config.hpp>
#include <confvis/engine/view.hpp>
#include <confvis/runtime/map_follower.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const confvis::DisplayConfig cave = confvis::loadDisplayConfig(argv[1]);
  const confvis::WallView front =
      confvis::makeViews(cave, confvis::HeadPose{}, confvis::Eye::Center).front();
  confvis::MapFollower follower(cave, [](const confvis::DisplayConfig&, const glm::dvec3& c) {
    return confvis::RetargetMap::identity(8, c);
  });
  follower.beginFrame(confvis::HeadPose{{0.0, 0.0, 0.25}});
  follower.waitForBake();
  const confvis::FollowerFrame frame = follower.beginFrame(confvis::HeadPose{{0.0, 0.0, 0.25}});
  std::printf("maps-only %s %.3f generation %llu display reference %.2f\n",
              front.wall->name.c_str(), front.nearDistance,
              static_cast<unsigned long long>(frame.generation), frame.display->reference.z);
  return 0;
}
