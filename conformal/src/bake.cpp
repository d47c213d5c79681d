#include "confvis/conformal/bake.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/progress.hpp"
#include "cube_texels.hpp"
#include "disk_locator.hpp"
#include "sphere_raster.hpp"

namespace confvis {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr int kMaxResolution = 8192;

void validateMesh(const SphereDiskMesh& mesh, const std::string& name) {
  auto fail = [&](const std::string& what) {
    throw Error(ErrorCode::InvalidInput, "display map " + name + " mesh: " + what);
  };
  const std::size_t vertices = mesh.sphere.size();
  if (mesh.disk.size() != vertices)
    fail(std::to_string(vertices) + " sphere points but " + std::to_string(mesh.disk.size()) +
         " disk points");
  if (mesh.triangles.empty()) fail("no triangles");
  if (!mesh.lit.empty() && mesh.lit.size() != mesh.triangles.size())
    fail(std::to_string(mesh.lit.size()) + " lit flags for " +
         std::to_string(mesh.triangles.size()) + " triangles");
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3d& p = mesh.sphere[v];
    if (!isFinite(p) || std::abs(norm(p) - 1.0) > 1e-6)
      fail("vertex " + std::to_string(v) + " is not a finite unit vector");
    const std::complex<double> z = mesh.disk[v];
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag()) || std::abs(z) > 1.0 + 1e-6)
      fail("disk point of vertex " + std::to_string(v) + " is not in the closed unit disk");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t])
      if (v < 0 || static_cast<std::size_t>(v) >= vertices)
        fail("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
             " of " + std::to_string(vertices));
}

// One direction map: rasterise `domain` on the sphere, carry each texel through the disks into
// `codomain`. alpha from the domain triangle's lit flag; `covered` marks every rasterised texel.
void bakeDirectionMap(const SphereDiskMesh& domain, const SphereDiskMesh& codomain,
                      const detail::DiskLocator& codomainDisk, int threads, CubeMap& out,
                      std::vector<std::uint8_t>& covered, Progress* progress) {
  const int n = out.faceSize;
  covered.assign(6 * static_cast<std::size_t>(n) * n, 0);
  const std::function<void()> onTaskDone = [progress] {
    if (progress) progress->advance();
  };
  detail::rasterizeSphereMesh(
      domain.sphere, domain.triangles, n, threads, onTaskDone,
      [&](CubeFace face, int x, int y, int triangle, const std::array<double, 3>& b, int& hint) {
        const auto& tri = domain.triangles[triangle];
        const std::complex<double> z =
            b[0] * domain.disk[tri[0]] + b[1] * domain.disk[tri[1]] + b[2] * domain.disk[tri[2]];
        const detail::DiskLocator::Hit hit = codomainDisk.locate(z, hint);
        const auto& image = codomain.triangles[hit.triangle];
        const Vec3d sum = hit.barycentric[0] * codomain.sphere[image[0]] +
                          hit.barycentric[1] * codomain.sphere[image[1]] +
                          hit.barycentric[2] * codomain.sphere[image[2]];
        const double length = norm(sum);
        // Only a triangle spanning antipodal corners could sum to zero; take its corner then.
        const Vec3d dir = length > 1e-12 ? (1.0 / length) * sum : codomain.sphere[image[0]];
        float* p = out.face(face).at(x, y);
        p[0] = static_cast<float>(dir.x);
        p[1] = static_cast<float>(dir.y);
        p[2] = static_cast<float>(dir.z);
        p[3] = domain.lit.empty() || domain.lit[triangle] ? 1.0f : 0.0f;
        covered[detail::texelIndex(face, x, y, n)] = 1;
      });
}

}  // namespace

void validateDisplayMap(const DisplayMap& map) {
  validateMesh(map.source, "source");
  validateMesh(map.target, "target");
}

RetargetMap bakeRetargetMap(const DisplayMap& map, int resolution, const BakeOptions& options,
                            BakeTimings* timings) {
  if (resolution < 1 || resolution > kMaxResolution)
    throw Error(ErrorCode::InvalidInput, "bake resolution must be between 1 and " +
                                             std::to_string(kMaxResolution) + " texels, got " +
                                             std::to_string(resolution));
  if (!isFinite(options.reference))
    throw Error(ErrorCode::InvalidInput, "bake reference point is not finite");
  validateDisplayMap(map);
  BakeTimings t;
  const auto start = Clock::now();
  auto stage = Clock::now();
  const detail::DiskLocator sourceDisk(map.source.disk, map.source.triangles);
  const detail::DiskLocator targetDisk(map.target.disk, map.target.triangles);
  t.locators = secondsSince(stage);

  const int bands = (resolution + detail::kRasterBandRows - 1) / detail::kRasterBandRows;
  std::unique_ptr<Progress> progress;
  if (options.showProgress) progress = std::make_unique<Progress>("bake", 12 * bands, true);

  RetargetMap result;
  result.reference = options.reference;
  result.ray = CubeMap(resolution);
  result.geom = CubeMap(resolution);
  std::vector<std::uint8_t> rayCovered, geomCovered;
  stage = Clock::now();
  bakeDirectionMap(map.target, map.source, sourceDisk, options.threads, result.ray, rayCovered,
                   progress.get());
  t.ray = secondsSince(stage);
  stage = Clock::now();
  bakeDirectionMap(map.source, map.target, targetDisk, options.threads, result.geom, geomCovered,
                   progress.get());
  t.geom = secondsSince(stage);
  stage = Clock::now();
  detail::parallelFor(2, options.threads, [&](std::size_t which) {
    if (which == 0) detail::extendPastBoundary(result.ray, rayCovered);
    else detail::extendPastBoundary(result.geom, geomCovered);
  });
  t.extend = secondsSince(stage);
  if (progress) progress->finish();
  for (const CubeMap* m : {&result.ray, &result.geom})
    for (const ImageRGBA& face : m->faces)
      if (!face.allFinite()) throw Error(ErrorCode::Internal, "bake produced a non-finite texel");
  t.total = secondsSince(start);
  if (timings) *timings = t;
  return result;
}

}  // namespace confvis
