#pragma once
// Bring-your-own Vulkan: the vertex attribute formats the conformal pre-pass step reads from an
// application's vertices (byo_prepass.hpp, VertexLayout), converted to float on the host.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

namespace confvis::vulkan {

// What an attribute is: positions and normals (three components used), or uvs (two).
enum class AttributeRole { Position, Normal, Uv };

// Bytes one attribute of `format` takes; throws Error(InvalidInput) naming `attribute` and the
// format (VK_FORMAT_...) with the formats the role takes where it is not one of them.
std::uint32_t attributeBytes(AttributeRole role, const char* attribute, VkFormat format);

// The attribute at `data` (unaligned) as floats: xyz of a position or normal, xy of a uv (z 0).
// `format` is one attributeBytes accepted.
glm::vec3 readAttribute(VkFormat format, const unsigned char* data);

// "VK_FORMAT_R16G16B16_SFLOAT" for the formats vertex buffers commonly hold, else
// "VkFormat <number>".
std::string vertexFormatName(VkFormat format);

}  // namespace confvis::vulkan
