// A minimal confvis application: load the shipped 5-sided CAVE, compute its wall views for a head
// at the centre, sample an identity map, follow a head that steps aside, read a ParaView file,
// and render real frames through a real bake. Prints lines that run_consumer_test.cmake checks
// against closed-form values.
#include <confvis/confvis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

// The checker sphere's colour (red, green, blue or white) an RGB value has: shading scales the
// brightness only. -1 for black (nothing drawn).
int colourClass(glm::vec3 rgb) {
  const float brightest = std::max({rgb.r, rgb.g, rgb.b});
  if (brightest <= 0.0f) return -1;
  rgb /= brightest;
  if (rgb.r > 0.5f && rgb.g > 0.5f && rgb.b > 0.5f) return 3;
  return rgb.r >= rgb.g && rgb.r >= rgb.b ? 0 : (rgb.g >= rgb.b ? 1 : 2);
}

// Pixels of a frame whose colour is not the checker sphere's (builtin_scenes.hpp) in the virtual
// direction `toVirtual` gives for the pixel's physical direction from the display's reference.
template <typename ToVirtual>
int pixelsOffClosedForm(const confvis::RenderResult& frame, const confvis::DisplayConfig& display,
                        ToVirtual toVirtual) {
  int off = 0;
  for (const confvis::WallImage& wall : frame.images) {
    const confvis::ImageRGBA& image = wall.image;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const glm::dvec3 point = display.wall(wall.wall).pointAt(
            (x + 0.5) / image.width, 1.0 - (y + 0.5) / image.height);
        const std::optional<glm::dvec3> seen = toVirtual(glm::normalize(point - display.reference));
        const float* p = image.at(x, y);
        if (!seen || colourClass({p[0], p[1], p[2]}) !=
                         colourClass(confvis::checkerSphereColor(*seen)))
          ++off;
      }
  }
  return off;
}

}  // namespace

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

    // Real frames through a real bake: the CAVE's map baked coarse (no cache), the checker
    // sphere rendered by Embree on 24-pixel walls, plainly and through the map. Each pixel must
    // show the sphere's colour in the direction its mode looks: the map's virtual direction, or
    // the pixel's own. (The conformal frame checked as if plain must fail: the map moves the
    // missing ceiling's green onto the walls.)
    confvis::BakeDisplayOptions bake;
    bake.resolution = 32;
    bake.edgeLength = 0.5;
    bake.useCache = false;
    const confvis::RetargetMap map = confvis::bakeDisplay(cave, bake).map;
    confvis::EmbreeBackend backend;
    backend.setScene(confvis::builtinScene("checker-sphere"));
    confvis::RenderSettings settings;
    settings.resolutionScale = 24.0 / cave.walls.front().width;
    const confvis::RenderResult conformal = backend.render(cave, &map, settings);
    settings.mode = confvis::RenderMode::Plain;
    const confvis::RenderResult plain = backend.render(cave, nullptr, settings);
    const auto throughMap = [&](const glm::dvec3& d) { return map.toVirtual(d); };
    const auto straight = [](const glm::dvec3& d) { return std::optional<glm::dvec3>(d); };
    std::printf("frames %zu pixels %d conformal off %d (as plain %d) plain off %d rays %llu\n",
                conformal.images.size(), 24 * 24 * static_cast<int>(conformal.images.size()),
                pixelsOffClosedForm(conformal, cave, throughMap),
                pixelsOffClosedForm(conformal, cave, straight),
                pixelsOffClosedForm(plain, cave, straight),
                static_cast<unsigned long long>(conformal.stats.embree.value().cameraRays));

    const confvis::DisplayConfig pvx =
        confvis::loadDisplayConfig(configs + "/imported/paraview-cave3.pvx");
    std::printf("pvx walls %zu first %s\n", pvx.walls.size(), pvx.walls.front().name.c_str());
    return 0;
  } catch (const confvis::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
