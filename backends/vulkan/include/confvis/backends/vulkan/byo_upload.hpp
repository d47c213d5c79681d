#pragma once
// Bring-your-own Vulkan (issue 25): uploads onto the application's device and queue. Each
// upload stages its texels in a host-visible buffer, records the layout transitions (UNDEFINED
// -> TRANSFER_DST_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL) and the copy in a command buffer of its
// own on `app.queue`, submits it and waits for it: on return the images are in
// VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ready to sample in any later submission.
// recordRetargetMapUpload (below) instead records the same on the application's own command
// buffer and leaves the submission, and the staging memory's lifetime, to the application.
// Thread-safety: an upload uses app.queue (see byo_device.hpp); the objects are move-only and
// their getters may be called from any thread.
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"
#include "confvis/backends/vulkan/byo_device.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

// A RetargetMap on the device: both cube maps as R32G32B32A32_SFLOAT cube images (kGeomMapFormat,
// faces in Vulkan's order, converted by toVulkanLayout) with cube views, and the warp's sampler
// (warpSamplerInfo: linear, clamp to edge). Bind geomView() with sampler() at
// CONFVIS_WARP_SET / CONFVIS_WARP_BINDING of confvis_warp.glsl for the warp; the conformal
// pre-pass step (byo_prepass.hpp) reads both. Destroys its objects (not the device) when
// destroyed, without waiting for the device: keep it alive until the device has finished every
// command that samples it (the same holds for UploadedTexture and ConformalPrepassStep).
// Thread-safety: its accessors are const and may be read from any thread; move or destroy it
// from one thread while nothing else uses it.
class UploadedRetargetMap {
 public:
  UploadedRetargetMap(UploadedRetargetMap&&) noexcept;
  UploadedRetargetMap& operator=(UploadedRetargetMap&&) noexcept;
  ~UploadedRetargetMap();

  VkImage geomImage() const;
  VkImageView geomView() const;    // samplerCube: virtual direction -> physical direction
  VkImage rayImage() const;
  VkImageView rayView() const;     // samplerCube: physical -> virtual, alpha: the display's coverage
  VkSampler sampler() const;
  glm::dvec3 reference() const;    // the warp centre c (RetargetMap::reference)
  std::uint32_t faceSize() const;  // geom map texels per face side
  // A hash of the geom texels and the reference point: equal for the same map.
  std::uint64_t fingerprint() const;

  struct Impl;
  explicit UploadedRetargetMap(std::unique_ptr<Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// Throws Error(InvalidInput) for a malformed map (face sizes, non-finite texels, non-finite
// reference point), Error(DeviceUnsupported) where the device lacks the memory or the format.
UploadedRetargetMap uploadRetargetMap(const AppDevice& app, const RetargetMap& map);

// The staging memory of an upload recorded on the application's command buffer
// (recordRetargetMapUpload): hold it until that command buffer's submission has completed (its
// fence signalled, a timeline semaphore reached, vkQueueWaitIdle returned), then call
// submissionCompleted() or destroy it; both free the staging buffers.
// Thread-safety: one thread at a time; move or destroy it from one thread.
class UploadStaging {
 public:
  UploadStaging();
  UploadStaging(UploadStaging&&) noexcept;
  UploadStaging& operator=(UploadStaging&&) noexcept;
  ~UploadStaging();

  void submissionCompleted();  // frees the staging buffers (again: nothing)
  bool holding() const;        // whether it still holds staging buffers
  VkDeviceSize bytes() const;  // the staging memory it holds, bytes (0 once freed)

  struct Impl;
  explicit UploadStaging(std::unique_ptr<Impl> impl);

 private:
  std::unique_ptr<Impl> impl_;
};

struct RecordedRetargetMapUpload {
  // Its images are in SHADER_READ_ONLY_OPTIMAL for every command recorded on `cmd` after the
  // upload (a barrier makes the copy visible to graphics and compute shader reads) and for later
  // submissions on the queue.
  UploadedRetargetMap map;
  UploadStaging staging;
};

// recordRetargetMapUpload(app, cmd, map): uploadRetargetMap recorded on `cmd` (a primary command
// buffer in the recording state, outside a render pass, for app.queueFamily) and not submitted:
// the layout transitions UNDEFINED -> TRANSFER_DST_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL and the
// copies from host-visible staging buffers, whose texels are written before it returns. The
// application submits `cmd` when it likes (say with the frame's pre-pass and draws) and keeps
// `staging` until that submission has completed. The same errors as uploadRetargetMap, thrown
// before anything is recorded on `cmd`.
RecordedRetargetMapUpload recordRetargetMapUpload(const AppDevice& app, VkCommandBuffer cmd,
                                                  const RetargetMap& map);

// A scene texture (RGBA float, rows from the top) as an R32G32B32A32_SFLOAT 2D image with a view,
// in SHADER_READ_ONLY_OPTIMAL; for applications that draw confvis scenes with their own
// pipeline (the example under tools/byo_vulkan_example). Throws Error(InvalidInput) for a
// texture whose size and texel count disagree.
// Thread-safety: as UploadedRetargetMap.
class UploadedTexture {
 public:
  UploadedTexture(UploadedTexture&&) noexcept;
  UploadedTexture& operator=(UploadedTexture&&) noexcept;
  ~UploadedTexture();
  VkImage image() const;
  VkImageView view() const;

  struct Impl;
  explicit UploadedTexture(std::unique_ptr<Impl> impl);

 private:
  std::unique_ptr<Impl> impl_;
};
UploadedTexture uploadTexture(const AppDevice& app, const Texture& texture);

}  // namespace vulkan
}  // namespace confvis
