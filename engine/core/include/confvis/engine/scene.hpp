#pragma once
// The scene both renderers share: flat, renderer-agnostic arrays that Embree (shared vertex and
// index buffers) and Vulkan (vertex/index buffers, one draw per mesh) upload without conversion.
// Units and frame follow conformal-pipeline.md §2: metres, right-handed, +y up, -z forward.
#include <glm/glm.hpp>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// An RGBA image in linear colour (sRGB-encoded files are decoded on load).
// Orientation follows glTF: row 0 is the top of the image and lies at uv v = 0; u grows to the
// right. OBJ files (v = 0 at the bottom) are flipped on load so that every Scene uses this one.
// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct Texture {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  // width * height * 4, row-major from row 0

  glm::vec4 texel(int x, int y) const;  // x, y wrapped (repeat)
  // Bilinear filtering with repeat wrap; texel centres at ((x + 0.5) / width, (y + 0.5) / height).
  // Inline: renderers call it per hit, and nearly every footprint lies inside the image (float
  // maths, no wrapping); the rest goes to sampleWrapped.
  glm::vec4 sample(glm::vec2 uv) const {
    const float x = uv.x * static_cast<float>(width) - 0.5f;
    const float y = uv.y * static_cast<float>(height) - 0.5f;
    if (!(x >= 0.0f && y >= 0.0f && x < static_cast<float>(width - 1) &&
          y < static_cast<float>(height - 1)))
      return sampleWrapped(uv);
    const int ix = static_cast<int>(x), iy = static_cast<int>(y);
    const float fx = x - static_cast<float>(ix), fy = y - static_cast<float>(iy);
    const float* row0 = rgba.data() + 4 * (static_cast<std::size_t>(iy) * width + ix);
    const float* row1 = row0 + 4 * static_cast<std::size_t>(width);
    const glm::vec4 a(row0[0], row0[1], row0[2], row0[3]), b(row0[4], row0[5], row0[6], row0[7]);
    const glm::vec4 c(row1[0], row1[1], row1[2], row1[3]), d(row1[4], row1[5], row1[6], row1[7]);
    return glm::mix(glm::mix(a, b, fx), glm::mix(c, d, fx), fy);
  }
  // The general case of sample: any uv, repeat wrap (1 for an empty texture).
  glm::vec4 sampleWrapped(glm::vec2 uv) const;
};

// The glTF metallic-roughness model reduced to what both renderers need: the base colour.
struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};
  int baseColorTexture = -1;  // index into Scene::textures, -1 = none
};

// One triangle list with one material. normals and uvs are per vertex and either empty or the
// same length as positions; triangles index positions counter-clockwise seen from the side the
// normals point to.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::uvec3> triangles;
  int material = -1;  // index into Scene::materials, -1 = default white
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};
  bool empty() const { return min.x > max.x; }
  void extend(glm::vec3 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;

  // Base colour at a point of a triangle; barycentrics follow Embree's hit (u, v):
  // p = (1 - u - v) * p0 + u * p1 + v * p2. Factor times texture sample where there is one.
  glm::vec4 baseColorAt(std::size_t meshIndex, std::size_t triangle, glm::vec2 barycentrics) const;
  std::size_t triangleCount() const;
  std::size_t vertexCount() const;
  Bounds bounds() const;
};

// Throws Error(InvalidInput) naming the scene and mesh when indices, attribute array lengths,
// material or texture references are inconsistent, or when the scene has no triangles.
void validateScene(const Scene& scene);

// Replaces a mesh's normals by per-face normals (vertices are unshared so each triangle gets its
// own); used where a file provides no normals.
void generateFlatNormals(Mesh& mesh);

}  // namespace confvis
