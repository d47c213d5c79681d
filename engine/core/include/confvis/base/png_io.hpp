#pragma once
// 8-bit PNG previews of linear float images (libpng), for humans and for image tests; the
// authoritative outputs are EXR. Written atomically.
#include <filesystem>

#include "confvis/base/export.hpp"
#include "confvis/base/image.hpp"

namespace confvis CONFVIS_API {

struct PngOptions {
  float exposure = 1.0f;  // RGB is multiplied by this before encoding (alpha is not)
  bool srgb = true;       // encode RGB with the sRGB transfer curve; false: store linear values
  bool alpha = false;     // write an RGBA file; false: RGB, alpha dropped
};

// Values are clamped to [0, 1] and rounded to the nearest 8-bit code. Throws Error(InvalidInput)
// for empty or non-finite images (naming the file), Error(IoFailure) when writing fails.
// The file is tagged sRGB either way (libpng's simplified API); srgb = false is meant for data
// previews whose codes should equal round(255 * value).
void writePng(const std::filesystem::path& path, const ImageRGBA& image,
              const PngOptions& options = {});

enum class PngDecoding {
  SrgbToLinear,  // RGB codes decoded with the sRGB curve: undoes writePng's default encoding
  Raw,           // every channel is code / 255: undoes writePng with srgb = false
};

// Reads any PNG as 8-bit RGBA (grey and palette files are expanded, missing alpha is 1). Alpha is
// always code / 255. Throws Error(FileNotFound) / Error(IoFailure) naming the file.
ImageRGBA readPng(const std::filesystem::path& path,
                  PngDecoding decoding = PngDecoding::SrgbToLinear);

// The sRGB transfer functions (IEC 61966-2-1) on one value, exposed for tests and previews.
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace confvis
