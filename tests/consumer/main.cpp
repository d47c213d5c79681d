// A minimal confvis application: load the shipped 5-sided CAVE, compute its wall views for a head
// at the centre, sample an identity map, follow a head that steps aside, and read a ParaView file.
// Prints lines that run_consumer_test.cmake checks against closed-form values.
#include <confvis/confvis.hpp>

#include <cmath>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  try {
    const std::string configs = CONFVIS_CONFIGS_DIR;
    const confvis::DisplayConfig cave =
        confvis::loadDisplayConfig(argc > 1 ? argv[1] : configs + "/cave5.json");
    std::printf("confvis %s display %s walls %zu\n", confvis::versionString(), cave.name.c_str(),
                cave.walls.size());

    // Head at the centre of the 3 m cube: every wall spans [-1.5, 1.5]^2 at distance 1.5.
    for (const confvis::WallView& view :
         confvis::makeViews(cave, confvis::HeadPose{}, confvis::Eye::Center))
      std::printf("view %s %.3f %.3f %.3f %.3f %.3f\n", view.wall->name.c_str(), view.left,
                  view.right, view.bottom, view.top, view.nearDistance);

    const confvis::RetargetMap identity = confvis::RetargetMap::identity(32);
    const glm::dvec3 d = glm::normalize(glm::dvec3{0.3, -0.2, -1.0});
    const std::optional<glm::dvec3> v = identity.toVirtual(d);
    std::printf("identity %s\n", v && confvis::angleBetween(*v, d) < 1e-2 ? "ok" : "wrong");

    // The map follows a head that steps 30 cm to the right (a stand-in bake: identity maps).
    confvis::MapFollower follower(cave, [](const confvis::DisplayConfig&, const glm::dvec3& c) {
      return confvis::RetargetMap::identity(8, c);
    });
    follower.beginFrame(confvis::HeadPose{{0.3, 0.0, 0.0}});
    follower.waitForBake();
    const confvis::FollowerFrame frame = follower.beginFrame(confvis::HeadPose{{0.3, 0.0, 0.0}});
    std::printf("follower generation %llu reference %.2f %.2f %.2f\n",
                static_cast<unsigned long long>(frame.generation), frame.map->reference.x,
                frame.map->reference.y, frame.map->reference.z);

    const confvis::DisplayConfig pvx =
        confvis::loadDisplayConfig(configs + "/imported/paraview-cave3.pvx");
    std::printf("pvx walls %zu first %s\n", pvx.walls.size(), pvx.walls.front().name.c_str());
    return 0;
  } catch (const confvis::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
