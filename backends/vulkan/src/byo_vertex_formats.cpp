#include "byo_vertex_formats.hpp"

#include <array>
#include <cstring>
#include <utility>

#include <glm/gtc/packing.hpp>

#include "confvis/base/error.hpp"

namespace confvis::vulkan {
namespace {

constexpr std::array<VkFormat, 3> kVectorFormats = {
    VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT};
constexpr std::array<VkFormat, 3> kUvFormats = {VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R16G16_SFLOAT,
                                                VK_FORMAT_R16G16_UNORM};

float readFloat(const unsigned char* data) {
  float value;
  std::memcpy(&value, data, sizeof(value));
  return value;
}

std::uint16_t read16(const unsigned char* data) {
  std::uint16_t value;
  std::memcpy(&value, data, sizeof(value));
  return value;
}

}  // namespace

std::string vertexFormatName(VkFormat format) {
  static const std::pair<VkFormat, const char*> kNames[] = {
      {VK_FORMAT_R32G32B32_SFLOAT, "VK_FORMAT_R32G32B32_SFLOAT"},
      {VK_FORMAT_R32G32B32A32_SFLOAT, "VK_FORMAT_R32G32B32A32_SFLOAT"},
      {VK_FORMAT_R16G16B16A16_SFLOAT, "VK_FORMAT_R16G16B16A16_SFLOAT"},
      {VK_FORMAT_R32G32_SFLOAT, "VK_FORMAT_R32G32_SFLOAT"},
      {VK_FORMAT_R16G16_SFLOAT, "VK_FORMAT_R16G16_SFLOAT"},
      {VK_FORMAT_R16G16_UNORM, "VK_FORMAT_R16G16_UNORM"},
      {VK_FORMAT_R32_SFLOAT, "VK_FORMAT_R32_SFLOAT"},
      {VK_FORMAT_R16G16B16_SFLOAT, "VK_FORMAT_R16G16B16_SFLOAT"},
      {VK_FORMAT_R16G16B16A16_UNORM, "VK_FORMAT_R16G16B16A16_UNORM"},
      {VK_FORMAT_R16G16B16A16_SNORM, "VK_FORMAT_R16G16B16A16_SNORM"},
      {VK_FORMAT_R16G16_SNORM, "VK_FORMAT_R16G16_SNORM"},
      {VK_FORMAT_R8G8B8A8_UNORM, "VK_FORMAT_R8G8B8A8_UNORM"},
      {VK_FORMAT_R8G8_UNORM, "VK_FORMAT_R8G8_UNORM"},
      {VK_FORMAT_R8G8_SNORM, "VK_FORMAT_R8G8_SNORM"},
      {VK_FORMAT_R16G16B16_UNORM, "VK_FORMAT_R16G16B16_UNORM"},
      {VK_FORMAT_R16G16B16_SNORM, "VK_FORMAT_R16G16B16_SNORM"},
      {VK_FORMAT_R8G8B8A8_SNORM, "VK_FORMAT_R8G8B8A8_SNORM"},
      {VK_FORMAT_A2B10G10R10_SNORM_PACK32, "VK_FORMAT_A2B10G10R10_SNORM_PACK32"},
      {VK_FORMAT_A2B10G10R10_UNORM_PACK32, "VK_FORMAT_A2B10G10R10_UNORM_PACK32"},
      {VK_FORMAT_R64G64B64_SFLOAT, "VK_FORMAT_R64G64B64_SFLOAT"},
      {VK_FORMAT_R32G32B32_UINT, "VK_FORMAT_R32G32B32_UINT"},
      {VK_FORMAT_R32G32B32_SINT, "VK_FORMAT_R32G32B32_SINT"},
  };
  for (const auto& [known, name] : kNames)
    if (known == format) return name;
  return "VkFormat " + std::to_string(static_cast<int>(format));
}

std::uint32_t attributeBytes(AttributeRole role, const char* attribute, VkFormat format) {
  const bool uv = role == AttributeRole::Uv;
  switch (format) {
    case VK_FORMAT_R32G32B32_SFLOAT: if (!uv) return 12; break;
    case VK_FORMAT_R32G32B32A32_SFLOAT: if (!uv) return 16; break;
    case VK_FORMAT_R16G16B16A16_SFLOAT: if (!uv) return 8; break;
    case VK_FORMAT_R32G32_SFLOAT: if (uv) return 8; break;
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16_UNORM: if (uv) return 4; break;
    default: break;
  }
  std::string supported;
  for (const VkFormat f : uv ? kUvFormats : kVectorFormats)
    supported += (supported.empty() ? "" : ", ") + vertexFormatName(f);
  throw Error(ErrorCode::InvalidInput, "pre-pass geometry: " + std::string(attribute) +
                                           " format " + vertexFormatName(format) +
                                           " is not supported (" + attribute + "s take " +
                                           supported + ")");
}

glm::vec3 readAttribute(VkFormat format, const unsigned char* data) {
  switch (format) {
    case VK_FORMAT_R32G32B32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return {readFloat(data), readFloat(data + 4), readFloat(data + 8)};
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return {glm::unpackHalf1x16(read16(data)), glm::unpackHalf1x16(read16(data + 2)),
              glm::unpackHalf1x16(read16(data + 4))};
    case VK_FORMAT_R32G32_SFLOAT: return {readFloat(data), readFloat(data + 4), 0.0f};
    case VK_FORMAT_R16G16_SFLOAT:
      return {glm::unpackHalf1x16(read16(data)), glm::unpackHalf1x16(read16(data + 2)), 0.0f};
    case VK_FORMAT_R16G16_UNORM:
      return {read16(data) / 65535.0f, read16(data + 2) / 65535.0f, 0.0f};
    default: break;
  }
  throw Error(ErrorCode::Internal, "readAttribute: unchecked format " + vertexFormatName(format));
}

}  // namespace confvis::vulkan
