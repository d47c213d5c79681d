#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>
#include <ImfMultiView.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/png_io.hpp"
#include "image_test_util.hpp"

namespace fs = std::filesystem;
using namespace confvis;
using confvis::test::countEntries;
using confvis::test::freshTestDir;

namespace {

// Distinct values in every channel, including ones that stress exactness (tiny, huge, -0).
ImageRGBA patternImage(int w, int h, float scale = 1.0f) {
  ImageRGBA image(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = scale * (std::sin(0.37f * static_cast<float>(i)) * 3.0f + 0.001f * i);
  image.pixels[0] = -0.0f;
  image.pixels[1] = 1e-30f;
  image.pixels[2] = -3.5e20f * scale;
  image.pixels[3] = std::numeric_limits<float>::denorm_min();
  return image;
}

void expectErrorNaming(const std::function<void()>& f, ErrorCode code, const fs::path& path) {
  try {
    f();
    FAIL() << "expected an Error naming " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

void truncateFile(const fs::path& path) { fs::resize_file(path, fs::file_size(path) / 2); }

}  // namespace

TEST(ImageRGBA, AtAddressesInterleavedRowsFromTheTop) {
  ImageRGBA image(3, 2);
  image.at(2, 1)[3] = 7.0f;
  EXPECT_EQ(image.pixels[(1 * 3 + 2) * 4 + 3], 7.0f);
  EXPECT_TRUE(image.allFinite());
  image.at(0, 0)[1] = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(image.allFinite());
}

TEST(ExrIo, FloatRoundTripIsBitExact) {
  const fs::path dir = freshTestDir("exr_float");
  const ImageRGBA image = patternImage(37, 11);
  writeExr(dir / "a.exr", image);
  const ImageRGBA back = readExr(dir / "a.exr");
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 11);
  EXPECT_EQ(std::memcmp(back.pixels.data(), image.pixels.data(), image.pixels.size() * 4), 0);
  Imf::InputFile file((dir / "a.exr").c_str());
  EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
  EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::FLOAT);
  EXPECT_EQ(countEntries(dir), 1);  // no temporary left behind
  fs::remove_all(dir);
}

TEST(ExrIo, HalfRoundTripIsWithinHalfPrecision) {
  const fs::path dir = freshTestDir("exr_half");
  ImageRGBA inRange = patternImage(16, 9);
  inRange.pixels[2] = -60000.0f;  // near the end of half's range
  writeExr(dir / "h.exr", inRange, ExrPixel::Half);
  const ImageRGBA back = readExr(dir / "h.exr");
  ASSERT_EQ(back.pixels.size(), inRange.pixels.size());
  for (std::size_t i = 0; i < back.pixels.size(); ++i) {
    const float v = inRange.pixels[i];
    // Half has an 11-bit significand; below 2^-14 it is subnormal with spacing 2^-24.
    EXPECT_NEAR(back.pixels[i], v, std::abs(v) * std::ldexp(1.0f, -11) + std::ldexp(1.0f, -25))
        << "index " << i;
  }
  Imf::InputFile file((dir / "h.exr").c_str());
  EXPECT_EQ(file.header().channels().findChannel("A")->type, Imf::HALF);
  // Values beyond half's range would silently become infinity.
  expectErrorNaming([&] { writeExr(dir / "big.exr", patternImage(4, 4), ExrPixel::Half); },
                    ErrorCode::InvalidInput, dir / "big.exr");
  EXPECT_FALSE(fs::exists(dir / "big.exr"));
  fs::remove_all(dir);
}

TEST(ExrIo, NonFiniteImagesAreRefusedAndLeaveNoFile) {
  const fs::path dir = freshTestDir("exr_nan");
  ImageRGBA image = patternImage(5, 5);
  image.at(3, 4)[2] = std::numeric_limits<float>::quiet_NaN();
  expectErrorNaming([&] { writeExr(dir / "nan.exr", image); }, ErrorCode::InvalidInput,
                    dir / "nan.exr");
  expectErrorNaming([&] { writeStereoExr(dir / "s.exr", patternImage(5, 5), image); },
                    ErrorCode::InvalidInput, dir / "s.exr");
  expectErrorNaming([&] { writePng(dir / "nan.png", image); }, ErrorCode::InvalidInput,
                    dir / "nan.png");
  EXPECT_EQ(countEntries(dir), 0);
  fs::remove_all(dir);
}

TEST(ExrIo, MissingAndCorruptFilesThrowNamingTheFile) {
  const fs::path dir = freshTestDir("exr_bad");
  expectErrorNaming([&] { readExr(dir / "missing.exr"); }, ErrorCode::FileNotFound,
                    dir / "missing.exr");
  writeExr(dir / "cut.exr", patternImage(64, 64));
  truncateFile(dir / "cut.exr");
  expectErrorNaming([&] { readExr(dir / "cut.exr"); }, ErrorCode::IoFailure, dir / "cut.exr");
  writeTextAtomically(dir / "junk.exr", "this is not an OpenEXR file at all, just text");
  expectErrorNaming([&] { readExr(dir / "junk.exr"); }, ErrorCode::IoFailure, dir / "junk.exr");
  expectErrorNaming([&] { readStereoExr(dir / "junk.exr"); }, ErrorCode::IoFailure,
                    dir / "junk.exr");
  fs::remove_all(dir);
}

TEST(ExrIo, ReadsOffsetDataWindowWithoutAlphaAsOpaque) {
  const fs::path dir = freshTestDir("exr_window");
  const fs::path path = dir / "rgb.exr";
  {  // Written with OpenEXR directly: data window at (10, 20), channels R, G, B only.
    const Imath::Box2i window({10, 20}, {13, 22});
    Imf::Header header(window, window);
    std::vector<float> rgb(4 * 3 * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<float>(i);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 3; ++c) {
      const char* name = c == 0 ? "R" : c == 1 ? "G" : "B";
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      fb.insert(name, Imf::Slice::Make(Imf::FLOAT, rgb.data() + c, window, 12, 48));
    }
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(3);
  }
  const ImageRGBA image = readExr(path);
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 3);
  EXPECT_EQ(image.at(3, 2)[0], 33.0f);  // pixel 11 of 12, R
  EXPECT_EQ(image.at(3, 2)[2], 35.0f);
  EXPECT_EQ(image.at(1, 0)[3], 1.0f);
  fs::remove_all(dir);
}

TEST(ExrStereo, RoundTripKeepsEyesApartAndWritesMultiView) {
  const fs::path dir = freshTestDir("exr_stereo");
  const ImageRGBA left = patternImage(8, 6, 1.0f), right = patternImage(8, 6, -2.0f);
  writeStereoExr(dir / "s.exr", left, right);
  const auto [l, r] = readStereoExr(dir / "s.exr");
  EXPECT_EQ(l.pixels, left.pixels);
  EXPECT_EQ(r.pixels, right.pixels);
  Imf::InputFile file((dir / "s.exr").c_str());
  ASSERT_TRUE(Imf::hasMultiView(file.header()));
  EXPECT_EQ(Imf::multiView(file.header()), (Imf::StringVector{"left", "right"}));
  std::vector<std::string> names;
  for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c)
    names.push_back(c.name());
  EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R", "right.A", "right.B", "right.G",
                                             "right.R"}));
  // Readers unaware of multi-view see the default view: the left eye.
  EXPECT_EQ(readExr(dir / "s.exr").pixels, left.pixels);
  // A plain image is not a stereo pair; mismatched eyes are refused.
  writeExr(dir / "mono.exr", left);
  expectErrorNaming([&] { readStereoExr(dir / "mono.exr"); }, ErrorCode::IoFailure,
                    dir / "mono.exr");
  expectErrorNaming([&] { writeStereoExr(dir / "m.exr", left, patternImage(8, 5)); },
                    ErrorCode::InvalidInput, dir / "m.exr");
  fs::remove_all(dir);
}

TEST(PngIo, RawRampRoundTripsEveryCode) {
  const fs::path dir = freshTestDir("png_ramp");
  ImageRGBA ramp(256, 2);
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 2; ++y) {
      float* p = ramp.at(x, y);
      p[0] = x / 255.0f;
      p[1] = (255 - x) / 255.0f;
      p[2] = y == 0 ? 0.0f : 1.0f;
      p[3] = ((x * 7) % 256) / 255.0f;
    }
  writePng(dir / "raw.png", ramp, {.exposure = 1.0f, .srgb = false, .alpha = true});
  const ImageRGBA back = readPng(dir / "raw.png", PngDecoding::Raw);
  ASSERT_EQ(back.width, 256);
  ASSERT_EQ(back.height, 2);
  for (std::size_t i = 0; i < ramp.pixels.size(); ++i)
    EXPECT_EQ(std::lround(back.pixels[i] * 255.0f), std::lround(ramp.pixels[i] * 255.0f)) << i;
  fs::remove_all(dir);
}

TEST(PngIo, SrgbEncodingRoundTripsLinearValues) {
  const fs::path dir = freshTestDir("png_srgb");
  ImageRGBA linear(256, 1);
  for (int x = 0; x < 256; ++x) {
    float* p = linear.at(x, 0);
    p[0] = p[1] = p[2] = srgbToLinear(x / 255.0f);
    p[3] = 0.25f;  // dropped: the default preview is RGB
  }
  writePng(dir / "s.png", linear);
  const ImageRGBA codes = readPng(dir / "s.png", PngDecoding::Raw);
  const ImageRGBA decoded = readPng(dir / "s.png");
  for (int x = 0; x < 256; ++x) {
    EXPECT_EQ(std::lround(codes.at(x, 0)[1] * 255.0f), x);
    EXPECT_NEAR(decoded.at(x, 0)[2], linear.at(x, 0)[2], 1e-6f);
    EXPECT_EQ(decoded.at(x, 0)[3], 1.0f);
  }
  // Mid-grey 0.214 (linear) encodes near code 128; exposure scales before encoding and clamps.
  EXPECT_NEAR(linearToSrgb(0.2140f), 0.5f, 1e-3f);
  ImageRGBA bright(1, 1, 0.6f);
  writePng(dir / "e.png", bright, {.exposure = 4.0f, .srgb = true, .alpha = false});
  EXPECT_EQ(readPng(dir / "e.png", PngDecoding::Raw).at(0, 0)[0], 1.0f);
  fs::remove_all(dir);
}

TEST(PngIo, MissingAndCorruptFilesThrowNamingTheFile) {
  const fs::path dir = freshTestDir("png_bad");
  expectErrorNaming([&] { readPng(dir / "missing.png"); }, ErrorCode::FileNotFound,
                    dir / "missing.png");
  writePng(dir / "cut.png", patternImage(64, 64, 0.1f));
  truncateFile(dir / "cut.png");
  expectErrorNaming([&] { readPng(dir / "cut.png"); }, ErrorCode::IoFailure, dir / "cut.png");
  writeTextAtomically(dir / "junk.png", "not a png");
  expectErrorNaming([&] { readPng(dir / "junk.png"); }, ErrorCode::IoFailure, dir / "junk.png");
  fs::remove_all(dir);
}
