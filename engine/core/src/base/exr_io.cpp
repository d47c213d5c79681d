#include "confvis/base/exr_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <half.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "exr_internal.hpp"

namespace confvis {
namespace fs = std::filesystem;

namespace {
constexpr std::array<const char*, 4> kChannels = {"R", "G", "B", "A"};
constexpr float kHalfMax = 65504.0f;  // larger values would be stored as infinity

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

const Imf::StringVector kStereoViews = {"left", "right"};

// Multi-view channel naming: the default (first) view's channels are bare, view i's are
// prefixed "<name>.".
std::string viewPrefix(const Imf::StringVector& views, std::size_t i) {
  return i == 0 ? std::string() : views.at(i) + ".";
}
}  // namespace

namespace detail {

void requireWritableImage(const fs::path& path, const ImageRGBA& image, const char* what) {
  if (image.empty() || image.pixels.size() != image.pixelCount() * 4)
    throw Error(ErrorCode::InvalidInput,
                std::string("refusing to write ") + quoted(path) + ": the " + what +
                    " is empty or its pixel buffer does not match " + std::to_string(image.width) +
                    "x" + std::to_string(image.height));
  if (!image.allFinite())
    throw Error(ErrorCode::InvalidInput, std::string("refusing to write ") + quoted(path) +
                                             ": the " + what + " has NaN or infinite values");
}

void writeExrLayers(const fs::path& path, const std::vector<ExrLayer>& layers, ExrPixel pixel,
                    const std::function<void(Imf::Header&)>& addAttributes) {
  const ImageRGBA& first = *layers.at(0).image;
  for (const ExrLayer& layer : layers) {
    requireWritableImage(path, *layer.image, layer.prefix.empty() ? "image" : "view image");
    if (layer.image->width != first.width || layer.image->height != first.height)
      throw Error(ErrorCode::InvalidInput,
                  "refusing to write " + quoted(path) + ": its views differ in size");
    if (pixel == ExrPixel::Half &&
        std::any_of(layer.image->pixels.begin(), layer.image->pixels.end(),
                    [](float v) { return std::abs(v) > kHalfMax; }))
      throw Error(ErrorCode::InvalidInput, "refusing to write " + quoted(path) +
                                               " as half: values exceed 65504 (use Float)");
  }
  const Imf::PixelType fileType = pixel == ExrPixel::Half ? Imf::HALF : Imf::FLOAT;
  // OpenEXR converts pixel types only when reading: half files need a half frame buffer.
  std::vector<std::vector<half>> halfCopies;
  if (pixel == ExrPixel::Half)
    for (const ExrLayer& layer : layers)
      halfCopies.emplace_back(layer.image->pixels.begin(), layer.image->pixels.end());
  writeFileAtomically(path, [&](const fs::path& temp) {
    Imf::Header header(first.width, first.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frameBuffer;
    const Imath::Box2i window = header.dataWindow();
    const std::size_t sampleSize = pixel == ExrPixel::Half ? sizeof(half) : sizeof(float);
    for (std::size_t l = 0; l < layers.size(); ++l) {
      const char* base = pixel == ExrPixel::Half
                             ? reinterpret_cast<const char*>(halfCopies[l].data())
                             : reinterpret_cast<const char*>(layers[l].image->pixels.data());
      for (std::size_t c = 0; c < kChannels.size(); ++c) {
        const std::string name = layers[l].prefix + kChannels[c];
        header.channels().insert(name, Imf::Channel(fileType));
        frameBuffer.insert(name, Imf::Slice::Make(fileType, base + c * sampleSize, window,
                                                  4 * sampleSize, 4 * sampleSize * first.width));
      }
    }
    if (addAttributes) addAttributes(header);
    Imf::OutputFile out(temp.c_str(), header);
    out.setFrameBuffer(frameBuffer);
    out.writePixels(first.height);
  });
}

void withExrInput(const fs::path& path, const std::function<void(Imf::InputFile&)>& use) {
  if (!isRegularFile(path))
    throw Error(ErrorCode::FileNotFound, "cannot open EXR file " + quoted(path) + ": not found");
  requirePlausibleExrHeader(path);
  try {
    Imf::InputFile file(path.c_str());
    use(file);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(ErrorCode::IoFailure, "cannot read EXR file " + quoted(path) + ": " + e.what());
  }
}

ImageRGBA readExrLayer(Imf::InputFile& file, const fs::path& path, const std::string& prefix) {
  const Imath::Box2i window = file.header().dataWindow();
  const Imf::ChannelList& channels = file.header().channels();
  for (std::size_t c = 0; c < 3; ++c)
    if (!channels.findChannel(prefix + kChannels[c]))
      throw Error(ErrorCode::IoFailure,
                  "EXR file " + quoted(path) + " has no channel '" + prefix + kChannels[c] + "'");
  // The window comes from the file: bounded before anything of its size is allocated.
  const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
  const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
  if (width <= 0 || height <= 0 || width > kMaxExrSide || height > kMaxExrSide ||
      width * height > kMaxExrPixels)
    throw Error(ErrorCode::IoFailure, "EXR file " + quoted(path) + " claims " +
                                          std::to_string(width) + "x" + std::to_string(height) +
                                          " pixels (at most " + std::to_string(kMaxExrSide) +
                                          " per side and " + std::to_string(kMaxExrPixels) +
                                          " in all)");
  // Beyond 1 GiB in memory, the file must be large enough to hold it at a plausible compression
  // ratio: a few kilobytes of header must not make confvis fill gigabytes.
  std::error_code ec;
  const auto fileBytes = static_cast<long long>(fs::file_size(path, ec));
  const long long memoryBytes = width * height * 16;
  if (memoryBytes > kMaxExrBytesUnchecked && (ec || memoryBytes / kMaxExrExpansion > fileBytes))
    throw Error(ErrorCode::IoFailure, "EXR file " + quoted(path) + " claims " +
                                          std::to_string(width) + "x" + std::to_string(height) +
                                          " pixels in " + std::to_string(fileBytes) + " bytes");
  ImageRGBA image(static_cast<int>(width), static_cast<int>(height));
  Imf::FrameBuffer frameBuffer;
  for (std::size_t c = 0; c < kChannels.size(); ++c) {
    const double fill = c == 3 ? 1.0 : 0.0;  // opaque when the file has no alpha
    frameBuffer.insert(
        prefix + kChannels[c],
        Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, window, 4 * sizeof(float),
                         4 * sizeof(float) * image.width, 1, 1, fill));
  }
  file.setFrameBuffer(frameBuffer);
  file.readPixels(window.min.y, window.max.y);
  return image;
}

}  // namespace detail

void writeExr(const fs::path& path, const ImageRGBA& image, ExrPixel pixel) {
  detail::writeExrLayers(path, {{"", &image}}, pixel, nullptr);
}

ImageRGBA readExr(const fs::path& path) {
  ImageRGBA image;
  detail::withExrInput(path,
                       [&](Imf::InputFile& file) { image = detail::readExrLayer(file, path, ""); });
  return image;
}

void writeStereoExr(const fs::path& path, const ImageRGBA& left, const ImageRGBA& right) {
  detail::writeExrLayers(
      path, {{viewPrefix(kStereoViews, 0), &left}, {viewPrefix(kStereoViews, 1), &right}},
      ExrPixel::Float, [](Imf::Header& header) { Imf::addMultiView(header, kStereoViews); });
}

std::pair<ImageRGBA, ImageRGBA> readStereoExr(const fs::path& path) {
  std::pair<ImageRGBA, ImageRGBA> views;
  detail::withExrInput(path, [&](Imf::InputFile& file) {
    if (!Imf::hasMultiView(file.header()) || Imf::multiView(file.header()).size() < 2)
      throw Error(ErrorCode::IoFailure,
                  "EXR file " + quoted(path) + " is not a stereo (multi-view) image");
    const Imf::StringVector& names = Imf::multiView(file.header());
    auto prefixOf = [&](const std::string& name, std::size_t fallback) {
      const auto it = std::find(names.begin(), names.end(), name);
      return viewPrefix(
          names, it == names.end() ? fallback : static_cast<std::size_t>(it - names.begin()));
    };
    views.first = detail::readExrLayer(file, path, prefixOf("left", 0));
    views.second = detail::readExrLayer(file, path, prefixOf("right", 1));
  });
  return views;
}

}  // namespace confvis
