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
  // What shading reads per hit, one per mesh (geomID), pointing into scene(): Scene::baseColorAt
  // is factor x texture sampled at the uvs interpolated with Embree's barycentrics.
  struct ShadingMesh {
    const glm::uvec3* triangles = nullptr;
    const glm::vec3* normals = nullptr;  // null: the mesh has none
    const glm::vec2* uvs = nullptr;
    const Texture* texture = nullptr;    // null: no texture, or no uvs to look it up with
    glm::vec4 factor{1.0f};              // material base colour factor (white without one)
  };
  // No bounds check: geomID comes from Embree.
  const ShadingMesh& shadingMesh(unsigned geomID) const { return shadingMeshes_[geomID]; }
  double buildSeconds() const { return buildSeconds_; }

 private:
  std::vector<ShadingMesh> shadingMeshes_;
  RTCScene scene_ = nullptr;
  Scene source_;
  double diagonal_ = 0.0;
  double buildSeconds_ = 0.0;
};

}  // namespace confvis
