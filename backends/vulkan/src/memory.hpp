#pragma once
// Buffers and images with their memory: creation, uploads through a staging buffer, layout
// transitions and readback of rendered layers.
#include <cstddef>
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

#include "confvis/base/image.hpp"
#include "context.hpp"
#include "handles.hpp"

namespace confvis::vulkan {

// Where a buffer's memory lies. Host: host-visible (staging, readback: the host reads it fast).
// Shared: small buffers the GPU works on (atomics, indirect commands, per-frame uniforms) and
// the host writes or reads a few bytes of: device-local and host-visible where the device has
// such memory (always on lavapipe and integrated GPUs; a discrete GPU's BAR), else Host, since a
// discrete GPU's atomics and indirect reads in host memory cross the bus.
enum class BufferMemory { Device, Host, Shared };

class Buffer {
 public:
  Buffer() = default;
  // Host-visible memory (Host, Shared) is mapped for the buffer's lifetime.
  Buffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
         BufferMemory memory);
  Buffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible)
      : Buffer(context, size, usage, hostVisible ? BufferMemory::Host : BufferMemory::Device) {}
  Buffer(Buffer&&) noexcept = default;
  Buffer& operator=(Buffer&&) noexcept = default;

  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }

 private:
  // Declared so that the buffer goes before its memory (freeing memory also unmaps it).
  UniqueMemory memory_;
  UniqueBuffer buffer_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// A device-local buffer holding `size` bytes of `data` (copied through a staging buffer).
Buffer uploadBuffer(VulkanContext& context, const void* data, std::size_t size,
                    VkBufferUsageFlags usage);

// A texel view of `elements` texels of `format` (texelBytes each) from the start of `buffer`
// (created with VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT). Throws DeviceUnsupported where the
// device's maxTexelBufferElements is smaller; `what` names the data in that message.
UniqueBufferView texelView(VulkanContext& context, VkBuffer buffer, VkFormat format,
                           VkDeviceSize texelBytes, std::size_t elements, const std::string& what);

struct ImageSpec {
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  std::uint32_t width = 1, height = 1, layers = 1;
  VkImageUsageFlags usage = 0;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  bool cube = false;  // six layers viewed as a samplerCube
};

class Image {
 public:
  Image() = default;
  Image(VulkanContext& context, const ImageSpec& spec);

  VkImage get() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  const ImageSpec& spec() const { return spec_; }

 private:
  ImageSpec spec_;
  UniqueMemory memory_;  // destroyed last
  UniqueImage image_;
  UniqueImageView view_;
};

// A barrier on every layer of `image`.
void transitionImage(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                     VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// Fills an R32G32B32A32_SFLOAT image from tightly packed RGBA floats (layers back to back, rows
// from the top) and leaves it ready for sampling in fragment and pre-rasterization stages.
void uploadFloatImage(VulkanContext& context, const Image& image, const float* rgba);
// The same recorded on `cmd` (not submitted): returns the staging buffer, which must live until
// that submission has completed.
Buffer recordFloatImageUpload(VulkanContext& context, VkCommandBuffer cmd, const Image& image,
                              const float* rgba);

// Points binding `binding` of `set` at the whole buffer / at the image view with a sampler
// (shader-read-only layout).
void writeBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                           VkDescriptorType type, VkBuffer buffer);
// The same for `range` bytes from `offset` (a multiple of the device's buffer offset alignment).
void writeBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                           VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset,
                           VkDeviceSize range);
void writeTexelBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                                VkBufferView view);
void writeImageDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                          VkSampler sampler, VkImageView view);

// Converts layer `layer` of readback data (tightly packed RGBA float, as copied by
// vkCmdCopyImageToBuffer) into an image.
ImageRGBA layerToImage(const Buffer& readback, std::uint32_t width, std::uint32_t height,
                       std::uint32_t layer);

}  // namespace confvis::vulkan
