#pragma once
// Internal pieces shared by the OBJ and glTF loaders.
#include <cstddef>
#include <filesystem>
#include <string>

#include "confvis/engine/scene.hpp"

namespace confvis::scene_files {

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
