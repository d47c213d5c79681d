#include "bake_previews.hpp"

#include <algorithm>
#include <cmath>

#include "disk_locator.hpp"

namespace confvis::detail {

namespace {

constexpr float kInvalidDimming = 0.25f;

template <class Colour>
CubeMap recolour(const CubeMap& map, Colour&& colour) {
  CubeMap out(map.faceSize);
  for (int f = 0; f < 6; ++f) {
    const ImageRGBA& in = map.faces[f];
    ImageRGBA& o = out.faces[f];
    for (std::size_t i = 0; i < in.pixelCount(); ++i) {
      const float* p = &in.pixels[4 * i];
      const Vec3d v{p[0], p[1], p[2]};
      const Vec3d c = colour(norm(v) > 0 ? normalized(v) : Vec3d{0, 0, -1});
      const float scale = p[3] >= 0.5f ? 1.0f : kInvalidDimming;
      o.pixels[4 * i] = static_cast<float>(c.x) * scale;
      o.pixels[4 * i + 1] = static_cast<float>(c.y) * scale;
      o.pixels[4 * i + 2] = static_cast<float>(c.z) * scale;
      o.pixels[4 * i + 3] = 1.0f;
    }
  }
  return out;
}

}  // namespace

Vec3d checkerColour(const Vec3d& d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  Vec3d base{0.0};
  double u, v, major;
  if (ax >= ay && ax >= az) {
    base = {0.9, 0.15, 0.1};
    major = ax;
    u = d.y;
    v = d.z;
  } else if (ay >= az) {
    base = {0.1, 0.75, 0.15};
    major = ay;
    u = d.x;
    v = d.z;
  } else {
    base = {0.1, 0.25, 0.9};
    major = az;
    u = d.x;
    v = d.y;
  }
  if (!(major > 0)) return base;
  const int cu = static_cast<int>(std::floor((u / major + 1) * 4));
  const int cv = static_cast<int>(std::floor((v / major + 1) * 4));
  return (cu + cv) % 2 == 0 ? base : 0.35 * base;
}

ImageRGBA diskPreview(const SphereDiskMesh& mesh, int size) {
  ImageRGBA image(size, size, 0.0f);
  const DiskLocator locator(mesh.disk, mesh.triangles);
  const double pixel = 2.0 / size;
  for (int y = 0; y < size; ++y) {
    int hint = -1;
    for (int x = 0; x < size; ++x) {
      const std::complex<double> z((x + 0.5) * pixel - 1.0, 1.0 - (y + 0.5) * pixel);
      if (std::abs(z) > 1.0) continue;
      const DiskLocator::Hit hit = locator.locate(z, hint);
      if (!hit.inside) continue;
      const auto& t = mesh.triangles[hit.triangle];
      const Vec3d s = hit.barycentric[0] * mesh.sphere[t[0]] + hit.barycentric[1] * mesh.sphere[t[1]] +
                      hit.barycentric[2] * mesh.sphere[t[2]];
      Vec3d colour = checkerColour(s);
      if (!mesh.lit.empty() && !mesh.lit[hit.triangle]) colour = 0.3 * colour;
      // Mesh edges: within about half a pixel of the triangle's border (barycentric coordinate
      // times the corner's height over the opposite edge), where triangles are big enough for
      // the lines not to hide the checkerboard.
      const double twiceArea = std::abs(((mesh.disk[t[1]] - mesh.disk[t[0]]) *
                                         std::conj(mesh.disk[t[2]] - mesh.disk[t[0]])).imag());
      for (int k = 0; k < 3; ++k) {
        const double edge = std::abs(mesh.disk[t[(k + 2) % 3]] - mesh.disk[t[(k + 1) % 3]]);
        const double height = edge > 0 ? twiceArea / edge : 0;
        if (height > 6 * pixel && hit.barycentric[k] * height < 0.5 * pixel) {
          colour = 0.5 * colour + Vec3d{0.4, 0.4, 0.4};
          break;
        }
      }
      float* p = image.at(x, y);
      p[0] = static_cast<float>(colour.x);
      p[1] = static_cast<float>(colour.y);
      p[2] = static_cast<float>(colour.z);
      p[3] = 1.0f;
    }
  }
  return image;
}

CubeMap directionPreview(const CubeMap& map) {
  return recolour(map, [](const Vec3d& d) { return 0.5 * (d + Vec3d{1, 1, 1}); });
}

CubeMap checkerPreview(const CubeMap& map) { return recolour(map, checkerColour); }

}  // namespace confvis::detail
