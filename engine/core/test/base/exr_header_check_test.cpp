// EXR headers are checked before OpenEXR opens the file, which allocates what the header declares
// before it can tell the file does not hold it (inputs found by tests/fuzz/fuzz_cube_exr).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"

using namespace confvis;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / ("confvis_exr_header_" + std::to_string(getpid()) + name);
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string int32(std::int32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[i] = static_cast<char>((static_cast<std::uint32_t>(v) >> (8 * i)) & 0xff);
  return s;
}

// The message of the Error reading `file` throws, and that it came within a second.
std::string refusal(const fs::path& file) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  try {
    (void)readCubeExr(file);
    ADD_FAILURE() << "read";
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
  return message;
}

TEST(ExrHeaderCheck, AnAttributeLargerThanTheFileIsRefusedBeforeOpenExrAllocatesIt) {
  const fs::path file = scratch("attribute.exr");
  writeCubeExr(file, CubeMap(8));
  std::string bytes = readBytes(file);
  const std::string attribute("displayWindow\0box2i\0", 20);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + attribute.size(), 4, int32(1634231040));  // the fuzzer's 1.6 GB
  writeBytes(file, bytes);
  const std::string message = refusal(file);
  EXPECT_NE(message.find("header attribute 'displayWindow' claims 1634231040 bytes"),
            std::string::npos)
      << message;
  fs::remove(file);
}

TEST(ExrHeaderCheck, ADataWindowBeyondTheLimitsIsRefusedBeforeTheOffsetTable) {
  const fs::path file = scratch("window.exr");
  writeCubeExr(file, CubeMap(8));
  std::string bytes = readBytes(file);
  const std::string attribute("dataWindow\0box2i\0", 17);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  // 2^31 scanlines: OpenEXR's offset table alone would be gigabytes.
  bytes.replace(at + attribute.size() + 4, 16, int32(0) + int32(-1073741824) + int32(7) +
                                                   int32(1073741823));
  writeBytes(file, bytes);
  const std::string message = refusal(file);
  EXPECT_NE(message.find("data window claims 8x2147483648 pixels"), std::string::npos) << message;
  fs::remove(file);
}

// A hand-written tiled header: 1x1 tiles over a 65536 x 4096 window would be 2^28 tiles (2 GB
// of offsets); 64 x 64 tiles over the same window pass the check (and then fail in OpenEXR on
// the truncated file, still an Error naming it).
TEST(ExrHeaderCheck, TinyTilesOverALargeWindowAreRefused) {
  const auto header = [](std::int32_t tile) {
    return int32(20000630) + int32(2 | 0x200) + std::string("dataWindow\0box2i\0", 17) +
           int32(16) + int32(0) + int32(0) + int32(65535) + int32(4095) +
           std::string("tiles\0tiledesc\0", 15) + int32(9) + int32(tile) + int32(tile) +
           std::string(1, '\0') + std::string(1, '\0') + std::string(64, '\0');
  };
  const fs::path file = scratch("tiles.exr");
  writeBytes(file, header(1));
  EXPECT_NE(refusal(file).find("tiles of 1x1 pixels would number more than"), std::string::npos);
  writeBytes(file, header(64));
  EXPECT_EQ(refusal(file).find("tiles of"), std::string::npos);
  fs::remove(file);
}

// OpenEXR reads names of up to 255 bytes even without the long-names flag: a 35-byte name is
// one name, and the size after its type is the one OpenEXR allocates (the fuzzer's fourth
// input; read as 32 bytes, the rest would have been taken for the type).
TEST(ExrHeaderCheck, ANameLongerThan31BytesIsReadAsOpenExrReadsIt) {
  const fs::path file = scratch("long-name.exr");
  const std::string name = std::string(32, 'x') + "abc";
  writeBytes(file, int32(20000630) + int32(2) + name + std::string(1, '\0') +
                       std::string("opaque\0", 7) + int32(1600000000) + std::string(64, '\0'));
  const std::string message = refusal(file);
  EXPECT_NE(message.find("header attribute '" + name + "' claims 1600000000 bytes"),
            std::string::npos)
      << message;
  fs::remove(file);
}

// OpenEXR reads a channel list to its end whatever size the header declares: a smaller
// declared size would put this check out of step with OpenEXR (the fuzzer's third input).
TEST(ExrHeaderCheck, AKnownTypeWhoseDeclaredSizeDiffersIsRefused) {
  const fs::path file = scratch("chlist.exr");
  writeCubeExr(file, CubeMap(8));
  std::string bytes = readBytes(file);
  const std::string attribute("channels\0chlist\0", 16);
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + attribute.size(), 4, int32(37));  // A and B only: 2 x 18 bytes + 1
  writeBytes(file, bytes);
  const std::string message = refusal(file);
  EXPECT_NE(message.find("header attribute 'channels' of type 'chlist' declares 37 bytes"),
            std::string::npos)
      << message;
  fs::remove(file);
}

TEST(ExrHeaderCheck, ValidCubeMapsAndImagesStillRead) {
  const fs::path file = scratch("valid.exr");
  writeCubeExr(file, CubeMap(8));
  EXPECT_EQ(readCubeExr(file).faceSize, 8);
  writeExr(file, ImageRGBA(5, 3, 0.5f));
  EXPECT_EQ(readExr(file).height, 3);
  fs::remove(file);
}

}  // namespace
