#include "confvis/engine/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "scene_file_parts.hpp"

namespace confvis {

namespace {

// Exporters write (0, 0, 0) normals for degenerate or unsmoothed faces; normalised they are NaN
// and would shade the whole render wrong. Such a mesh gets flat normals, with a warning.
void repairNormals(Scene& scene, const std::filesystem::path& path) {
  for (Mesh& mesh : scene.meshes) {
    const auto bad = std::count_if(mesh.normals.begin(), mesh.normals.end(), [](const glm::vec3& n) {
      const float length = glm::length(n);
      return !std::isfinite(length) || length < 1e-12f;
    });
    if (bad == 0) continue;
    scene_files::warn(path, "mesh '" + mesh.name + "': " + std::to_string(bad) +
                                " zero-length or non-finite normals; using flat face normals");
    generateFlatNormals(mesh);
  }
}

}  // namespace

Scene loadScene(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj" && extension != ".gltf" && extension != ".glb")
    throw Error(ErrorCode::InvalidInput, "scene file '" + path.string() +
                                             "' has an unknown extension (supported: .obj, "
                                             ".gltf, .glb)");
  if (!isRegularFile(path))
    throw Error(ErrorCode::FileNotFound, "scene file '" + path.string() + "' does not exist");
  Scene scene = extension == ".obj" ? scene_files::loadObjScene(path)
                                    : scene_files::loadGltfScene(path, extension == ".glb");
  scene.name = path.string();  // validation messages then name the file
  repairNormals(scene, path);
  validateScene(scene);
  return scene;
}

Scene sceneByNameOrFile(const std::string& nameOrPath) {
  const std::vector<std::string> names = builtinSceneNames();
  if (std::find(names.begin(), names.end(), nameOrPath) != names.end())
    return builtinScene(nameOrPath);
  if (!pathExists(nameOrPath)) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    throw Error(ErrorCode::FileNotFound, "scene '" + nameOrPath +
                                             "' is neither a built-in scene (" + list +
                                             ") nor an existing file");
  }
  return loadScene(nameOrPath);
}

}  // namespace confvis
