#include "memory.hpp"

#include <algorithm>
#include <cstring>

#include "confvis/base/error.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

// One descriptor of `type` at `binding`; the caller points it at its buffer, view or image.
VkWriteDescriptorSet descriptorWrite(VkDescriptorSet set, std::uint32_t binding,
                                     VkDescriptorType type) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  return write;
}

UniqueMemory allocate(VulkanContext& context, const VkMemoryRequirements& requirements,
                      std::uint32_t memoryType) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = memoryType;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(context.device(), &info, nullptr, &memory), "vkAllocateMemory");
  return UniqueMemory(context.device(), memory);
}

// The memory type for a buffer's `memory` among typeBits (see BufferMemory).
std::uint32_t bufferMemoryType(const VulkanContext& context, std::uint32_t typeBits,
                               BufferMemory memory) {
  constexpr VkMemoryPropertyFlags kHost =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  if (memory == BufferMemory::Device)
    return context.memoryType(typeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (memory == BufferMemory::Shared)
    if (const auto shared =
            context.findMemoryType(typeBits, kHost | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT))
      return *shared;
  return context.memoryType(typeBits, kHost);
}

}  // namespace

Buffer::Buffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
               BufferMemory memory)
    : size_(size) {
  const bool hostVisible = memory != BufferMemory::Device;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &buffer), "vkCreateBuffer");
  buffer_ = UniqueBuffer(context.device(), buffer);
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(context.device(), buffer, &requirements);
  memory_ = allocate(context, requirements,
                     bufferMemoryType(context, requirements.memoryTypeBits, memory));
  check(vkBindBufferMemory(context.device(), buffer, memory_.get(), 0), "vkBindBufferMemory");
  if (hostVisible)
    check(vkMapMemory(context.device(), memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped_),
          "vkMapMemory");
}

Buffer uploadBuffer(VulkanContext& context, const void* data, std::size_t size,
                    VkBufferUsageFlags usage) {
  Buffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::memcpy(staging.mapped(), data, size);
  Buffer buffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cmd, staging.get(), buffer.get(), 1, &region);
  });
  return buffer;
}

Image::Image(VulkanContext& context, const ImageSpec& spec) : spec_(spec) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.flags = spec.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = spec.format;
  info.extent = {spec.width, spec.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = spec.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = spec.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  check(vkCreateImage(context.device(), &info, nullptr, &image), "vkCreateImage");
  image_ = UniqueImage(context.device(), image);
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(context.device(), image, &requirements);
  memory_ = allocate(context, requirements,
                     context.memoryType(requirements.memoryTypeBits,
                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
  check(vkBindImageMemory(context.device(), image, memory_.get(), 0), "vkBindImageMemory");

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = spec.cube ? VK_IMAGE_VIEW_TYPE_CUBE
                      : spec.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                        : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = spec.format;
  viewInfo.subresourceRange = {spec.aspect, 0, 1, 0, spec.layers};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(context.device(), &viewInfo, nullptr, &view), "vkCreateImageView");
  view_ = UniqueImageView(context.device(), view);
}

void transitionImage(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                     VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.get();
  barrier.subresourceRange = {image.spec().aspect, 0, 1, 0, image.spec().layers};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

Buffer recordFloatImageUpload(VulkanContext& context, VkCommandBuffer cmd, const Image& image,
                              const float* rgba) {
  const ImageSpec& spec = image.spec();
  const std::size_t bytes =
      std::size_t{spec.width} * spec.height * spec.layers * 4 * sizeof(float);
  Buffer staging(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::memcpy(staging.mapped(), rgba, bytes);
  transitionImage(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, spec.layers};
  region.imageExtent = {spec.width, spec.height, 1};
  vkCmdCopyBufferToImage(cmd, staging.get(), image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &region);
  // Compute too: the conformal pre-pass samples the map images.
  transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT);
  return staging;
}

void uploadFloatImage(VulkanContext& context, const Image& image, const float* rgba) {
  Buffer staging;
  context.submitAndWait(
      [&](VkCommandBuffer cmd) { staging = recordFloatImageUpload(context, cmd, image, rgba); });
}

void writeBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                           VkDescriptorType type, VkBuffer buffer) {
  writeBufferDescriptor(device, set, binding, type, buffer, 0, VK_WHOLE_SIZE);
}

void writeBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                           VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset,
                           VkDeviceSize range) {
  const VkDescriptorBufferInfo info{buffer, offset, range};
  VkWriteDescriptorSet write = descriptorWrite(set, binding, type);
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void writeTexelBufferDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                                VkBufferView view) {
  VkWriteDescriptorSet write =
      descriptorWrite(set, binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
  write.pTexelBufferView = &view;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

UniqueBufferView texelView(VulkanContext& context, VkBuffer buffer, VkFormat format,
                           VkDeviceSize texelBytes, std::size_t elements, const std::string& what) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  if (elements > properties.limits.maxTexelBufferElements)
    throw Error(ErrorCode::DeviceUnsupported,
                "Vulkan device '" + std::string(properties.deviceName) + "' holds at most " +
                    std::to_string(properties.limits.maxTexelBufferElements) +
                    " texels in a texel buffer; the conformal pre-pass needs " +
                    std::to_string(elements) + " for " + what);
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer;
  info.format = format;
  info.offset = 0;
  info.range = std::max<std::size_t>(elements, 1) * texelBytes;
  VkBufferView view = VK_NULL_HANDLE;
  check(vkCreateBufferView(context.device(), &info, nullptr, &view), "vkCreateBufferView");
  return UniqueBufferView(context.device(), view);
}

void writeImageDescriptor(VkDevice device, VkDescriptorSet set, std::uint32_t binding,
                          VkSampler sampler, VkImageView view) {
  const VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write =
      descriptorWrite(set, binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

ImageRGBA layerToImage(const Buffer& readback, std::uint32_t width, std::uint32_t height,
                       std::uint32_t layer) {
  ImageRGBA image(static_cast<int>(width), static_cast<int>(height));
  const std::size_t floats = image.pixels.size();
  const float* source = static_cast<const float*>(readback.mapped()) + floats * layer;
  std::memcpy(image.pixels.data(), source, floats * sizeof(float));
  return image;
}

}  // namespace confvis::vulkan
