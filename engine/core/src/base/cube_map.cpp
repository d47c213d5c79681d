#include "confvis/base/cube_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// A face's outward normal and the directions in which its texel x and y grow.
struct FaceFrame {
  Vec3d normal{0.0}, right{0.0}, down{0.0};
};
using FrameTable = std::array<FaceFrame, 6>;

// OpenEXR: Imf::CubeMap::direction composed with Imf::CubeMap::pixelPosition (see header).
constexpr FrameTable kExrFrames = {{
    {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{-1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {-1, 0, 0}, {0, -1, 0}},
    {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}},
}};

// Vulkan spec, cube map face selection table: right = d(sc), down = d(tc) per unit of the
// major axis, e.g. +X: sc = -rz, tc = -ry.
constexpr FrameTable kVulkanFrames = {{
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
}};

// Face coordinate of texel centre i in [-1, 1]; integer numerator, so c(N-1-i) == -c(i) exactly.
double texelCentre(int i, int n) { return static_cast<double>(2 * i + 1 - n) / n; }

Vec3d directionOnFace(const FrameTable& frames, CubeFace face, double a, double b) {
  const FaceFrame& f = frames[static_cast<int>(face)];
  return f.normal + a * f.right + b * f.down;
}

void requireFaceSize(int n) {
  if (n <= 0) throw Error(ErrorCode::InvalidInput, "cube map face size must be positive");
}

// Major axis selection; ties go to x, then y (Imf::CubeMap::faceAndPixelPosition).
void locate(const FrameTable& frames, const Vec3d& d, int n, CubeFace& face, double& x, double& y) {
  requireFaceSize(n);
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  if (!isFinite(d) || (ax == 0 && ay == 0 && az == 0))
    throw Error(ErrorCode::InvalidInput, "cube map lookup with a zero or non-finite direction");
  double major;
  if (ax >= ay && ax >= az) {
    face = d.x > 0 ? CubeFace::PosX : CubeFace::NegX;
    major = ax;
  } else if (ay >= az) {
    face = d.y > 0 ? CubeFace::PosY : CubeFace::NegY;
    major = ay;
  } else {
    face = d.z > 0 ? CubeFace::PosZ : CubeFace::NegZ;
    major = az;
  }
  const FaceFrame& f = frames[static_cast<int>(face)];
  x = (dot(d, f.right) / major + 1.0) * 0.5 * n;
  y = (dot(d, f.down) / major + 1.0) * 0.5 * n;
}

int clampIndex(double coordinate, int n) {
  return std::clamp(static_cast<int>(std::floor(coordinate)), 0, n - 1);
}

void requireWellFormed(const CubeMap& map) {
  requireFaceSize(map.faceSize);
  for (const ImageRGBA& f : map.faces)
    if (f.width != map.faceSize || f.height != map.faceSize ||
        f.pixels.size() != f.pixelCount() * 4)
      throw Error(ErrorCode::InvalidInput, "cube map faces must all be " +
                                               std::to_string(map.faceSize) + "x" +
                                               std::to_string(map.faceSize));
}

// Adds the texels of `face` that interpolate linearly at direction d (taken on that face's plane,
// whatever its major axis), with texel coordinates clamped to the texel centres: bilinear
// inside, linear along the edge row beyond it.
void addClampedBilinear(CubeFace face, const Vec3d& d, int n, double weight, TexelStandIn& out) {
  const FaceFrame& f = kExrFrames[static_cast<int>(face)];
  const double major = dot(d, f.normal);
  auto footprint = [n](double coordinate, int& i0, double& t) {
    const double c = std::clamp(coordinate - 0.5, 0.0, static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(std::floor(c)), std::max(n - 2, 0));
    t = n > 1 ? c - i0 : 0.0;
  };
  int x0, y0;
  double tx, ty;
  footprint((dot(d, f.right) / major + 1.0) * 0.5 * n, x0, tx);
  footprint((dot(d, f.down) / major + 1.0) * 0.5 * n, y0, ty);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double w = weight * (i ? tx : 1 - tx) * (j ? ty : 1 - ty);
      if (w > 0) out.texels[out.count++] = {{face, x0 + i, y0 + j}, w};
    }
}

CubeFace faceOfAxis(int axis, double sign) {
  return static_cast<CubeFace>(2 * axis + (sign > 0 ? 0 : 1));
}

}  // namespace

const char* toString(CubeFace face) noexcept {
  static constexpr const char* kNames[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  return kNames[static_cast<int>(face)];
}

CubeMap::CubeMap(int n, float value) : faceSize(n) {
  requireFaceSize(n);
  for (ImageRGBA& f : faces) f = ImageRGBA(n, n, value);
}

Vec3d texelDirection(CubeFace face, int x, int y, int n) {
  return directionOnFace(kExrFrames, face, texelCentre(x, n), texelCentre(y, n));
}

void directionToTexel(const Vec3d& d, int n, CubeFace& face, double& x, double& y) {
  locate(kExrFrames, d, n, face, x, y);
}

Vec3d vulkanTexelDirection(CubeFace face, int x, int y, int n) {
  return directionOnFace(kVulkanFrames, face, texelCentre(x, n), texelCentre(y, n));
}

void vulkanDirectionToTexel(const Vec3d& d, int n, CubeFace& face, double& x, double& y) {
  locate(kVulkanFrames, d, n, face, x, y);
}

void exrToVulkanTexel(CubeFace face, int x, int y, int n, int& vulkanX, int& vulkanY) {
  // The texel centre's direction has |major axis| = 1, so its Vulkan face coordinates are
  // +-c(x) or +-c(y) exactly; invert c to get the integer index.
  const Vec3d d = texelDirection(face, x, y, n);
  const FaceFrame& vk = kVulkanFrames[static_cast<int>(face)];
  vulkanX = static_cast<int>(std::lround((dot(d, vk.right) * n + n - 1) * 0.5));
  vulkanY = static_cast<int>(std::lround((dot(d, vk.down) * n + n - 1) * 0.5));
}

CubeMap toVulkanLayout(const CubeMap& exrLayout) {
  requireWellFormed(exrLayout);
  const int n = exrLayout.faceSize;
  CubeMap vulkan(n);
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int vx, vy;
        exrToVulkanTexel(face, x, y, n, vx, vy);
        std::copy_n(exrLayout.face(face).at(x, y), 4, vulkan.face(face).at(vx, vy));
      }
  return vulkan;
}

std::array<float, 4> sampleNearest(const CubeMap& map, const Vec3d& dir) {
  requireWellFormed(map);
  CubeFace face;
  double x, y;
  locate(kExrFrames, dir, map.faceSize, face, x, y);
  const float* t = map.face(face).at(clampIndex(x, map.faceSize), clampIndex(y, map.faceSize));
  return {t[0], t[1], t[2], t[3]};
}

TexelStandIn texelAcrossFaceEdge(CubeFace face, int x, int y, int n) {
  requireFaceSize(n);
  TexelStandIn out;
  if (x >= 0 && x < n && y >= 0 && y < n) {
    out.texels[out.count++] = {{face, x, y}, 1.0};
    return out;
  }
  if (x < -1 || x > n || y < -1 || y > n)
    throw Error(ErrorCode::InvalidInput, "cube map texel more than one texel beyond its face");
  // Beyond the face, |c| = 1 + 1/n exceeds the face's own normal component 1: the major axis is
  // that of the edge crossed, or a tie between two such axes beyond a corner (exact: both are
  // the same rational number).
  const Vec3d d = directionOnFace(kExrFrames, face, texelCentre(x, n), texelCentre(y, n));
  std::array<double, 3> component{d.x, d.y, d.z};
  double major = 0;
  for (double c : component) major = std::max(major, std::abs(c));
  int ties = 0;
  for (double c : component) ties += std::abs(c) == major;
  if (ties == 2) {
    // Beyond a corner d lies on the edge between faces B and C, at coordinate alpha along it.
    // The mean of B's and C's texels beside the edge at coordinate u stands for the edge point
    // alpha = u / (1 - 1/(2n)) (their centres are 1/n in from the edge): so look both up at
    // u = alpha (1 - 1/(2n)), i.e. scale the third component.
    for (double& c : component)
      if (std::abs(c) != major) c *= 1.0 - 0.5 / n;
  }
  const Vec3d lookup{component[0], component[1], component[2]};
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(component[axis]) == major)
      addClampedBilinear(faceOfAxis(axis, component[axis]), lookup, n, 1.0 / ties, out);
  return out;
}

std::array<float, 4> sampleBilinear(const CubeMap& map, const Vec3d& dir) {
  requireWellFormed(map);
  const int n = map.faceSize;
  CubeFace face;
  double x, y;
  locate(kExrFrames, dir, n, face, x, y);
  // Texel centres sit at i + 0.5: the footprint is the 2x2 block around (x - 0.5, y - 0.5).
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  std::array<double, 4> sum{};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double w = (i ? tx : 1 - tx) * (j ? ty : 1 - ty);
      if (w == 0) continue;
      const TexelStandIn standIn = texelAcrossFaceEdge(face, x0 + i, y0 + j, n);
      for (int k = 0; k < standIn.count; ++k) {
        const WeightedTexel& r = standIn.texels[k];
        const float* t = map.face(r.texel.face).at(r.texel.x, r.texel.y);
        for (int c = 0; c < 4; ++c) sum[c] += w * r.weight * t[c];
      }
    }
  return {static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2]),
          static_cast<float>(sum[3])};
}

}  // namespace confvis
