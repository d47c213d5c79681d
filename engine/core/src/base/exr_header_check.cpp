// The EXR header read by confvis before OpenEXR opens the file. OpenEXR allocates what a header
// declares before it can tell the file does not hold it: an attribute's value at its declared
// size (a 5 KB file claiming a 1.6 GB attribute made it allocate 1.6 GB; found by
// tests/fuzz/fuzz_cube_exr), and the chunk offset table at the size of the data window (one
// entry per scanline or per tile). Checked here: every attribute fits in the file and holds the
// bytes OpenEXR will read of it (so this reading stays in step with OpenEXR's), the data
// window is within kMaxExrSide / kMaxExrPixels, and a tiled file has at most kMaxExrTiles tiles.
// Anything else (a bad magic number, a truncated header) is left to OpenEXR's own error.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

#include "confvis/base/error.hpp"
#include "exr_internal.hpp"

namespace confvis::detail {
namespace fs = std::filesystem;

namespace {

constexpr std::int32_t kExrMagic = 20000630;
constexpr std::int32_t kMultiPartFlag = 0x1000;

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw Error(ErrorCode::IoFailure, "EXR file '" + path.string() + "': " + what);
}

std::int32_t littleEndianInt(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  std::int32_t result;
  std::memcpy(&result, &value, sizeof result);
  return result;
}

// A name as OpenEXR 3.1 reads it (Header::readFrom): up to 256 bytes ending at a NUL, which it
// consumes, whatever the long-names flag says. False at the end of the file or without a NUL
// (OpenEXR refuses such a name itself).
bool readName(std::istream& in, std::string& name) {
  name.clear();
  for (int i = 0; i < 256; ++i) {
    char c;
    if (!in.get(c)) return false;
    if (c == '\0') return true;
    name.push_back(c);
  }
  return false;
}

// The pixels of a data window (box2i), refused beyond the readers' limits.
long long checkedWindowPixels(const fs::path& path, const char* value) {
  const long long minX = littleEndianInt(value), minY = littleEndianInt(value + 4);
  const long long maxX = littleEndianInt(value + 8), maxY = littleEndianInt(value + 12);
  const long long width = maxX - minX + 1, height = maxY - minY + 1;
  if (width <= 0 || height <= 0 || width > kMaxExrSide || height > kMaxExrSide ||
      width * height > kMaxExrPixels)
    refuse(path, "its data window claims " + std::to_string(width) + "x" +
                     std::to_string(height) + " pixels (at most " + std::to_string(kMaxExrSide) +
                     " per side and " + std::to_string(kMaxExrPixels) + " in all)");
  return width * height;
}

// The bytes OpenEXR reads of a value of `type`, whatever size the header declares: known types
// are read by their own structure (a box2i is 16 bytes, a channel list runs to its empty
// name), so a declared size that differs would make OpenEXR read the rest of the header out of
// step with this check. -1 when a length inside the value runs past it.
long long bytesOpenExrReads(const std::string& type, const std::string& value) {
  static const std::map<std::string, long long> kFixed = {
      {"box2i", 16},   {"box2f", 16},  {"chromaticities", 32}, {"compression", 1},
      {"double", 8},   {"envmap", 1},  {"float", 4},           {"int", 4},
      {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36},          {"m33d", 72},
      {"m44f", 64},    {"m44d", 128},  {"rational", 8},        {"tiledesc", 9},
      {"timecode", 8}, {"v2i", 8},     {"v2f", 8},             {"v2d", 16},
      {"v3i", 12},     {"v3f", 12},    {"v3d", 24},            {"deepImageState", 1}};
  const long long size = static_cast<long long>(value.size());
  if (const auto fixed = kFixed.find(type); fixed != kFixed.end()) return fixed->second;
  if (type == "chlist") {  // channels: name (NUL-ended, up to 256 bytes), 16 bytes; empty name
    std::size_t at = 0;
    while (at < value.size()) {
      const std::size_t end = value.find('\0', at);
      if (end == std::string::npos || end - at > 255) return -1;
      if (end == at) return static_cast<long long>(end + 1);
      at = end + 1 + 16;
    }
    return -1;
  }
  if (type == "preview") {  // width, height, then 4 bytes per pixel, allocated before reading
    if (size < 8) return -1;
    const long long width = static_cast<std::uint32_t>(littleEndianInt(value.data()));
    const long long height = static_cast<std::uint32_t>(littleEndianInt(value.data() + 4));
    if (width != 0 && height > (size - 8) / 4 / width) return -1;
    return 8 + 4 * width * height;
  }
  if (type == "stringvector") {  // (length, bytes)... within the declared size
    long long at = 0;
    while (at < size) {
      if (size - at < 4) return -1;
      const long long length = littleEndianInt(value.data() + at);
      if (length < 0 || length > size - at - 4) return -1;
      at += 4 + length;
    }
    return at;
  }
  if (type == "floatvector") return size - size % 4;
  return size;  // strings and unknown (opaque) types: the declared size
}

}  // namespace

void requirePlausibleExrHeader(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const auto fileSize = static_cast<long long>(fs::file_size(path, ec));
  char word[8];
  if (!in || ec || !in.read(word, 8) || littleEndianInt(word) != kExrMagic) return;
  const bool multiPart = (littleEndianInt(word + 4) & kMultiPartFlag) != 0;
  long long windowPixels = 0;  // of the current part, for the tile count
  while (true) {  // one header per part
    std::string name, type;
    int attributes = 0;
    while (true) {
      if (!readName(in, name)) return;  // truncated: OpenEXR says so
      if (name.empty()) break;          // the end of this header
      char sizeBytes[4];
      if (!readName(in, type) || !in.read(sizeBytes, 4)) return;
      const long long size = littleEndianInt(sizeBytes);
      const long long left = fileSize - static_cast<long long>(in.tellg());
      if (size < 0 || size > left)
        refuse(path, "header attribute '" + name + "' claims " + std::to_string(size) +
                         " bytes, the file has " + std::to_string(left) + " left");
      ++attributes;
      std::string value(static_cast<std::size_t>(size), '\0');
      if (!in.read(value.data(), size)) return;
      const long long read = bytesOpenExrReads(type, value);
      if (read != size)
        refuse(path, "header attribute '" + name + "' of type '" + type + "' declares " +
                         std::to_string(size) + " bytes but holds " +
                         (read < 0 ? std::string("a length beyond them") : std::to_string(read)));
      if (name == "dataWindow" && type == "box2i") {
        windowPixels = checkedWindowPixels(path, value.data());
      } else if (name == "tiles" && type == "tiledesc") {
        const long long tileX = static_cast<std::uint32_t>(littleEndianInt(value.data()));
        const long long tileY = static_cast<std::uint32_t>(littleEndianInt(value.data() + 4));
        // Level 0's tiles at least (mip and rip levels add at most 3x): bounded whichever
        // attribute comes first, so check against the largest window the readers accept.
        const long long pixels = windowPixels > 0 ? windowPixels : kMaxExrPixels;
        if (tileX == 0 || tileY == 0 || pixels / tileX / tileY > kMaxExrTiles)
          refuse(path, "its tiles of " + std::to_string(tileX) + "x" + std::to_string(tileY) +
                           " pixels would number more than " + std::to_string(kMaxExrTiles));
      }
    }
    if (!multiPart || attributes == 0) return;  // one header, or the empty one ending the list
  }
}

}  // namespace confvis::detail
