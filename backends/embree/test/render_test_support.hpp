#pragma once
// Shared helpers of the renderer tests: shipped configs, small renders, image comparison with a
// per-pixel tolerance and a bad-pixel budget, and simple analytic scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::test {

inline DisplayConfig shippedConfig(const std::string& name) {
  return loadDisplayConfig(std::string(CONFVIS_SOURCE_DIR) + "/configs/" + name + ".json");
}

// Scale that turns the shipped 1920-pixel CAVE walls into `pixels`-pixel test images.
inline double scaleFor(int pixels) { return pixels / 1920.0; }

// The analytic dilation map without a ceiling (analytic_maps.hpp; factor 1.5, 256 texels), made
// once: the moving-head, tail-grid and tail-lattice tests' map with a known exact curve.
inline const RetargetMap& dilationMap() {
  static const RetargetMap map = ceilinglessDilationMap(1.5, 256);
  return map;
}

// Conformal exact stereo rays of one eye on one wall, `pixels` wide, the head at `head`: the
// frames whose tails the lattice and tail-grid tests take apart.
inline RenderSettings exactStereoWallSettings(const std::string& wall, Eye eye, int pixels,
                                              const glm::dvec3& head) {
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = {eye};
  settings.stereoRays = StereoRays::Exact;
  settings.walls = {wall};
  settings.resolutionScale = scaleFor(pixels);
  settings.head.position = head;
  return settings;
}

struct ImageDiff {
  std::size_t badPixels = 0;
  double maxDifference = 0.0;   // largest channel difference (RGBA)
  double meanDifference = 0.0;  // mean over pixels of the largest channel difference
  double badFraction(const ImageRGBA& image) const {
    return static_cast<double>(badPixels) / static_cast<double>(image.pixelCount());
  }
};

inline ImageDiff compareImages(const ImageRGBA& a, const ImageRGBA& b, double tolerance) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  ImageDiff diff;
  if (a.width != b.width || a.height != b.height) {
    diff.badPixels = std::max(a.pixelCount(), b.pixelCount());
    diff.maxDifference = 1e30;
    return diff;
  }
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    double worst = 0.0;
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, static_cast<double>(std::abs(a.pixels[4 * i + c] - b.pixels[4 * i + c])));
    diff.maxDifference = std::max(diff.maxDifference, worst);
    diff.meanDifference += worst;
    if (worst > tolerance) ++diff.badPixels;
  }
  diff.meanDifference /= static_cast<double>(a.pixelCount());
  return diff;
}

// Same pixels within `tolerance` except at most `budget` (fraction) of them: anti-aliasing-free
// renders of the same rays differ only where a ray grazes an edge.
inline ::testing::AssertionResult imagesMatch(const ImageRGBA& a, const ImageRGBA& b,
                                              double tolerance = 0.02, double budget = 0.01) {
  const ImageDiff diff = compareImages(a, b, tolerance);
  if (diff.badFraction(a) <= budget) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << diff.badPixels << " of " << a.pixelCount() << " pixels differ by more than "
         << tolerance << " (max " << diff.maxDifference << ", mean " << diff.meanDifference
         << ")";
}

inline const WallImage& imageOf(const RenderResult& result, const std::string& wall, Eye eye) {
  for (const WallImage& image : result.images)
    if (image.wall == wall && image.eye == eye) return image;
  throw std::runtime_error("no image of wall " + wall);
}

// A flat square of side `size` centred at `centre`, facing `towards`, in one colour.
inline Mesh facingSquare(const glm::dvec3& centre, const glm::dvec3& towards, double size) {
  const glm::dvec3 n = glm::normalize(towards - centre);
  const glm::dvec3 helper = std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n)), v = glm::cross(n, u);
  Mesh mesh;
  mesh.name = "square";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      mesh.positions.emplace_back(centre + (i - 0.5) * size * u + (j - 0.5) * size * v);
  mesh.triangles = {{0, 1, 3}, {0, 3, 2}};
  mesh.normals.assign(4, glm::vec3(n));
  return mesh;
}

inline Scene squareScene(const glm::dvec3& centre, double size, glm::vec3 colour) {
  Scene scene;
  scene.name = "square";
  scene.materials.push_back({"paint", glm::vec4(colour, 1.0f), -1});
  scene.meshes.push_back(facingSquare(centre, glm::dvec3(0.0), size));
  scene.meshes.back().material = 0;
  return scene;
}

// Centroid (pixel units, centres at +0.5) of the pixels with alpha above one half.
inline glm::dvec2 coverageCentroid(const ImageRGBA& image, std::size_t* count = nullptr) {
  glm::dvec2 sum(0.0);
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[3] > 0.5f) {
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++n;
      }
  if (count) *count = n;
  return n ? sum / static_cast<double>(n) : glm::dvec2(-1.0);
}

// The point where a polyline (then its straight tail from the last vertex) first reaches
// distance rho from the origin, leaving the ball (the first vertex inside it).
inline glm::dvec3 curveAtDistance(const std::vector<glm::dvec3>& vertices, const glm::dvec3& tail,
                                  double rho) {
  const auto crossing = [&](const glm::dvec3& from, const glm::dvec3& unit, double maxT) {
    // |from + t unit| = rho, the larger root (leaving the sphere).
    const double b = glm::dot(from, unit), c = glm::dot(from, from) - rho * rho;
    const double t = -b + std::sqrt(std::max(0.0, b * b - c));
    return t <= maxT ? std::optional<glm::dvec3>(from + t * unit) : std::nullopt;
  };
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
    if (glm::length(vertices[i + 1]) < rho) continue;
    const glm::dvec3 step = vertices[i + 1] - vertices[i];
    if (const auto p = crossing(vertices[i], step / glm::length(step), glm::length(step))) return *p;
  }
  return *crossing(vertices.back(), tail, 1e30);
}

// One backend holding the checker-sphere, shared by the tests (the BVH is built once).
inline EmbreeBackend& checkerSphereBackend() {
  static const std::unique_ptr<EmbreeBackend> backend = [] {
    auto b = std::make_unique<EmbreeBackend>();
    b->setScene(builtinScene("checker-sphere"));
    return b;
  }();
  return *backend;
}

// Maps a physical pixel ray direction to the virtual direction whose colour the pixel must show,
// or nullopt where the pixel must be black.
using DirectionMap = std::function<std::optional<glm::dvec3>(const glm::dvec3&)>;

// Fraction of pixels of `image` whose colour differs from the checker-sphere's colour along
// `toVirtual` of the pixel's ray (headlight Lambert is 1 on a sphere seen from its centre), or
// that are not black where toVirtual has no direction. Pixels within half a pixel of a checker
// edge or of the unlit boundary are skipped: the texture filter and the map's bilinear alpha
// blend there.
inline double checkerMismatch(const ImageRGBA& image, const WallView& view, double scale,
                              const DirectionMap& toVirtual) {
  std::size_t bad = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      auto colourAt = [&](double dx, double dy) {
        const std::optional<glm::dvec3> v = toVirtual(
            view.rayDirection((x + 0.5 + dx) / scale, (y + 0.5 + dy) / scale));
        return v ? glm::vec4(checkerSphereColor(*v), 1.0f) : glm::vec4(0.0f);
      };
      const glm::vec4 expected = colourAt(0, 0);
      if (colourAt(-0.5, 0) != expected || colourAt(0.5, 0) != expected ||
          colourAt(0, -0.5) != expected || colourAt(0, 0.5) != expected)
        continue;
      const float* p = image.at(x, y);
      for (int c = 0; c < 4; ++c)
        if (std::abs(p[c] - expected[c]) > 0.02f) {
          ++bad;
          break;
        }
    }
  return static_cast<double>(bad) / static_cast<double>(image.pixelCount());
}

}  // namespace confvis::test
