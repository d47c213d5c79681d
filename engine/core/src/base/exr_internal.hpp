#pragma once
// OpenEXR plumbing shared by exr_io.cpp and cube_map_io.cpp. Private to confvis_base: OpenEXR is
// a private dependency, so no public header includes it.
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "confvis/base/exr_io.hpp"
#include "confvis/base/image.hpp"

namespace confvis::detail {

// Largest image the EXR readers allocate (16 bytes per pixel in memory): a wall's 65536-pixel
// side, and 2^28 pixels (4 GiB) in all; a cube map of 8192 per face is 8192 x 49152 = 2^28.4,
// so the cube reader's own limit (8192 per face) is checked by the shape first.
inline constexpr long long kMaxExrSide = 65536;
inline constexpr long long kMaxExrPixels = 8192LL * 6 * 8192;
// An image needing more than 1 GiB in memory is read only from a file at least 1/2000 of that
// size (ZIP, the writers' compression, stays far below 2000:1 on real images).
inline constexpr long long kMaxExrBytesUnchecked = 1LL << 30;
inline constexpr long long kMaxExrExpansion = 2000;
// Most tiles of a tiled EXR's first level: OpenEXR allocates 8 bytes per tile before reading any.
inline constexpr long long kMaxExrTiles = 1LL << 22;

// Throws Error(InvalidInput) naming `path` if the image is empty or has NaN/infinite values.
void requireWritableImage(const std::filesystem::path& path, const ImageRGBA& image,
                          const char* what = "image");

// One image stored as channels <prefix>R, <prefix>G, <prefix>B, <prefix>A.
struct ExrLayer {
  std::string prefix;
  const ImageRGBA* image;
};

// Writes same-sized layers into one ZIP-compressed scanline EXR, atomically. `addAttributes` may
// add header attributes (envmap, multiView). Validates the layers first.
void writeExrLayers(const std::filesystem::path& path, const std::vector<ExrLayer>& layers,
                    ExrPixel pixel, const std::function<void(Imf::Header&)>& addAttributes);

// Refuses, with Error(IoFailure) naming the file, an EXR header that would make OpenEXR allocate
// more than the file can hold: an attribute larger than the rest of the file, a data window
// beyond kMaxExrSide / kMaxExrPixels, more than kMaxExrTiles tiles (exr_header_check.cpp).
void requirePlausibleExrHeader(const std::filesystem::path& path);

// Opens `path` and runs `use(file)`, turning a missing file into Error(FileNotFound) and any
// OpenEXR or system exception into Error(IoFailure); both messages name the file.
void withExrInput(const std::filesystem::path& path,
                  const std::function<void(Imf::InputFile&)>& use);

// Reads channels <prefix>R, G, B (required) and A (optional, default 1) of the whole data window;
// Error(IoFailure) for a window beyond kMaxExrSide / kMaxExrPixels.
ImageRGBA readExrLayer(Imf::InputFile& file, const std::filesystem::path& path,
                       const std::string& prefix);

}  // namespace confvis::detail
