#pragma once
// Small scenes built in code for the renderer comparisons (Vulkan against Embree): textured quads
// placed around the display's reference point, and a display config scaled as a whole.
#include <cmath>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "confvis/engine/display_config.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis::test {

// A `squares` x `squares` checker of `color` and its half, one texel a square (the renderers'
// bilinear filter blends neighbouring squares only within half a texel of their edges).
inline Texture checkerTexture(glm::vec3 color, int squares) {
  Texture texture;
  texture.width = texture.height = squares;
  for (int y = 0; y < squares; ++y)
    for (int x = 0; x < squares; ++x) {
      const glm::vec3 c = ((x + y) % 2) ? color : 0.5f * color;
      texture.rgba.insert(texture.rgba.end(), {c.r, c.g, c.b, 1.0f});
    }
  return texture;
}

// Adds a material (colour factor, optional texture index) and returns its index.
inline int addMaterial(Scene& scene, const std::string& name, glm::vec4 color, int texture = -1) {
  scene.materials.push_back({name, color, texture});
  return static_cast<int>(scene.materials.size()) - 1;
}

inline int addTexture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return static_cast<int>(scene.textures.size()) - 1;
}

// A two-triangle quad centred at `centre`, spanned by half-axes `u` and `v` (its normal u x v),
// uv covering [0, repeats]^2.
inline Mesh quad(const std::string& name, glm::vec3 centre, glm::vec3 u, glm::vec3 v, int material,
                 float repeats = 1.0f) {
  Mesh mesh;
  mesh.name = name;
  for (auto [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
    mesh.positions.push_back(centre + a * u + b * v);
    mesh.uvs.push_back(0.5f * repeats * glm::vec2(a + 1.0f, 1.0f - b));
  }
  mesh.normals.assign(4, glm::normalize(glm::cross(u, v)));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.material = material;
  return mesh;
}

// A quad at `distance` from `c` along the unit `axis`, facing c, half-size `half`.
inline Mesh facingQuad(const std::string& name, glm::vec3 c, glm::vec3 axis, float distance,
                       float half, int material, float repeats = 1.0f) {
  const glm::vec3 u = std::abs(axis.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 v = glm::cross(u, axis);  // u x v = -axis: the normal faces c
  return quad(name, c + distance * axis, half * u, half * v, material, repeats);
}

// Every position of `scene` times `scale` (about the origin).
inline Scene scaledScene(Scene scene, float scale) {
  for (Mesh& mesh : scene.meshes)
    for (glm::vec3& p : mesh.positions) p *= scale;
  return scene;
}

// The display, its reference point and eye separation times `scale` (about the origin).
inline DisplayConfig scaledDisplay(DisplayConfig config, double scale) {
  for (Wall& wall : config.walls) {
    wall.lowerLeft *= scale;
    wall.lowerRight *= scale;
    wall.upperLeft *= scale;
  }
  config.reference *= scale;
  config.eyeSeparation *= scale;
  config.edgeLength *= scale;
  return config;
}

}  // namespace confvis::test
