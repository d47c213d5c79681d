// The shared guards of hostile input (input_limits.hpp, json_text.hpp, text_encoding.hpp,
// checksum.hpp), each against its own minimal input.
#include "confvis/base/input_limits.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/json_text.hpp"
#include "confvis/base/text_encoding.hpp"

using namespace confvis;
namespace fs = std::filesystem;

namespace {

std::string errorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FileNameSafety, PlainNamesPass) {
  for (const char* name : {"front", "top-left", "wall 2", "cave5-bake", "Ω-wall", ".hidden"})
    EXPECT_NO_THROW(requireFileNameSafe(name, "wall name")) << name;
  EXPECT_EQ(childPath("out", "front", "wall name"), fs::path("out") / "front");
}

TEST(FileNameSafety, NamesThatLeaveTheDirectoryAreRefusedNamingTheField) {
  const std::string escape = errorOf([] { requireFileNameSafe("../../escape", "cave.json: wall name"); });
  EXPECT_NE(escape.find("cave.json: wall name '../../escape'"), std::string::npos) << escape;
  EXPECT_NE(escape.find("path separator"), std::string::npos) << escape;
  EXPECT_NE(errorOf([] { requireFileNameSafe("/abs/x", "display name"); }).find("display name '/abs/x'"),
            std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe("a\\b", "f"); }).find("path separator"), std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe("..", "f"); }).find("directory"), std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe(".", "f"); }).find("directory"), std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe("", "f"); }).find("empty"), std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe(std::string(201, 'a'), "f"); }).find("201 bytes"),
            std::string::npos);
  EXPECT_THROW(childPath("out", "../x", "f"), Error);
}

TEST(FileNameSafety, NulAndControlCharactersAreRefusedAndShownEscaped) {
  const std::string nul = errorOf([] { requireFileNameSafe(std::string("screen\0.exr", 11), "wall name"); });
  EXPECT_NE(nul.find("NUL"), std::string::npos) << nul;
  EXPECT_NE(nul.find("screen\\x00.exr"), std::string::npos) << nul;  // not cut at the NUL
  EXPECT_NE(errorOf([] { requireFileNameSafe("a\nb", "f"); }).find("control character"), std::string::npos);
  EXPECT_NE(errorOf([] { requireFileNameSafe("a\x7f", "f"); }).find("control character"), std::string::npos);
}

// Found by fuzz_sgct_xml / fuzz_pvx: a name from XML with invalid UTF-8 made the config hash's
// JSON dump throw an uncaught type_error (std::terminate in the harness, exit 3 in the CLI).
TEST(FileNameSafety, InvalidUtf8IsRefused) {
  for (const char* bad : {"wall\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80"})
    EXPECT_NE(errorOf([&] { requireFileNameSafe(bad, "wall name"); }).find("not valid UTF-8"),
              std::string::npos)
        << bad;
  for (const char* good : {"caf\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80"})
    EXPECT_NO_THROW(requireFileNameSafe(good, "wall name")) << good;
}

TEST(JsonDepth, HundredThousandNestedBracketsAreRefusedWithoutRecursion) {
  const std::string deep = "{\"a\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const auto start = std::chrono::steady_clock::now();
  const std::string message = errorOf([&] { parseJsonText(deep, "deep.json"); });
  EXPECT_NE(message.find("deep.json: JSON nested deeper than 64"), std::string::npos) << message;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

TEST(JsonDepth, LimitIsExactAndStringsDoNotCount) {
  const auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  EXPECT_NO_THROW(requireJsonDepth(nested(kMaxJsonDepth), "x"));
  EXPECT_THROW(requireJsonDepth(nested(kMaxJsonDepth + 1), "x"), Error);
  EXPECT_NO_THROW(requireJsonDepth("[\"" + std::string(1000, '[') + "\\\"[\"]", "x"));
  EXPECT_EQ(parseJsonText("{\"a\": [1, {\"b\": 2}]}", "x")["a"][1]["b"], 2);
  EXPECT_NE(errorOf([] { parseJsonText("{\"a\": ", "cut.json"); }).find("cut.json: invalid JSON"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseJsonText("[1e999]", "big.json"); }).find("big.json"), std::string::npos);
}

TEST(ByteRanges, SumsNearTwoToTheSixtyFourDoNotWrap) {
  constexpr std::size_t kMax = static_cast<std::size_t>(-1);
  EXPECT_TRUE(byteRangeFits(0, 36, 36));
  EXPECT_TRUE(byteRangeFits(36, 0, 36));
  EXPECT_FALSE(byteRangeFits(1, 36, 36));
  EXPECT_FALSE(byteRangeFits(kMax - 15, 36, 36));  // offset + length wraps to 20 < 36
  EXPECT_FALSE(byteRangeFits(37, 0, 36));
  std::size_t bytes = 0;
  EXPECT_TRUE(stridedSpan(3, 12, 12, bytes));
  EXPECT_EQ(bytes, 36u);
  EXPECT_TRUE(stridedSpan(0, 12, 12, bytes));
  EXPECT_EQ(bytes, 0u);
  EXPECT_FALSE(stridedSpan(kMax / 4, 16, 12, bytes));  // count * stride overflows
}

TEST(TextEncoding, Utf16AndBomsAndCrLfBecomeUtf8Lines) {
  const std::string utf16le("\xFF\xFEv\0 \0" "1\0\r\0\n\0", 12);
  EXPECT_EQ(decodeTextFile(utf16le, "a.obj"), "v 1\n");
  const std::string utf16be("\xFE\xFF\0v\0 \0" "1\0\n", 10);
  EXPECT_EQ(decodeTextFile(utf16be, "a.obj"), "v 1\n");
  const std::string noBom("v\0 \0" "1\0 \0" "2\0 \0" "3\0\n\0", 16);
  EXPECT_EQ(decodeTextFile(noBom, "a.obj"), "v 1 2 3\n");
  EXPECT_EQ(decodeTextFile(std::string("\xC3\xA9\0", 2), "a.obj"), "\xC3\xA9");  // UTF-8 é
  EXPECT_EQ(decodeTextFile("\xEF\xBB\xBFx\r\ny\rz", "a.obj"), "x\ny\nz");
  EXPECT_EQ(decodeTextFile(std::string("\xFF\xFE\xE9\0", 4), "a.obj"), "\xC3\xA9");
  EXPECT_NE(errorOf([] { decodeTextFile(std::string("\xFF\xFE\x00\xD8x\0", 6), "bad.obj"); })
                .find("bad.obj"),
            std::string::npos);
  EXPECT_NE(errorOf([] { decodeTextFile(std::string("abc\0def\0ghi", 11), "bin.obj"); }).find("NUL"),
            std::string::npos);
}

TEST(Checksum, FileChecksumIsFnv1aOfTheBytesAndSeesOneBit) {
  EXPECT_EQ(fnv1a64Hex(""), "cbf29ce484222325");  // the FNV-1a 64 offset basis
  EXPECT_EQ(fnv1a64Hex("a"), "af63dc4c8601ec8c");  // published test vector
  const fs::path file = fs::temp_directory_path() / ("confvis_checksum_" + std::to_string(getpid()));
  std::string bytes(200000, 'x');
  writeTextAtomically(file, bytes);
  EXPECT_EQ(fileChecksum(file), fnv1a64Hex(bytes));  // across 64 KiB blocks
  bytes[123456] ^= 1;
  writeTextAtomically(file, bytes);
  EXPECT_EQ(fileChecksum(file), fnv1a64Hex(bytes));
  EXPECT_NE(fileChecksum(file), fnv1a64Hex(std::string(200000, 'x')));
  fs::remove(file);
  EXPECT_THROW(fileChecksum(file), Error);
}

// A 35 KB EXR whose header claims an 8192 x 49152 data window (a cube of 8192 per face, 6 GiB as
// floats): refused before anything of that size is allocated, naming the file.
TEST(ExrLimits, SmallFileClaimingAHugeWindowIsRefusedQuickly) {
  const fs::path file = fs::temp_directory_path() / ("confvis_exr_window_" + std::to_string(getpid()) + ".exr");
  writeCubeExr(file, CubeMap(8));
  std::string bytes = readTextFile(file);
  const std::size_t window = bytes.find(std::string("dataWindow\0box2i\0", 17));
  ASSERT_NE(window, std::string::npos);
  const std::int32_t box[4] = {0, 0, 8191, 49151};
  std::memcpy(bytes.data() + window + 17 + 4, box, sizeof box);  // after the attribute's size
  bytes += std::string(30000, '\0');  // room for the line offset table OpenEXR reads first
  writeTextAtomically(file, bytes);
  const auto start = std::chrono::steady_clock::now();
  try {
    (void)readCubeExr(file);
    ADD_FAILURE() << "read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("claims 8192x49152 pixels in"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  fs::remove(file);
}
