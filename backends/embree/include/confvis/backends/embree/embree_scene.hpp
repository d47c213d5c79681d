#pragma once
// A confvis Scene uploaded to Embree: one triangle geometry per mesh (geomID = mesh index), one
// committed BVH. Keeps its own copy of the Scene for shading (base colour, normals), so the
// caller's scene may go away after construction.
#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/base/export.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: immutable once built; rays may be traced through handle() from any number of
// threads at once (Embree committed scenes are thread-safe to intersect).
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
  // Whether the device traces 16-ray packets natively (AVX-512): the renderer then traces two
  // 8-ray packets with one rtcIntersect16, otherwise with two rtcIntersect8.
  bool nativeRay16() const { return nativeRay16_; }
  // What shading reads per hit (Scene::baseColorAt: factor x texture sampled at the uvs, and
  // the vertex normals, both interpolated with Embree's barycentrics), built here so that a hit
  // reads one cache line instead of the triangle's indices and then its vertices.
  struct alignas(64) ShadingTriangle {
    float normals[9] = {};   // n0, n1, n2; zeros where the mesh has none
    float uvs[6] = {};       // uv0, uv1, uv2; zeros where the mesh has no texture
    std::uint32_t material = 0;  // index into shadingMaterial()
  };
  static_assert(sizeof(ShadingTriangle) == 64);
  struct ShadingMaterial {  // one per mesh, after the "no hit" material 0 (black, untextured)
    const Texture* texture = nullptr;  // null: no texture, or no uvs to look it up with
    glm::vec4 factor{0.0f};            // material base colour factor (white without a material)
  };
  // The record of triangle primID of mesh geomID; record 0 (zeros, material 0) stands for no hit.
  std::uint32_t shadingTriangleIndex(unsigned geomID, unsigned primID) const {
    return firstShadingTriangle_[geomID] + primID;
  }
  const ShadingTriangle* shadingTriangles() const { return shadingTriangles_.data(); }
  const ShadingMaterial& shadingMaterial(std::uint32_t index) const {
    return shadingMaterials_[index];
  }
  double buildSeconds() const { return buildSeconds_; }

 private:
  void buildShadingRecords();

  std::vector<ShadingTriangle> shadingTriangles_;
  std::vector<std::uint32_t> firstShadingTriangle_;  // per mesh (geomID)
  std::vector<ShadingMaterial> shadingMaterials_;
  RTCScene scene_ = nullptr;
  Scene source_;
  double diagonal_ = 0.0;
  bool nativeRay16_ = false;
  double buildSeconds_ = 0.0;
};

}  // namespace confvis
