#include "gltf_file_checks.hpp"

#include <stb_image.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/base/input_limits.hpp"
#include "scene_file_parts.hpp"

namespace confvis::scene_files {

void requireGltfJsonDepth(const std::string& bytes, bool binary,
                          const std::filesystem::path& path) {
  const std::string source = "glTF file '" + path.string() + "'";
  if (!binary) {
    requireJsonDepth(bytes, source);
    return;
  }
  // GLB: a 12-byte header, then the JSON chunk (length, type, bytes). A malformed header is
  // tinygltf's to report.
  constexpr std::size_t kChunkStart = 20;
  if (bytes.size() < kChunkStart || bytes.compare(0, 4, "glTF") != 0) return;
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  if (!byteRangeFits(kChunkStart, length, bytes.size())) return;
  requireJsonDepth(std::string_view(bytes).substr(kChunkStart, length), source);
}

bool decodeGltfImage(tinygltf::Image* image, int index, std::string* error, std::string* warning,
                     int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                     void* user) {
  const auto fail = [&](const std::string& what) {
    if (error) *error += "image " + std::to_string(index) + ": " + what + "\n";
    return false;
  };
  // tinygltf hands over &buffer.data[view.byteOffset] and view.byteLength unchecked.
  const auto& model = *static_cast<const tinygltf::Model*>(user);
  if (image->bufferView >= 0) {
    if (static_cast<std::size_t>(image->bufferView) >= model.bufferViews.size())
      return fail("buffer view out of range");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(image->bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
      return fail("buffer out of range");
    if (!byteRangeFits(view.byteOffset, view.byteLength,
                       model.buffers[static_cast<std::size_t>(view.buffer)].data.size()))
      return fail("buffer view " + std::to_string(image->bufferView) +
                  " reaches past the end of its buffer");
  }
  if (size <= 0) return fail("no image bytes");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, size, &width, &height, &channels))
    return fail(std::string("cannot decode (") + stbi_failure_reason() + ")");
  if (!texturePixelsAllowed(width, height))
    return fail("is " + std::to_string(width) + "x" + std::to_string(height) + " pixels (at most " +
                std::to_string(kMaxTexturePixels) + ")");
  return tinygltf::LoadImageData(image, index, error, warning, requiredWidth, requiredHeight,
                                 bytes, size, nullptr);
}

namespace {

bool regularFileExists(const std::string& path, void*) { return isRegularFile(path); }

bool readRegularFile(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                     void*) {
  const bool regular = isRegularFile(path);
  std::error_code ec;
  const auto size = regular ? std::filesystem::file_size(path, ec) : 0;
  if (!regular || ec) {
    if (error) *error += "'" + path + "' is not a readable file\n";
    return false;
  }
  if (size > std::numeric_limits<unsigned>::max()) {
    if (error) *error += "'" + path + "' is larger than 4 GiB\n";
    return false;
  }
  try {
    const std::string bytes = readTextFile(path);
    out->assign(bytes.begin(), bytes.end());
  } catch (const Error& e) {
    if (error) *error += std::string(e.what()) + "\n";
    return false;
  }
  return true;
}

}  // namespace

tinygltf::FsCallbacks gltfFileAccess() {
  return {&regularFileExists, &tinygltf::ExpandFilePath, &readRegularFile,
          &tinygltf::WriteWholeFile, nullptr};
}

}  // namespace confvis::scene_files
