// Bring-your-own Vulkan: uploads onto the application's device (byo_upload.hpp), through the
// backend's own staging and layout transitions (memory.cpp, map_images.cpp).
#include "confvis/backends/vulkan/byo_upload.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "byo_internal.hpp"
#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"
#include "confvis/base/error.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {

UploadedRetargetMap::UploadedRetargetMap(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UploadedRetargetMap::UploadedRetargetMap(UploadedRetargetMap&&) noexcept = default;
UploadedRetargetMap& UploadedRetargetMap::operator=(UploadedRetargetMap&&) noexcept = default;
UploadedRetargetMap::~UploadedRetargetMap() = default;
VkImage UploadedRetargetMap::geomImage() const { return impl_->images.geom.get(); }
VkImageView UploadedRetargetMap::geomView() const { return impl_->images.geom.view(); }
VkImage UploadedRetargetMap::rayImage() const { return impl_->images.coverage.get(); }
VkImageView UploadedRetargetMap::rayView() const { return impl_->images.coverage.view(); }
VkSampler UploadedRetargetMap::sampler() const { return impl_->sampler.get(); }
glm::dvec3 UploadedRetargetMap::reference() const { return impl_->reference; }
std::uint32_t UploadedRetargetMap::faceSize() const { return impl_->images.geom.spec().width; }
std::uint64_t UploadedRetargetMap::fingerprint() const { return impl_->fingerprint; }

namespace {

// Everything of an uploaded map but its images; `upload` makes them.
template <class Upload>
UploadedRetargetMap makeUploadedMap(const AppDevice& app, const RetargetMap& map, Upload upload) {
  const glm::dvec3 reference = map.reference;
  if (!std::isfinite(reference.x) || !std::isfinite(reference.y) || !std::isfinite(reference.z))
    throw Error(ErrorCode::InvalidInput, "retarget map: reference point is not finite");
  auto impl = std::make_unique<UploadedRetargetMap::Impl>();
  impl->context = std::make_unique<VulkanContext>(app);
  impl->images = upload(*impl->context);
  const VkSamplerCreateInfo samplerInfo = warpSamplerInfo();
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(app.device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
  impl->sampler = UniqueSampler(app.device, sampler);
  impl->reference = reference;
  impl->fingerprint = fingerprintCubeMap(map.geom, reference);
  return UploadedRetargetMap(std::move(impl));
}

}  // namespace

UploadedRetargetMap uploadRetargetMap(const AppDevice& app, const RetargetMap& map) {
  return makeUploadedMap(app, map,
                         [&](VulkanContext& context) { return uploadMapImages(context, map); });
}

UploadStaging::UploadStaging() : impl_(std::make_unique<Impl>()) {}
UploadStaging::UploadStaging(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UploadStaging::UploadStaging(UploadStaging&&) noexcept = default;
UploadStaging& UploadStaging::operator=(UploadStaging&&) noexcept = default;
UploadStaging::~UploadStaging() = default;
void UploadStaging::submissionCompleted() {
  if (impl_) impl_->buffers.clear();
}
bool UploadStaging::holding() const { return impl_ && !impl_->buffers.empty(); }
VkDeviceSize UploadStaging::bytes() const {
  VkDeviceSize total = 0;
  if (impl_)
    for (const Buffer& buffer : impl_->buffers) total += buffer.size();
  return total;
}

RecordedRetargetMapUpload recordRetargetMapUpload(const AppDevice& app, VkCommandBuffer cmd,
                                                  const RetargetMap& map) {
  if (cmd == VK_NULL_HANDLE)
    throw Error(ErrorCode::InvalidInput, "recordRetargetMapUpload: no command buffer");
  // Validated first: a malformed map leaves `cmd` as it was.
  const MapUploadData data = mapUploadData(map);
  auto staging = std::make_unique<UploadStaging::Impl>();
  UploadedRetargetMap uploaded = makeUploadedMap(app, map, [&](VulkanContext& context) {
    return recordMapImagesUpload(context, cmd, data, staging->buffers);
  });
  return {std::move(uploaded), UploadStaging(std::move(staging))};
}

struct UploadedTexture::Impl {
  std::unique_ptr<VulkanContext> context;  // destroyed last
  Image image;
};
UploadedTexture::UploadedTexture(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UploadedTexture::UploadedTexture(UploadedTexture&&) noexcept = default;
UploadedTexture& UploadedTexture::operator=(UploadedTexture&&) noexcept = default;
UploadedTexture::~UploadedTexture() = default;
VkImage UploadedTexture::image() const { return impl_->image.get(); }
VkImageView UploadedTexture::view() const { return impl_->image.view(); }

UploadedTexture uploadTexture(const AppDevice& app, const Texture& texture) {
  if (texture.width <= 0 || texture.height <= 0 ||
      texture.rgba.size() != 4 * static_cast<std::size_t>(texture.width) * texture.height)
    throw Error(ErrorCode::InvalidInput,
                "texture: " + std::to_string(texture.width) + " x " +
                    std::to_string(texture.height) + " does not match its " +
                    std::to_string(texture.rgba.size()) + " floats");
  auto impl = std::make_unique<UploadedTexture::Impl>();
  impl->context = std::make_unique<VulkanContext>(app);
  ImageSpec spec;
  spec.width = static_cast<std::uint32_t>(texture.width);
  spec.height = static_cast<std::uint32_t>(texture.height);
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  impl->image = Image(*impl->context, spec);
  uploadFloatImage(*impl->context, impl->image, texture.rgba.data());
  return UploadedTexture(std::move(impl));
}

}  // namespace confvis::vulkan
