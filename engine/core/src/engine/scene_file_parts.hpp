#pragma once
// Internal pieces shared by the OBJ and glTF loaders.
#include <cstddef>
#include <filesystem>
#include <string>

#include "confvis/engine/scene.hpp"

namespace confvis::scene_files {

// Limits of scene files (documented in the README): checked from the counts in a file before
// anything of that size is allocated, so a small file cannot ask for gigabytes.
inline constexpr std::size_t kMaxTexturePixels = std::size_t{1} << 25;  // 8192 x 4096
inline constexpr std::size_t kMaxSceneTriangles = std::size_t{1} << 23;  // ~8.4 million
inline constexpr std::size_t kMaxSceneVertices = std::size_t{1} << 23;
inline constexpr std::size_t kMaxNodeInstances = std::size_t{1} << 16;  // glTF node visits

inline bool texturePixelsAllowed(int width, int height) {
  return width > 0 && height > 0 &&
         static_cast<std::size_t>(width) * static_cast<std::size_t>(height) <= kMaxTexturePixels;
}

// Converts interleaved pixels (1-4 channels, 8 or 16 bits each, row 0 first) into a linear RGBA
// Texture. Colour channels are sRGB-decoded when `srgb`; alpha never is. Grey images fill RGB.
Texture textureFromPixels(const void* pixels, int width, int height, int channels,
                          int bitsPerChannel, bool srgb);

// Reads an image file with stb_image (8-bit files as sRGB, .hdr as linear). Throws
// Error(FileNotFound) for a missing file and Error(InvalidInput) with stb's reason otherwise.
Texture loadTextureFile(const std::filesystem::path& path);

void warn(const std::filesystem::path& file, const std::string& message);

Scene loadObjScene(const std::filesystem::path& path);
Scene loadGltfScene(const std::filesystem::path& path, bool binary);

}  // namespace confvis::scene_files
