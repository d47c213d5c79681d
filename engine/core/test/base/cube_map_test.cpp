#include "confvis/base/cube_map.hpp"

#include <ImfChannelList.h>
#include <ImfEnvmap.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"
#include "image_test_util.hpp"

namespace fs = std::filesystem;
using namespace confvis;
using confvis::test::freshTestDir;
using confvis::test::randomDirection;

namespace {

Imath::Box2i cubeWindow(int n) { return Imath::Box2i({0, 0}, {n - 1, 6 * n - 1}); }

Vec3d toVec(const Imath::V3f& v) { return {v.x, v.y, v.z}; }

// A map whose texels store their own (unit) direction in RGB and 1 in alpha.
CubeMap directionMap(int n) {
  CubeMap map(n);
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3d d = normalized(texelDirection(face, x, y, n));
        float* t = map.face(face).at(x, y);
        t[0] = static_cast<float>(d.x), t[1] = static_cast<float>(d.y);
        t[2] = static_cast<float>(d.z), t[3] = 1.0f;
      }
  return map;
}

Vec3d rgb(const float* t) { return {t[0], t[1], t[2]}; }
Vec3d rgb(const std::array<float, 4>& t) { return {t[0], t[1], t[2]}; }

// The Vulkan spec's face selection table, written out literally: {sc, tc, ma} for direction r.
struct SpecCoords {
  int layer;
  double sc, tc, ma;
};
SpecCoords vulkanSpecTable(const Vec3d& r) {
  const double ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
  if (ax >= ay && ax >= az)
    return r.x > 0 ? SpecCoords{0, -r.z, -r.y, r.x} : SpecCoords{1, r.z, -r.y, r.x};
  if (ay >= az) return r.y > 0 ? SpecCoords{2, r.x, r.z, r.y} : SpecCoords{3, r.x, -r.z, r.y};
  return r.z > 0 ? SpecCoords{4, r.x, -r.y, r.z} : SpecCoords{5, -r.x, -r.y, r.z};
}

// Directions that crowd the cube's edges and corners, where conventions and filtering break.
std::vector<Vec3d> edgeAndCornerDirections(std::mt19937& rng) {
  std::uniform_real_distribution<double> small(-0.02, 0.02), any(-1.0, 1.0);
  std::vector<Vec3d> dirs;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        dirs.push_back({double(sx), double(sy), double(sz)});
        for (int k = 0; k < 20; ++k)
          dirs.push_back({sx + small(rng), sy + small(rng), sz + small(rng)});
      }
  for (int k = 0; k < 300; ++k) {  // near the 12 edges: two coordinates of magnitude ~1
    const double a = (k % 2 ? 1 : -1) * (1 + small(rng)), b = (k % 3 ? 1 : -1) * (1 + small(rng));
    const double c = any(rng);
    dirs.push_back(k % 3 == 0 ? Vec3d{a, b, c} : k % 3 == 1 ? Vec3d{c, a, b} : Vec3d{a, c, b});
  }
  return dirs;
}

}  // namespace

TEST(CubeMapConvention, TexelDirectionsFollowImfCubeMap) {
  for (int n : {1, 2, 5, 12}) {
    const Imath::Box2i window = cubeWindow(n);
    for (CubeFace face : kCubeFaces) {
      const auto imfFace = static_cast<Imf::CubeMapFace>(face);
      // Imf describes a face by in-face positions q and where pixelPosition puts them.
      for (int qy = 0; qy < n; ++qy)
        for (int qx = 0; qx < n; ++qx) {
          const Imath::V2f image = Imf::CubeMap::pixelPosition(imfFace, window, Imath::V2f(qx, qy));
          const int x = static_cast<int>(std::lround(image.x));
          const int y = static_cast<int>(std::lround(image.y)) - static_cast<int>(face) * n;
          ASSERT_TRUE(x >= 0 && x < n && y >= 0 && y < n);
          // Same texel, GPU texel centre: in-face position (q + 0.5) (N - 1) / N (header).
          const float scale = n > 1 ? float(n - 1) / float(n) : 0.0f;
          const Imath::V2f centre((qx + 0.5f) * scale, (qy + 0.5f) * scale);
          const Vec3d expected = toVec(Imf::CubeMap::direction(imfFace, window, centre));
          const Vec3d actual = texelDirection(face, x, y, n);
          EXPECT_NEAR(actual.x, expected.x, 1e-6) << toString(face) << " n=" << n;
          EXPECT_NEAR(actual.y, expected.y, 1e-6) << toString(face) << " n=" << n;
          EXPECT_NEAR(actual.z, expected.z, 1e-6) << toString(face) << " n=" << n;
        }
    }
  }
}

TEST(CubeMapConvention, DirectionToTexelFollowsImfAndInvertsTexelDirection) {
  const int n = 8;
  const Imath::Box2i window = cubeWindow(n);
  std::mt19937 rng(7);
  for (int k = 0; k < 2000; ++k) {
    const Vec3d d = randomDirection(rng);
    Imf::CubeMapFace imfFace;
    Imath::V2f inFace;
    Imf::CubeMap::faceAndPixelPosition(Imath::V3f(float(d.x), float(d.y), float(d.z)), window,
                                       imfFace, inFace);
    const Imath::V2f image = Imf::CubeMap::pixelPosition(imfFace, window, inFace);
    CubeFace face;
    double x, y;
    directionToTexel(d, n, face, x, y);
    ASSERT_EQ(static_cast<int>(face), static_cast<int>(imfFace));
    // Both as face coordinates in [-1, 1]: Imf spans pixel centres 0..N-1, confvis 0..N edges.
    EXPECT_NEAR(2 * x / n - 1, 2 * image.x / (n - 1) - 1, 1e-5);
    EXPECT_NEAR(2 * y / n - 1, 2 * (image.y - int(face) * n) / (n - 1) - 1, 1e-5);
  }
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        CubeFace back;
        double bx, by;
        directionToTexel(texelDirection(face, x, y, n), n, back, bx, by);
        EXPECT_EQ(back, face);
        EXPECT_NEAR(bx, x + 0.5, 1e-12);
        EXPECT_NEAR(by, y + 0.5, 1e-12);
      }
  CubeFace face;
  double x, y;
  EXPECT_THROW(directionToTexel({0, 0, 0}, n, face, x, y), Error);
  EXPECT_THROW(directionToTexel({std::nan(""), 1, 0}, n, face, x, y), Error);
}

TEST(CubeMapVulkan, ConvertedTexelsKeepTheirDirectionExactly) {
  for (int n : {1, 2, 3, 8}) {
    for (CubeFace face : kCubeFaces) {
      std::set<std::pair<int, int>> hit;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          int vx, vy;
          exrToVulkanTexel(face, x, y, n, vx, vy);
          ASSERT_TRUE(vx >= 0 && vx < n && vy >= 0 && vy < n);
          hit.insert({vx, vy});
          EXPECT_EQ(vulkanTexelDirection(face, vx, vy, n), texelDirection(face, x, y, n))
              << toString(face) << " (" << x << "," << y << ") n=" << n;
        }
      EXPECT_EQ(hit.size(), std::size_t(n) * n);  // a bijection per face
    }
  }
}

TEST(CubeMapVulkan, MatchesTheSpecTableAndRoundTripsRandomDirections) {
  const int n = 16;
  CubeMap ids(n);  // every texel stores a unique id
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) ids.face(face).at(x, y)[0] = float((int(face) * n + y) * n + x);
  const CubeMap vulkan = toVulkanLayout(ids);
  std::mt19937 rng(11);
  std::vector<Vec3d> dirs = edgeAndCornerDirections(rng);
  for (int k = 0; k < 3000; ++k) dirs.push_back(randomDirection(rng));
  for (const Vec3d& d : dirs) {
    // vulkanDirectionToTexel against the spec's formulas.
    const SpecCoords spec = vulkanSpecTable(d);
    CubeFace face;
    double s, t;
    vulkanDirectionToTexel(d, n, face, s, t);
    ASSERT_EQ(int(face), spec.layer);
    EXPECT_NEAR(s, 0.5 * (spec.sc / std::abs(spec.ma) + 1) * n, 1e-9);
    EXPECT_NEAR(t, 0.5 * (spec.tc / std::abs(spec.ma) + 1) * n, 1e-9);
    // A nearest lookup the GPU way in the converted map finds what the EXR layout stores.
    const float* gpu = vulkan.face(face).at(std::min(int(s), n - 1), std::min(int(t), n - 1));
    EXPECT_EQ(gpu[0], sampleNearest(ids, d)[0]) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(CubeMapSampling, BilinearReturnsTheQueriedDirectionEverywhere) {
  for (int n : {4, 32}) {
    const CubeMap map = directionMap(n);
    // Smallest angle a texel subtends anywhere (at the cube's corners): 2/N * sqrt(2)/3.
    const double texelAngle = 2.0 / n * std::sqrt(2.0) / 3.0;
    std::mt19937 rng(3);
    std::vector<Vec3d> dirs = edgeAndCornerDirections(rng);
    for (int k = 0; k < 5000; ++k) dirs.push_back(randomDirection(rng));
    double worstBilinear = 0, worstNearest = 0;
    for (const Vec3d& d : dirs) {
      const auto b = sampleBilinear(map, d);
      ASSERT_TRUE(std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2]));
      EXPECT_NEAR(b[3], 1.0f, 1e-6f);  // weights sum to one, even across edges and corners
      worstBilinear = std::max(worstBilinear, angleBetween(rgb(b), d));
      worstNearest = std::max(worstNearest, angleBetween(rgb(sampleNearest(map, d)), d));
    }
    // Measured: about a quarter of texelAngle; half catches seams filtered by clamping.
    EXPECT_LT(worstBilinear, 0.5 * texelAngle) << "n=" << n;
    EXPECT_LT(worstNearest, 1.5 / n) << "n=" << n;  // half a texel diagonal at a face centre
  }
  EXPECT_THROW(sampleBilinear(directionMap(4), {0, 0, 0}), Error);
  EXPECT_THROW(sampleBilinear(CubeMap{}, {0, 0, 1}), Error);
}

namespace {

// A smooth function of the unit direction, stored at the texel centres.
double smoothField(const Vec3d& u) { return std::sin(3 * u.x + 1) * std::cos(2 * u.y) + u.z * u.x; }

CubeMap smoothFieldMap(int n) {
  CubeMap map(n);
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float* t = map.face(face).at(x, y);
        t[0] = static_cast<float>(smoothField(normalized(texelDirection(face, x, y, n))));
        t[3] = 1.0f;
      }
  return map;
}

// Worst bilinear error of smoothField, by where the direction falls: a face's inside, within
// one texel of one edge, or within one texel of two edges (a corner).
struct RegionErrors {
  double interior = 0, edge = 0, corner = 0;
};
RegionErrors bilinearErrors(int n) {
  const CubeMap map = smoothFieldMap(n);
  std::mt19937 rng(11);
  std::vector<Vec3d> dirs = edgeAndCornerDirections(rng);
  for (int k = 0; k < 20000; ++k) dirs.push_back(randomDirection(rng));
  RegionErrors worst;
  for (const Vec3d& d : dirs) {
    CubeFace face;
    double x, y;
    directionToTexel(d, n, face, x, y);
    const int near = (std::min(x, n - x) < 1.0) + (std::min(y, n - y) < 1.0);
    const double error = std::abs(sampleBilinear(map, d)[0] - smoothField(normalized(d)));
    double& slot = near == 0 ? worst.interior : near == 1 ? worst.edge : worst.corner;
    slot = std::max(slot, error);
  }
  return worst;
}

}  // namespace

TEST(CubeMapSampling, BilinearIsSecondOrderAcrossEdgesAndCorners) {
  const RegionErrors coarse = bilinearErrors(32), fine = bilinearErrors(64);
  // Seamless: edges and corners are no worse than a face's inside (fetching the nearest
  // neighbour-face texel instead was first order there: 4x the inside's error at n = 64, 8x at
  // n = 128).
  EXPECT_LT(fine.edge, 1.5 * fine.interior);
  EXPECT_LT(fine.corner, 1.5 * fine.interior);
  // Second order: halving the texel divides every error by about four (first order: two).
  EXPECT_GT(coarse.interior / fine.interior, 3.0);
  EXPECT_GT(coarse.edge / fine.edge, 3.0);
  EXPECT_GT(coarse.corner / fine.corner, 3.0);
  std::printf("bilinear error at n=64: interior %.3g, edge %.3g, corner %.3g\n", fine.interior,
              fine.edge, fine.corner);
}

TEST(CubeMapSampling, TexelBeyondAnEdgeOrCornerStandsInFromTheNeighbouringFaces) {
  const int n = 8;
  for (CubeFace face : kCubeFaces)
    for (int y = -1; y <= n; ++y)
      for (int x = -1; x <= n; ++x) {
        const TexelStandIn s = texelAcrossFaceEdge(face, x, y, n);
        ASSERT_GE(s.count, 1);
        double sum = 0;
        Vec3d blended{0, 0, 0};
        for (int k = 0; k < s.count; ++k) {
          const TexelRef& r = s.texels[k].texel;
          const double w = s.texels[k].weight;
          ASSERT_TRUE(r.x >= 0 && r.x < n && r.y >= 0 && r.y < n);
          EXPECT_GT(w, 0);
          sum += w;
          blended = blended + w * normalized(texelDirection(r.face, r.x, r.y, n));
        }
        EXPECT_NEAR(sum, 1.0, 1e-12);
        const bool inside = x >= 0 && x < n && y >= 0 && y < n;
        if (inside) {
          EXPECT_EQ(s.count, 1);
          EXPECT_EQ(s.texels[0].texel.face, face);
          continue;
        }
        for (int k = 0; k < s.count; ++k) EXPECT_NE(s.texels[k].texel.face, face);
        // The blend of the stand-in texels' directions points where the extended face's texel
        // does, to well under a texel (about 0.6 texel for the nearest texel near corners).
        const Vec3d want = normalized(texelDirection(face, x, y, n));
        EXPECT_LT(angleBetween(blended, want), 0.25 * (2.0 / n)) << x << "," << y;
      }
  EXPECT_THROW(texelAcrossFaceEdge(CubeFace::PosX, -2, 0, n), Error);
}

TEST(CubeMapFiles, ExrRoundTripKeepsEnvmapAndData) {
  const fs::path dir = freshTestDir("cube_exr");
  const int n = 8;
  CubeMap map = directionMap(n);
  map.face(CubeFace::NegY).at(3, 5)[3] = 0.0f;  // an uncovered texel
  writeCubeExr(dir / "ray.exr", map);
  const CubeMap back = readCubeExr(dir / "ray.exr");
  ASSERT_EQ(back.faceSize, n);
  for (CubeFace face : kCubeFaces) EXPECT_EQ(back.face(face).pixels, map.face(face).pixels);

  Imf::InputFile file((dir / "ray.exr").c_str());
  ASSERT_TRUE(Imf::hasEnvmap(file.header()));
  EXPECT_EQ(Imf::envmap(file.header()), Imf::ENVMAP_CUBE);
  EXPECT_EQ(file.header().dataWindow(), cubeWindow(n));
  EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::FLOAT);
  // Looking a direction up the OpenEXR way in the stacked file image finds that direction.
  const ImageRGBA stacked = readExr(dir / "ray.exr");
  std::mt19937 rng(5);
  for (int k = 0; k < 500; ++k) {
    const Vec3d d = randomDirection(rng);
    Imf::CubeMapFace face;
    Imath::V2f inFace;
    Imf::CubeMap::faceAndPixelPosition(Imath::V3f(float(d.x), float(d.y), float(d.z)),
                                       cubeWindow(n), face, inFace);
    const Imath::V2f p = Imf::CubeMap::pixelPosition(face, cubeWindow(n), inFace);
    const float* t = stacked.at(int(std::lround(p.x)), int(std::lround(p.y)));
    if (t[3] == 0.0f) continue;
    // Imf's pixel centres differ from confvis's by up to half a texel, plus rounding: a texel.
    EXPECT_LT(angleBetween(rgb(t), d), 2.0 / n);
  }
  fs::remove_all(dir);
}

TEST(CubeMapFiles, RefusesNonCubeFilesAndBadMaps) {
  const fs::path dir = freshTestDir("cube_bad");
  writeExr(dir / "plain.exr", ImageRGBA(4, 24, 0.5f));
  try {
    readCubeExr(dir / "plain.exr");
    ADD_FAILURE() << "a plain EXR was read as a cube map";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("plain.exr"), std::string::npos) << e.what();
  }
  {  // envmap = cube, but 4 x 20 instead of N x 6N.
    Imf::Header header(4, 20);
    Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
    std::vector<float> zeros(4 * 20, 0.0f);
    Imf::FrameBuffer fb;
    for (const char* name : {"R", "G", "B"}) {
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      fb.insert(name, Imf::Slice::Make(Imf::FLOAT, zeros.data(), header.dataWindow()));
    }
    Imf::OutputFile out((dir / "short.exr").c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(20);
  }
  EXPECT_THROW(readCubeExr(dir / "short.exr"), Error);
  EXPECT_THROW(readCubeExr(dir / "missing.exr"), Error);
  CubeMap map = directionMap(4);
  map.face(CubeFace::PosZ).at(1, 1)[0] = std::nanf("");
  EXPECT_THROW(writeCubeExr(dir / "nan.exr", map), Error);
  map.face(CubeFace::PosZ) = ImageRGBA(3, 4);
  EXPECT_THROW(writeCubeExr(dir / "bad.exr", map), Error);
  EXPECT_FALSE(fs::exists(dir / "nan.exr"));
  EXPECT_FALSE(fs::exists(dir / "bad.exr"));
  fs::remove_all(dir);
}

TEST(CubeMapFiles, CrossPreviewIsContinuousAndSeenFromInside) {
  const int n = 16;
  const ImageRGBA cross = cubeCrossImage(directionMap(n));
  ASSERT_EQ(cross.width, 4 * n);
  ASSERT_EQ(cross.height, 3 * n);
  // Every pair of neighbouring covered pixels, seams included, is about one texel apart.
  for (int y = 0; y < cross.height; ++y)
    for (int x = 0; x < cross.width; ++x) {
      if (cross.at(x, y)[3] == 0.0f) continue;
      if (x + 1 < cross.width && cross.at(x + 1, y)[3] != 0.0f) {
        EXPECT_LT(angleBetween(rgb(cross.at(x, y)), rgb(cross.at(x + 1, y))), 2.5 / n)
            << x << "," << y;
      }
      if (y + 1 < cross.height && cross.at(x, y + 1)[3] != 0.0f) {
        EXPECT_LT(angleBetween(rgb(cross.at(x, y)), rgb(cross.at(x, y + 1))), 2.5 / n)
            << x << "," << y;
      }
    }
  // The front wall (-Z) sits in the middle of the second column: right is +x, up is +y.
  const Vec3d centre = rgb(cross.at(n + n / 2, n + n / 2));
  EXPECT_LT(angleBetween(centre, {0, 0, -1}), 1.5 / n);  // pixel n/2 is half a texel off-centre
  EXPECT_GT(cross.at(n + n / 2 + 1, n + n / 2)[0], centre.x);
  EXPECT_GT(cross.at(n + n / 2, n + n / 2 - 1)[1], centre.y);
  EXPECT_LT(angleBetween(rgb(cross.at(n + n / 2, n / 2)), {0, 1, 0}), 1.5 / n);          // ceiling
  EXPECT_LT(angleBetween(rgb(cross.at(n / 2, n + n / 2)), {-1, 0, 0}), 1.5 / n);         // left
  EXPECT_LT(angleBetween(rgb(cross.at(3 * n + n / 2, n + n / 2)), {0, 0, 1}), 1.5 / n);  // back
  EXPECT_EQ(cross.at(0, 0)[3], 0.0f);
  const fs::path dir = freshTestDir("cube_cross");
  writeCubeCrossPng(dir / "cross.png", directionMap(n));
  EXPECT_TRUE(fs::exists(dir / "cross.png"));
  fs::remove_all(dir);
}
