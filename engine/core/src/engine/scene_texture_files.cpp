// Image decoding for scene textures. stb_image comes from Debian's libstb (linked as a shared
// library, so no STB_IMAGE_IMPLEMENTATION here; TinyGLTF's own shared library uses it too).
#include <stb_image.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>

#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "scene_file_parts.hpp"

namespace confvis::scene_files {

namespace {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float channelValue(const void* pixels, std::size_t index, int bitsPerChannel) {
  if (bitsPerChannel == 16) return static_cast<const std::uint16_t*>(pixels)[index] / 65535.0f;
  if (bitsPerChannel == 32) return static_cast<const float*>(pixels)[index];
  return static_cast<const std::uint8_t*>(pixels)[index] / 255.0f;
}

}  // namespace

Texture textureFromPixels(const void* pixels, int width, int height, int channels,
                          int bitsPerChannel, bool srgb) {
  Texture texture;
  texture.width = width;
  texture.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  texture.rgba.resize(4 * count);
  const auto stride = static_cast<std::size_t>(channels);
  const bool hasAlpha = channels == 2 || channels == 4;
  const std::size_t colorChannels = channels >= 3 ? 3 : 1;
  for (std::size_t p = 0; p < count; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float value = channelValue(pixels, p * stride + (colorChannels == 3 ? c : 0),
                                       bitsPerChannel);
      texture.rgba[4 * p + c] = srgb ? srgbToLinear(value) : value;
    }
    texture.rgba[4 * p + 3] =
        hasAlpha ? channelValue(pixels, p * stride + stride - 1, bitsPerChannel) : 1.0f;
  }
  return texture;
}

Texture loadTextureFile(const std::filesystem::path& path) {
  if (!isRegularFile(path))
    throw Error(ErrorCode::FileNotFound, "texture image '" + path.string() + "' does not exist");
  int width = 0, height = 0, channels = 0;
  if (stbi_info(path.c_str(), &width, &height, &channels) && !texturePixelsAllowed(width, height))
    throw Error(ErrorCode::InvalidInput, "texture image '" + path.string() + "' is " +
                                             std::to_string(width) + "x" + std::to_string(height) +
                                             " pixels (at most " +
                                             std::to_string(kMaxTexturePixels) + ")");
  const bool hdr = stbi_is_hdr(path.c_str()) != 0;
  const std::unique_ptr<void, void (*)(void*)> pixels(
      hdr ? static_cast<void*>(stbi_loadf(path.c_str(), &width, &height, &channels, 0))
          : static_cast<void*>(stbi_load(path.c_str(), &width, &height, &channels, 0)),
      &stbi_image_free);
  if (!pixels)
    throw Error(ErrorCode::InvalidInput, "cannot read texture image '" + path.string() +
                                             "': " + stbi_failure_reason());
  return textureFromPixels(pixels.get(), width, height, channels, hdr ? 32 : 8, !hdr);
}

void warn(const std::filesystem::path& file, const std::string& message) {
  std::cerr << "confvis: warning: " << file.string() << ": " << message << '\n';
}

}  // namespace confvis::scene_files
