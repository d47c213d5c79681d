#pragma once
// A confvis Scene uploaded to Embree: one triangle geometry per mesh (geomID = mesh index), one
// committed BVH. Keeps its own copy of the Scene for shading (base colour, normals), so the
// caller's scene may go away after construction.
#include <embree3/rtcore.h>

#include <glm/glm.hpp>

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
  // Unit shading normal at a hit: the interpolated vertex normal where the mesh has normals,
  // else the geometric normal Embree reported (Ng, any length).
  glm::vec3 shadingNormal(unsigned geomID, unsigned primID, float u, float v,
                          const glm::vec3& geometricNormal) const;
  double buildSeconds() const { return buildSeconds_; }

 private:
  RTCScene scene_ = nullptr;
  Scene source_;
  double diagonal_ = 0.0;
  double buildSeconds_ = 0.0;
};

}  // namespace confvis
