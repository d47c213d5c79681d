#include "confvis/engine/scene_loader.hpp"

#include <algorithm>
#include <cctype>

#include "confvis/base/error.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "scene_file_parts.hpp"

namespace confvis {

Scene loadScene(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj" && extension != ".gltf" && extension != ".glb")
    throw Error(ErrorCode::InvalidInput, "scene file '" + path.string() +
                                             "' has an unknown extension (supported: .obj, "
                                             ".gltf, .glb)");
  if (!std::filesystem::is_regular_file(path))
    throw Error(ErrorCode::FileNotFound, "scene file '" + path.string() + "' does not exist");
  Scene scene = extension == ".obj" ? scene_files::loadObjScene(path)
                                    : scene_files::loadGltfScene(path, extension == ".glb");
  scene.name = path.string();  // validation messages then name the file
  validateScene(scene);
  return scene;
}

Scene sceneByNameOrFile(const std::string& nameOrPath) {
  const std::vector<std::string> names = builtinSceneNames();
  if (std::find(names.begin(), names.end(), nameOrPath) != names.end())
    return builtinScene(nameOrPath);
  if (!std::filesystem::exists(nameOrPath)) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    throw Error(ErrorCode::FileNotFound, "scene '" + nameOrPath +
                                             "' is neither a built-in scene (" + list +
                                             ") nor an existing file");
  }
  return loadScene(nameOrPath);
}

}  // namespace confvis
