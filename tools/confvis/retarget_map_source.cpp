#include "retarget_map_source.hpp"

#include "confvis/backends/retarget_map_files.hpp"
#include "confvis/base/error.hpp"

namespace confvis::cli {

MapSource retargetMapFor(const DisplayConfig& config, const std::string& mapDirectory) {
  if (!mapDirectory.empty())
    return {readRetargetMapDirectory(mapDirectory, config.reference), mapDirectory};
  if (displayCoversWholeSphere(config)) {
    const Vec3d c{config.reference.x, config.reference.y, config.reference.z};
    return {RetargetMap::identity(config.cubeResolution, c),
            "identity (the display covers the whole sphere)"};
  }
  throw Error(ErrorCode::InvalidInput,
              "no baked map for display '" + config.name +
                  "': run confvis bake, then pass its output with --map DIR "
                  "(or render with --mode plain)");
}

}  // namespace confvis::cli
