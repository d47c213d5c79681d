#pragma once
// A confvis Scene uploaded to Embree: one triangle geometry per mesh (geomID = mesh index), one
// committed BVH. Keeps its own copy of the Scene for shading (base colour, normals), so the
// caller's scene may go away after construction.
#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <vector>

#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis {

class EmbreeScene {
 public:
  // Validates the scene (validateScene) and builds the BVH; Embree errors become Error.
  EmbreeScene(EmbreeDevice& device, const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return scene_; }
  const Scene& scene() const { return source_; }
  // Length of the bounding-box diagonal, metres (a scale for ambient-occlusion distances).
  double diagonal() const { return diagonal_; }
  // The vertex normals interpolated at a hit, not normalised; zero where the mesh has none.
  glm::vec3 interpolatedNormal(unsigned geomID, unsigned primID, float u, float v) const {
    const ShadingMesh& mesh = shadingMeshes_[geomID];
    if (!mesh.normals) return glm::vec3(0.0f);
    const glm::uvec3 t = mesh.triangles[primID];
    return (1.0f - u - v) * mesh.normals[t.x] + u * mesh.normals[t.y] + v * mesh.normals[t.z];
  }
  // Scene::baseColorAt for a hit, from the flattened per-mesh data (no bounds checks: geomID and
  // primID come from Embree).
  glm::vec4 baseColor(unsigned geomID, unsigned primID, float u, float v) const {
    const ShadingMesh& mesh = shadingMeshes_[geomID];
    if (!mesh.texture) return mesh.factor;
    const glm::uvec3 t = mesh.triangles[primID];
    const glm::vec2 uv = (1.0f - u - v) * mesh.uvs[t.x] + u * mesh.uvs[t.y] + v * mesh.uvs[t.z];
    return mesh.factor * mesh.texture->sample(uv);
  }
  double buildSeconds() const { return buildSeconds_; }

 private:
  // What shading reads per hit, one per mesh, pointing into source_.
  struct ShadingMesh {
    const glm::uvec3* triangles = nullptr;
    const glm::vec3* normals = nullptr;  // null: the mesh has none
    const glm::vec2* uvs = nullptr;
    const Texture* texture = nullptr;    // null: no texture, or no uvs to look it up with
    glm::vec4 factor{1.0f};              // material base colour factor (white without one)
  };
  std::vector<ShadingMesh> shadingMeshes_;
  RTCScene scene_ = nullptr;
  Scene source_;
  double diagonal_ = 0.0;
  double buildSeconds_ = 0.0;
};

}  // namespace confvis
