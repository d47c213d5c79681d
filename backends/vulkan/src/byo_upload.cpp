// Bring-your-own Vulkan: uploads onto the application's device (byo_upload.hpp), through the
// backend's own staging and layout transitions (memory.cpp, map_images.cpp).
#include "confvis/backends/vulkan/byo_upload.hpp"

#include <cmath>
#include <string>

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

UploadedRetargetMap uploadRetargetMap(const AppDevice& app, const RetargetMap& map) {
  const glm::dvec3 reference = map.reference;
  if (!std::isfinite(reference.x) || !std::isfinite(reference.y) || !std::isfinite(reference.z))
    throw Error(ErrorCode::InvalidInput, "retarget map: reference point is not finite");
  auto impl = std::make_unique<UploadedRetargetMap::Impl>();
  impl->context = std::make_unique<VulkanContext>(app);
  impl->images = uploadMapImages(*impl->context, map);
  const VkSamplerCreateInfo samplerInfo = warpSamplerInfo();
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(app.device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
  impl->sampler = UniqueSampler(app.device, sampler);
  impl->reference = reference;
  impl->fingerprint = fingerprintCubeMap(map.geom, reference);
  return UploadedRetargetMap(std::move(impl));
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
