#include "confvis/engine/builtin_scenes.hpp"

#include <cmath>
#include <functional>
#include <utility>

#include "builtin_scene_parts.hpp"
#include "confvis/base/error.hpp"

namespace confvis {

namespace {

using Builder = Scene (*)(const BuiltinSceneOptions&);

const std::vector<std::pair<std::string, Builder>>& registry() {
  static const std::vector<std::pair<std::string, Builder>> builders = {
      {"checker-sphere", &builtin::buildCheckerSphere},
      {"checker-tunnel", &builtin::buildCheckerTunnel},
      {"graph", &builtin::buildGraph},
  };
  return builders;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

Scene builtinScene(const std::string& name, const BuiltinSceneOptions& options) {
  for (const auto& [known, build] : registry()) {
    if (known != name) continue;
    Scene scene = build(options);
    scene.name = name;
    validateScene(scene);
    return scene;
  }
  std::string list;
  for (const std::string& known : builtinSceneNames()) list += (list.empty() ? "" : ", ") + known;
  throw Error(ErrorCode::InvalidInput,
              "unknown built-in scene '" + name + "' (known scenes: " + list + ")");
}

namespace builtin {

glm::vec3 checkerSquareColor(glm::vec3 color, long long i, long long j) {
  return ((i + j) % 2 == 0) ? color : kWhite;
}

Texture checkerTexture(glm::vec3 color, int squares, int texelsPerSquare) {
  Texture texture;
  texture.width = texture.height = squares * texelsPerSquare;
  texture.rgba.reserve(4 * static_cast<std::size_t>(texture.width) *
                       static_cast<std::size_t>(texture.height));
  for (int y = 0; y < texture.height; ++y) {
    for (int x = 0; x < texture.width; ++x) {
      const glm::vec3 c = checkerSquareColor(color, x / texelsPerSquare, y / texelsPerSquare);
      texture.rgba.insert(texture.rgba.end(), {c.r, c.g, c.b, 1.0f});
    }
  }
  return texture;
}

int addTexture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return static_cast<int>(scene.textures.size()) - 1;
}

int addMaterial(Scene& scene, const std::string& name, glm::vec3 color, int texture) {
  scene.materials.push_back(Material{name, glm::vec4(color, 1.0f), texture});
  return static_cast<int>(scene.materials.size()) - 1;
}

void addQuad(Mesh& mesh, unsigned a, unsigned b, unsigned c, unsigned d, glm::vec3 facing) {
  const glm::vec3 pa = mesh.positions[a], pb = mesh.positions[b], pc = mesh.positions[c];
  if (glm::dot(glm::cross(pb - pa, pc - pa), facing) >= 0.0f) {
    mesh.triangles.emplace_back(a, b, c);
    mesh.triangles.emplace_back(a, c, d);
  } else {
    mesh.triangles.emplace_back(a, c, b);
    mesh.triangles.emplace_back(a, d, c);
  }
}

void addGridQuads(Mesh& mesh, unsigned first, int countA, int countB, glm::vec3 facing) {
  const auto vertex = [first, countA](int i, int j) {
    return first + static_cast<unsigned>(j * (countA + 1) + i);
  };
  for (int j = 0; j < countB; ++j)
    for (int i = 0; i < countA; ++i)
      addQuad(mesh, vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1), facing);
}

int optionOrDefault(int value, int fallback, const char* what, const std::string& scene) {
  if (value < 0)
    throw Error(ErrorCode::InvalidInput, "built-in scene '" + scene + "': option " + what +
                                             " must not be negative (got " +
                                             std::to_string(value) + ")");
  return value == 0 ? fallback : value;
}

int texelsPerSquare(const BuiltinSceneOptions& options, const std::string& scene) {
  return optionOrDefault(options.texelsPerSquare, kDefaultTexelsPerSquare, "texelsPerSquare", scene);
}

}  // namespace builtin
}  // namespace confvis
