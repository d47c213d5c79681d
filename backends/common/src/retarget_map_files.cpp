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

namespace {

bool litWallBehind(const DisplayConfig& config, const glm::dvec3& direction) {
  for (const Wall& wall : config.walls) {
    const Wall lit = wall.litRectangle();
    const glm::dvec3 n = lit.normal();
    const double facing = glm::dot(direction, n);
    if (facing >= 0.0) continue;  // the wall faces away from this direction
    const double t = glm::dot(lit.lowerLeft - config.reference, n) / facing;
    if (t <= 0.0) continue;
    const glm::dvec3 local = config.reference + t * direction - lit.lowerLeft;
    const double s = glm::dot(local, lit.right()) / lit.widthMetres();
    const double u = glm::dot(local, lit.up()) / lit.heightMetres();
    if (s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0) return true;
  }
  return false;
}

}  // namespace

bool displayCoversWholeSphere(const DisplayConfig& config, int samplesPerFaceEdge) {
  if (config.source != SourceField::FullSphere) return false;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < samplesPerFaceEdge; ++y)
      for (int x = 0; x < samplesPerFaceEdge; ++x) {
        const Vec3d d = texelDirection(face, x, y, samplesPerFaceEdge);
        if (!litWallBehind(config, glm::normalize(glm::dvec3(d.x, d.y, d.z)))) return false;
      }
  return true;
}

}  // namespace confvis
