#include "confvis/backends/embree/embree_scene.hpp"

#include <chrono>
#include <cstring>

#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"

namespace confvis {

namespace {

void attachMesh(EmbreeDevice& device, RTCScene scene, const Mesh& mesh, unsigned meshIndex) {
  RTCGeometry geometry = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  device.check("creating the geometry of mesh " + std::to_string(meshIndex));
  // Embree-owned copies (rtcSetNewGeometryBuffer pads the vertex buffer for its 16-byte loads,
  // which a shared glm::vec3 array would not guarantee).
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(float) * 3,
      mesh.positions.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(unsigned) * 3,
      mesh.triangles.size()));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    device.check("allocating the buffers of mesh " + std::to_string(meshIndex));
    throw Error(ErrorCode::Internal, "Embree returned no buffer for mesh " +
                                         std::to_string(meshIndex));
  }
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3));
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene, geometry, meshIndex);
  rtcReleaseGeometry(geometry);
  device.check("uploading mesh " + std::to_string(meshIndex) + " ('" + mesh.name + "')");
}

}  // namespace

EmbreeScene::EmbreeScene(EmbreeDevice& device, const Scene& scene) : source_(scene) {
  validateScene(source_);
  buildShadingRecords();
  const auto start = SteadyClock::now();
  nativeRay16_ = rtcGetDeviceProperty(device.handle(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
  scene_ = rtcNewScene(device.handle());
  try {
    device.check("creating a scene");
    // Robust mode makes the triangle test watertight: camera rays that pass exactly through a
    // shared edge or vertex (a pixel grid aligned with a mesh grid, as on the checker-sphere)
    // would otherwise slip through the surface.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    for (std::size_t i = 0; i < source_.meshes.size(); ++i)
      if (!source_.meshes[i].triangles.empty())
        attachMesh(device, scene_, source_.meshes[i], static_cast<unsigned>(i));
    rtcCommitScene(scene_);
    device.check("building the BVH of scene '" + source_.name + "'");
  } catch (...) {
    if (scene_) rtcReleaseScene(scene_);
    throw;
  }
  buildSeconds_ =
      secondsSince(start);
  const Bounds box = source_.bounds();
  diagonal_ = box.empty() ? 0.0 : glm::length(glm::dvec3(box.max - box.min));
}

EmbreeScene::~EmbreeScene() { rtcReleaseScene(scene_); }

void EmbreeScene::buildShadingRecords() {
  std::size_t triangles = 1;  // record 0: no hit
  for (const Mesh& mesh : source_.meshes) triangles += mesh.triangles.size();
  if (triangles > UINT32_MAX)
    throw Error(ErrorCode::InvalidInput, "scene '" + source_.name + "' has " +
                                             std::to_string(triangles - 1) +
                                             " triangles; the Embree backend takes at most 2^32 - 2");
  shadingTriangles_.assign(triangles, ShadingTriangle{});
  shadingMaterials_.assign(1, ShadingMaterial{});
  firstShadingTriangle_.clear();
  std::uint32_t next = 1;
  for (const Mesh& mesh : source_.meshes) {
    ShadingMaterial& material = shadingMaterials_.emplace_back();
    material.factor = glm::vec4(1.0f);
    if (mesh.material >= 0) {
      const Material& source = source_.materials[static_cast<std::size_t>(mesh.material)];
      material.factor = source.baseColorFactor;
      if (source.baseColorTexture >= 0 && !mesh.uvs.empty())
        material.texture = &source_.textures[static_cast<std::size_t>(source.baseColorTexture)];
    }
    const auto materialIndex = static_cast<std::uint32_t>(shadingMaterials_.size() - 1);
    firstShadingTriangle_.push_back(next);
    for (const glm::uvec3& corners : mesh.triangles) {
      ShadingTriangle& record = shadingTriangles_[next++];
      record.material = materialIndex;
      for (int k = 0; k < 3; ++k) {
        if (!mesh.normals.empty())
          for (int i = 0; i < 3; ++i) record.normals[3 * k + i] = mesh.normals[corners[k]][i];
        if (material.texture)
          for (int i = 0; i < 2; ++i) record.uvs[2 * k + i] = mesh.uvs[corners[k]][i];
      }
    }
  }
}

}  // namespace confvis
