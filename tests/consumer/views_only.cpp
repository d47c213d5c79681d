// An application of display configs and views only (find_package(confvis COMPONENTS engine)),
// built by the test consumer_shared_package against the shared libraries: loads the shipped
// CAVE, computes its walls' views for a head 0.5 m right of the centre, and catches the error a
// broken config throws from inside libconfvis_engine.so (the exception's type information
// crosses the library boundary only if the library exports it).
#include <confvis/base/error.hpp>
#include <confvis/engine/display_config.hpp>
#include <confvis/engine/view.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: views_only CONFIG BROKEN-CONFIG\n");
    return 2;
  }
  const confvis::DisplayConfig cave = confvis::loadDisplayConfig(argv[1]);
  const confvis::HeadPose head{{0.5, 0.0, 0.0}};
  for (const confvis::WallView& view : confvis::makeViews(cave, head, confvis::Eye::Center))
    std::printf("view %s %.3f %.3f %.3f\n", view.wall->name.c_str(), view.left, view.right,
                view.nearDistance);
  try {
    confvis::loadDisplayConfig(argv[2]);
    std::printf("no error\n");
  } catch (const confvis::Error& error) {
    std::printf("caught %s: %s\n", confvis::toString(error.code()), error.what());
  }
  return 0;
}
