#include "confvis/backends/conformal_warp.hpp"

#include <cmath>
#include <cstring>

#include <tbb/parallel_for.h>

#include "confvis/base/error.hpp"

namespace confvis {

ConformalWarp::ConformalWarp(const RetargetMap& map)
    : map_(&map), reference_(map.reference.x, map.reference.y, map.reference.z) {
  if (!isFinite(map.reference))
    throw Error(ErrorCode::InvalidInput, "retarget map: the reference point is not finite");
  const int n = map.ray.faceSize;
  if (n <= 0)
    throw Error(ErrorCode::InvalidInput, "retarget map: the ray cube map is empty");
  for (const ImageRGBA& face : map.ray.faces)
    if (face.width != n || face.height != n || face.pixels.size() != face.pixelCount() * 4)
      throw Error(ErrorCode::InvalidInput,
                  "retarget map: the ray cube map's faces are not all " + std::to_string(n) +
                      "x" + std::to_string(n));
}

ConformalWarp::Lookup ConformalWarp::lookup(const glm::dvec3& physicalDir) const {
  // sampleBilinear's result, with a fast path for footprints inside one face (all but a thin
  // band along the cube's edges): renderers look the map up once per camera sample.
  const Vec3d d{physicalDir.x, physicalDir.y, physicalDir.z};
  const int n = map_->ray.faceSize;
  CubeFace face;
  double x, y;
  directionToTexel(d, n, face, x, y);  // throws for a zero or non-finite direction
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  std::array<float, 4> s;
  if (x0 >= 0 && y0 >= 0 && x0 + 1 < n && y0 + 1 < n) {
    const ImageRGBA& image = map_->ray.face(face);
    const float tx = static_cast<float>(fx - x0), ty = static_cast<float>(fy - y0);
    const float* a = image.at(x0, y0);
    const float* b = a + 4;
    const float* c = image.at(x0, y0 + 1);
    const float* e = c + 4;
    for (int k = 0; k < 4; ++k)
      s[k] = (1 - ty) * ((1 - tx) * a[k] + tx * b[k]) + ty * ((1 - tx) * c[k] + tx * e[k]);
  } else {
    s = sampleBilinear(map_->ray, d);
  }
  const glm::dvec3 v(s[0], s[1], s[2]);
  const double length = glm::length(v);
  // A map that stores a zero or non-finite direction is broken, not merely unlit: say so rather
  // than trace NaN rays.
  if (!(length > 0.0) || !std::isfinite(length))
    throw Error(ErrorCode::InvalidInput,
                "retarget map: the ray map stores no valid direction near (" +
                    std::to_string(physicalDir.x) + ", " + std::to_string(physicalDir.y) + ", " +
                    std::to_string(physicalDir.z) + ")");
  return {v / length, s[3] >= 0.5f, s[3]};
}

int ConformalWarp::litFootprint(const glm::dvec3& physicalDir,
                                std::array<glm::dvec3, 4>& directions) const {
  const int n = map_->ray.faceSize;
  CubeFace face;
  double x, y;
  directionToTexel({physicalDir.x, physicalDir.y, physicalDir.z}, n, face, x, y);
  const int x0 = static_cast<int>(std::floor(x - 0.5)), y0 = static_cast<int>(std::floor(y - 0.5));
  int lit = 0;
  for (int j = y0; j <= y0 + 1; ++j)
    for (int i = x0; i <= x0 + 1; ++i) {
      const Vec3d d = texelDirection(face, i, j, n);  // beyond the face where i or j is outside
      const bool inside = i >= 0 && j >= 0 && i < n && j < n;
      const float alpha = inside ? map_->ray.face(face).at(i, j)[3] : sampleNearest(map_->ray, d)[3];
      if (alpha >= 0.5f) directions[static_cast<std::size_t>(lit++)] = {d.x, d.y, d.z};
    }
  return lit;
}

namespace {

// mixHash's body, local so that fingerprint's loop inlines it (an exported function of a
// position-independent library is not inlined: it could be interposed).
inline std::uint64_t mix(std::uint64_t hash, std::uint64_t word) {
  std::uint64_t z = word ^ (hash + 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t mixHash(std::uint64_t hash, std::uint64_t word) { return mix(hash, word); }

std::uint64_t mixHash(std::uint64_t hash, double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return mixHash(hash, bits);
}

std::uint64_t ConformalWarp::fingerprint() const {
  return fingerprintCubeMap(map_->ray, reference_);
}

std::uint64_t fingerprintCubeMap(const CubeMap& map, const glm::dvec3& reference) {
  // Faces in parallel (every conformal frame hashes its map: ~1 ms on one thread for 256^2
  // texels a face), each in four independent lanes (instruction-level parallelism), folded
  // together in face order at the end.
  std::array<std::uint64_t, 6> faceHashes{};
  tbb::parallel_for(0, static_cast<int>(map.faces.size()), [&](int f) {
    const ImageRGBA& face = map.faces[static_cast<std::size_t>(f)];
    std::array<std::uint64_t, 4> lanes = {1, 2, 3, 4};
    const std::size_t words = face.pixels.size() / 2;  // two floats per word
    const float* data = face.pixels.data();
    std::size_t i = 0;
    for (; i + 4 <= words; i += 4)
      for (std::size_t lane = 0; lane < 4; ++lane) {
        std::uint64_t bits;
        std::memcpy(&bits, data + 2 * (i + lane), sizeof bits);
        lanes[lane] = mix(lanes[lane], bits);
      }
    for (; 2 * i < face.pixels.size(); ++i) lanes[0] = mixHash(lanes[0], double(data[2 * i]));
    std::uint64_t hash = static_cast<std::uint64_t>(f);
    for (std::uint64_t lane : lanes) hash = mix(hash, lane);
    faceHashes[static_cast<std::size_t>(f)] = hash;
  });
  std::uint64_t hash = static_cast<std::uint64_t>(map.faceSize);
  for (std::uint64_t face : faceHashes) hash = mixHash(hash, face);
  for (double value : {reference.x, reference.y, reference.z}) hash = mixHash(hash, value);
  return hash;
}

glm::dvec3 ConformalWarp::warpPoint(const glm::dvec3& physicalPoint) const {
  const glm::dvec3 offset = physicalPoint - reference_;
  const double distance = glm::length(offset);
  if (distance == 0.0) return reference_;
  return reference_ + distance * direction(offset);
}

}  // namespace confvis
