#pragma once
// Direction cube maps (design note §2, §3 step 7): six square faces of N x N RGBA float texels
// indexed by a 3D direction. The in-memory layout and the file layout follow OpenEXR's cube
// environment map (Imf::CubeMap, ENVMAP_CUBE): faces +X, -X, +Y, -Y, +Z, -Z (also the order of
// Vulkan cube layers), each face oriented as seen from the cube's centre:
//   +X: right = +z, down = -y      -X: right = -z, down = -y
//   +Y: right = +x, down = -z      -Y: right = +x, down = +z
//   +Z: right = -x, down = -y      -Z: right = +x, down = -y
//
// Texel centres. Imf::CubeMap::direction maps in-face pixel positions 0 .. N-1 onto the face's
// full extent -1 .. +1, so its edge pixels sit *on* the cube edges and are shared by two faces.
// Vulkan (and every GPU) puts texel i's centre at (i + 0.5) / N. Baked maps are sampled by the
// GPU, so confvis uses the GPU's texel centres with OpenEXR's orientation:
//   texel (x, y) of face f has direction  normal(f) + c(x) right(f) + c(y) down(f),
//   c(i) = (2 i + 1 - N) / N,
// which equals Imf::CubeMap::direction(f, dw, p) at the in-face position
// p = (q + 0.5) (N - 1) / N, where q is the integer in-face position Imf::CubeMap::pixelPosition
// maps to image pixel (x, f N + y). The difference to Imf's own centres is under half a texel.
//
// Continuous texel coordinates (directionToTexel, vulkanDirectionToTexel) run from 0 to N across
// a face, texel i covering [i, i + 1) with its centre at i + 0.5, as in Vulkan.
#include <array>
#include <filesystem>

#include "confvis/base/export.hpp"
#include "confvis/base/image.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/vec3.hpp"

namespace confvis CONFVIS_API {

enum class CubeFace { PosX, NegX, PosY, NegY, PosZ, NegZ };  // OpenEXR's and Vulkan's order

inline constexpr std::array<CubeFace, 6> kCubeFaces = {
    CubeFace::PosX, CubeFace::NegX, CubeFace::PosY, CubeFace::NegY, CubeFace::PosZ, CubeFace::NegZ};
const char* toString(CubeFace face) noexcept;

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct CubeMap {
  int faceSize = 0;                // N
  std::array<ImageRGBA, 6> faces;  // indexed by CubeFace, each N x N

  CubeMap() = default;
  explicit CubeMap(int n, float value = 0.0f);

  ImageRGBA& face(CubeFace f) { return faces[static_cast<int>(f)]; }
  const ImageRGBA& face(CubeFace f) const { return faces[static_cast<int>(f)]; }
};

// --- OpenEXR convention (confvis's own layout) ---
// Direction through the centre of texel (x, y) of `face`, as a point on the cube [-1, 1]^3
// (not normalised: exact, and comparable with Imf::CubeMap::direction).
glm::dvec3 texelDirection(CubeFace face, int x, int y, int n);
// Face and continuous texel coordinates (0..N) hit by direction d. Ties between axes go to x,
// then y, as in Imf::CubeMap::faceAndPixelPosition. Throws Error(InvalidInput) for a zero or
// non-finite direction.
void directionToTexel(const glm::dvec3& d, int n, CubeFace& face, double& x, double& y);

// --- Vulkan convention ("Cube Map Face Selection": s = (sc/|ma| + 1)/2, row 0 at t = 0) ---
glm::dvec3 vulkanTexelDirection(CubeFace face, int x, int y, int n);
void vulkanDirectionToTexel(const glm::dvec3& d, int n, CubeFace& face, double& x, double& y);
// The texel of the Vulkan layout that holds texel (x, y) of the same face of the EXR layout.
void exrToVulkanTexel(CubeFace face, int x, int y, int n, int& vulkanX, int& vulkanY);
// Reorients every face so that a Vulkan samplerCube looking up d returns what the EXR-layout map
// stores for d. Face order is unchanged; upload faces[i] as array layer i.
CubeMap toVulkanLayout(const CubeMap& exrLayout);

// --- Sampling (EXR layout). Both throw Error(InvalidInput) for a zero or non-finite direction
// or a malformed map. ---
std::array<float, 4> sampleNearest(const CubeMap& map, const glm::dvec3& dir);
// Bilinear across face edges, second order everywhere: a footprint texel that falls off the face
// stands for the direction of its centre on the face's plane extended past the edge, and takes
// the value there interpolated on the neighbouring face(s) (texelAcrossFaceEdge). Seamless: the
// error at edges and corners is no larger than inside a face.
std::array<float, 4> sampleBilinear(const CubeMap& map, const glm::dvec3& dir);

struct TexelRef {
  CubeFace face = CubeFace::PosX;
  int x = 0, y = 0;
};
struct WeightedTexel {
  TexelRef texel;
  double weight = 0;
};
// The in-face texels whose weighted sum stands in for texel (x, y) of `face`, where x and y may
// lie one texel beyond the face (-1 or n). Inside the face: the texel itself. Beyond an edge: the
// direction of that texel's centre on the face's extended plane, interpolated linearly along the
// neighbouring face's edge row (an O(1/n^2) error, where the nearest texel is O(1/n) off). Beyond
// a corner that direction lies on the edge between the two other faces there: their two texels
// beside it, averaged. Weights are positive and sum to one; `count` of `texels` are used.
struct TexelStandIn {
  std::array<WeightedTexel, 8> texels;
  int count = 0;
};
TexelStandIn texelAcrossFaceEdge(CubeFace face, int x, int y, int n);

// --- Files ---
// OpenEXR cube environment map: N x 6N, faces stacked top to bottom, float32 RGBA, ZIP,
// envmap = ENVMAP_CUBE. Throws Error(InvalidInput) for malformed or non-finite maps.
void writeCubeExr(const std::filesystem::path& path, const CubeMap& map);
// Throws Error(IoFailure) if the file has no envmap = cube attribute or is not N x 6N.
CubeMap readCubeExr(const std::filesystem::path& path);

// Horizontal-cross preview, 4N x 3N, as seen by a person standing in a CAVE at the origin facing
// -z, with +y up (every face exactly as stored, since faces are already oriented as seen from
// inside):            [+Y]
//               [-X]  [-Z]  [+X]  [+Z]
//                     [-Y]
// i.e. left wall, front, right wall, back; ceiling above and floor below the front wall, all
// edges continuous. Unused cells are transparent black.
ImageRGBA cubeCrossImage(const CubeMap& map);
void writeCubeCrossPng(const std::filesystem::path& path, const CubeMap& map,
                       const PngOptions& options = {});

}  // namespace confvis
