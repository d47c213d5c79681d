#include "confvis/backends/retarget_map_files.hpp"

#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace confvis {

RetargetMap readRetargetMapDirectory(const std::filesystem::path& directory,
                                     const glm::dvec3& reference) {
  if (!std::filesystem::is_directory(directory))
    throw Error(ErrorCode::FileNotFound,
                "baked map directory '" + directory.string() + "' does not exist");
  // A `confvis bake` directory: its own loader checks every file against bake.json and takes
  // the reference point the map was baked around from it.
  if (std::filesystem::exists(directory / "bake.json")) return loadBakeDirectory(directory).map;
  for (const char* name : {"ray.exr", "geom.exr"})
    if (!std::filesystem::exists(directory / name))
      throw Error(ErrorCode::FileNotFound, "baked map directory '" + directory.string() +
                                               "' has no " + name + " (run confvis bake)");
  RetargetMap map;
  map.reference = {reference.x, reference.y, reference.z};
  map.ray = readCubeExr(directory / "ray.exr");
  map.geom = readCubeExr(directory / "geom.exr");
  if (map.ray.faceSize != map.geom.faceSize)
    throw Error(ErrorCode::InvalidInput,
                "baked map directory '" + directory.string() + "': ray.exr has " +
                    std::to_string(map.ray.faceSize) + " texels per face edge, geom.exr " +
                    std::to_string(map.geom.faceSize));
  return map;
}

}  // namespace confvis
