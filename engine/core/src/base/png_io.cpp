#include "confvis/base/png_io.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"

// libpng's simplified API (png_image_*) reports errors through return values and a message,
// so no setjmp/longjmp crosses C++ frames.
namespace confvis {
namespace fs = std::filesystem;

namespace {
std::uint8_t toCode(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

float linearToSrgb(float linear) {
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

void writePng(const fs::path& path, const ImageRGBA& image, const PngOptions& options) {
  if (image.empty() || image.pixels.size() != image.pixelCount() * 4 || !image.allFinite())
    throw Error(ErrorCode::InvalidInput, "refusing to write PNG '" + path.string() +
                                             "': the image is empty or has NaN/infinite values");
  if (!std::isfinite(options.exposure))
    throw Error(ErrorCode::InvalidInput,
                "refusing to write PNG '" + path.string() + "': exposure is not finite");
  const int channels = options.alpha ? 4 : 3;
  std::vector<std::uint8_t> codes(image.pixelCount() * channels);
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const float* rgba = image.pixels.data() + 4 * p;
    for (int c = 0; c < 3; ++c) {
      const float v = std::clamp(rgba[c] * options.exposure, 0.0f, 1.0f);
      codes[channels * p + c] = toCode(options.srgb ? linearToSrgb(v) : v);
    }
    if (options.alpha) codes[channels * p + 3] = toCode(rgba[3]);
  }
  writeFileAtomically(path, [&](const fs::path& temp) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = options.alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
    if (!options.srgb) png.flags |= PNG_IMAGE_FLAG_COLORSPACE_NOT_sRGB;
    if (!png_image_write_to_file(&png, temp.c_str(), 0, codes.data(), 0, nullptr))
      throw Error(ErrorCode::IoFailure, "cannot write PNG '" + path.string() + "': " + png.message);
  });
}

ImageRGBA readPng(const fs::path& path, PngDecoding decoding) {
  if (!isRegularFile(path))
    throw Error(ErrorCode::FileNotFound, "cannot open PNG file '" + path.string() + "': not found");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw Error(ErrorCode::IoFailure,
                "cannot read PNG file '" + path.string() + "': " + png.message);
  png.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> codes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, codes.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw Error(ErrorCode::IoFailure, "cannot read PNG file '" + path.string() + "': " + message);
  }
  ImageRGBA image(static_cast<int>(png.width), static_cast<int>(png.height));
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const float raw = codes[i] / 255.0f;
    const bool colour = i % 4 != 3;
    image.pixels[i] = colour && decoding == PngDecoding::SrgbToLinear ? srgbToLinear(raw) : raw;
  }
  return image;
}

}  // namespace confvis
