// The EXR header read by confvis before OpenEXR opens the file. OpenEXR allocates what a header
// declares before it can tell the file does not hold it: an attribute's value at its declared
// size (a 5 KB file claiming a 1.6 GB attribute made it allocate 1.6 GB; found by
// tests/fuzz/fuzz_cube_exr), and the chunk offset table at the size of the data window (one
// entry per scanline or per tile). Checked here: every attribute fits in the file, the data
// window is within kMaxExrSide / kMaxExrPixels, and a tiled file has at most kMaxExrTiles tiles.
// Anything else (a bad magic number, a truncated header) is left to OpenEXR's own error.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "confvis/base/error.hpp"
#include "exr_internal.hpp"

namespace confvis::detail {
namespace fs = std::filesystem;

namespace {

constexpr std::int32_t kExrMagic = 20000630;
constexpr std::int32_t kMultiPartFlag = 0x1000;
constexpr std::int32_t kLongNamesFlag = 0x400;

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

// A name as OpenEXR reads it (Xdr::read): up to maxLength + 1 bytes, ending early at a NUL,
// which it consumes; a longer name goes on into the next field. False at the end of the file.
bool readName(std::istream& in, int maxLength, std::string& name) {
  name.clear();
  for (int i = 0; i <= maxLength; ++i) {
    char c;
    if (!in.get(c)) return false;
    if (c == '\0') return true;
    name.push_back(c);
  }
  return true;
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

}  // namespace

void requirePlausibleExrHeader(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const auto fileSize = static_cast<long long>(fs::file_size(path, ec));
  char word[8];
  if (!in || ec || !in.read(word, 8) || littleEndianInt(word) != kExrMagic) return;
  const bool multiPart = (littleEndianInt(word + 4) & kMultiPartFlag) != 0;
  const int maxName = (littleEndianInt(word + 4) & kLongNamesFlag) != 0 ? 255 : 31;
  long long windowPixels = 0;  // of the current part, for the tile count
  while (true) {  // one header per part
    std::string name, type;
    int attributes = 0;
    while (true) {
      if (!readName(in, maxName, name)) return;  // truncated: OpenEXR says so
      if (name.empty()) break;          // the end of this header
      char sizeBytes[4];
      if (!readName(in, maxName, type) || !in.read(sizeBytes, 4)) return;
      const long long size = littleEndianInt(sizeBytes);
      const long long left = fileSize - static_cast<long long>(in.tellg());
      if (size < 0 || size > left)
        refuse(path, "header attribute '" + name + "' claims " + std::to_string(size) +
                         " bytes, the file has " + std::to_string(left) + " left");
      ++attributes;
      if (name == "dataWindow" && type == "box2i" && size == 16) {
        char value[16];
        if (!in.read(value, 16)) return;
        windowPixels = checkedWindowPixels(path, value);
      } else if (name == "tiles" && type == "tiledesc" && size == 9) {
        char value[9];
        if (!in.read(value, 9)) return;
        const long long tileX = static_cast<std::uint32_t>(littleEndianInt(value));
        const long long tileY = static_cast<std::uint32_t>(littleEndianInt(value + 4));
        // Level 0's tiles at least (mip and rip levels add at most 3x): bounded whichever
        // attribute comes first, so check against the largest window the readers accept.
        const long long pixels = windowPixels > 0 ? windowPixels : kMaxExrPixels;
        if (tileX == 0 || tileY == 0 || pixels / tileX / tileY > kMaxExrTiles)
          refuse(path, "its tiles of " + std::to_string(tileX) + "x" + std::to_string(tileY) +
                           " pixels would number more than " + std::to_string(kMaxExrTiles));
      } else {
        in.seekg(size, std::ios::cur);
      }
    }
    if (!multiPart || attributes == 0) return;  // one header, or the empty one ending the list
  }
}

}  // namespace confvis::detail
