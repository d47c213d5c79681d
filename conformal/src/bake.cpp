#include "confvis/conformal/bake.hpp"

#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/stopwatch.hpp"
#include "bake_count.hpp"
#include "cube_texels.hpp"
#include "disk_locator.hpp"
#include "parallel_for.hpp"
#include "smooth_interpolation.hpp"
#include "sphere_raster.hpp"

namespace confvis {

namespace {

constexpr int kMaxResolution = 8192;

std::atomic<std::size_t> bakes{0};  // detail::retargetBakeCount

using detail::writeDirection;

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

// A codomain triangle as linear maps of the homogeneous disk point h = (hx, hy, hw): its
// homogeneous barycentric coordinates l1 = b1 . h, l2 = b2 . h (l0 = hw - l1 - l2) and the
// unnormalised direction l0 s0 + l1 s1 + l2 s2 = hx dx + hy dy + hw dw. One per codomain
// triangle, made before the texel loops: texels switch triangles ~2 times per span.
struct CodomainFrame {
  double b1[3] = {}, b2[3] = {};
  Vec3d dx{0.0}, dy{0.0}, dw{0.0};
  Vec3d corner{0.0};  // s0: the direction written if the sum cancels (antipodal corners only)
};

std::vector<CodomainFrame> codomainFrames(const SphereDiskMesh& codomain,
                                          const detail::DiskLocator& disk) {
  std::vector<CodomainFrame> frames(codomain.triangles.size());
  for (std::size_t t = 0; t < frames.size(); ++t) {
    CodomainFrame& f = frames[t];
    const detail::DiskLocator::Affine& a = disk.affine(static_cast<int>(t));
    const double b1[3] = {a.m11, a.m12, -(a.m11 * a.x0 + a.m12 * a.y0)};
    const double b2[3] = {a.m21, a.m22, -(a.m21 * a.x0 + a.m22 * a.y0)};
    const auto& image = codomain.triangles[t];
    const Vec3d& s0 = codomain.sphere[image[0]];
    const Vec3d s1 = codomain.sphere[image[1]] - s0, s2 = codomain.sphere[image[2]] - s0;
    // direction = hw s0 + l1 (s1 - s0) + l2 (s2 - s0)
    Vec3d rows[3];
    for (int c = 0; c < 3; ++c) {
      f.b1[c] = b1[c];
      f.b2[c] = b2[c];
      rows[c] = b1[c] * s1 + b2[c] * s2;
    }
    f.dx = rows[0];
    f.dy = rows[1];
    f.dw = rows[2] + s0;
    f.corner = s0;
  }
  return frames;
}

// Per raster task: the codomain triangle of the last texel shaded (`hint`, for point location)
// and that of the first texel of the last span, the best start for the next span (the next row
// of the same domain triangle); -1: none. `triangle` is the domain triangle whose disk corners
// (`zx`, `zy`) and per-texel step of the homogeneous disk point (`dh`) are cached: a triangle's
// spans come row after row.
struct ShadeState {
  int hint = -1;
  int spanStart = -1;
  int triangle = -1;
  double zx[3] = {}, zy[3] = {};
  double dh[3] = {};
};

// A texel may cross this many codomain edges before the walk gives way to point location (a
// texel on a vertex can bounce between the triangles around it).
constexpr int kMaxCrossings = 16;
// Texels left in a span from which a run inside one codomain triangle is stepped linearly.
constexpr int kLinearRun = 4;

// Per domain vertex, the codomain triangle holding its disk point: where the walk of a domain
// triangle's first span starts (the previous span may lie far away in the codomain disk). Each
// vertex is located from a corner of the same domain triangle located before it: a short walk.
std::vector<int> codomainTriangleOfVertices(const SphereDiskMesh& domain,
                                            const detail::DiskLocator& codomainDisk) {
  std::vector<int> triangles(domain.disk.size(), -1);
  int hint = -1;
  for (const auto& tri : domain.triangles) {
    for (int v : tri)
      if (triangles[v] >= 0) {
        hint = triangles[v];
        break;
      }
    for (int v : tri)
      if (triangles[v] < 0) triangles[v] = codomainDisk.locate(domain.disk[v], hint).triangle;
  }
  return triangles;
}

// One direction map's pass: rasterise `domain` on the sphere, carry each texel through the disks
// into `codomain`. alpha from the domain triangle's lit flag; `covered` marks every rasterised
// texel. Set up once (on the thread that built the codomain's locator), then its raster tasks run
// on any thread, in one loop with the other direction's.
//
// Along a span of texels in one domain triangle the homogeneous disk point h = (sum w_i z_i,
// sum w_i) is linear in x. In a codomain triangle its homogeneous barycentric coordinates L and
// the direction L0 s0 + L1 s1 + L2 s2 are linear maps of h (CodomainFrame). A texel outside the
// previous texel's codomain triangle (some L < 0) steps to the neighbour across the edge
// opposite the most negative L; point location only where that walk fails (outside the
// codomain disk: clamped). At 256 texels a face (cave5, 20 cm) texels stay ~2 to a codomain
// triangle, so a texel evaluates its frame afresh; only where at least kLinearRun texels of the
// span are left is the rest of the run inside one triangle stepped linearly.
class DirectionPass {
 public:
  // `covered` is sized and cleared here; `out` must have the bake's face size.
  DirectionPass(const SphereDiskMesh& domain, const SphereDiskMesh& codomain,
                const detail::DiskLocator& codomainDisk, CubeMap& out,
                std::vector<std::uint8_t>& covered)
      : domain_(domain),
        codomain_(codomain),
        codomainDisk_(codomainDisk),
        out_(out),
        covered_(covered),
        frames_(codomainFrames(codomain, codomainDisk)),
        vertexHints_(codomainTriangleOfVertices(domain, codomainDisk)),
        raster_(domain.sphere, domain.triangles, out.faceSize) {
    covered.assign(6 * static_cast<std::size_t>(out.faceSize) * out.faceSize, 0);
  }

  std::size_t taskCount() const { return raster_.taskCount(); }
  void runTask(std::size_t task) {
    raster_.runTask<ShadeState>(task, [this](const detail::RasterSpan& span, ShadeState& state) {
      shadeSpan(span, state);
    });
  }

 private:
  void shadeSpan(const detail::RasterSpan& span, ShadeState& state) const {
    const SphereDiskMesh& domain = domain_;
    const SphereDiskMesh& codomain = codomain_;
    const detail::DiskLocator& codomainDisk = codomainDisk_;
    const std::vector<CodomainFrame>& frames = frames_;
    const std::vector<int>& vertexHints = vertexHints_;
    CubeMap& out = out_;
    const int n = out.faceSize;
    const auto& tri = domain.triangles[span.triangle];
    if (state.triangle != span.triangle) {
      state.triangle = span.triangle;
      for (int i = 0; i < 3; ++i) {
        state.zx[i] = domain.disk[tri[i]].real();
        state.zy[i] = domain.disk[tri[i]].imag();
      }
      const std::array<double, 3>& s = span.step;
      state.dh[0] = s[0] * state.zx[0] + s[1] * state.zx[1] + s[2] * state.zx[2];
      state.dh[1] = s[0] * state.zy[0] + s[1] * state.zy[1] + s[2] * state.zy[2];
      state.dh[2] = s[0] + s[1] + s[2];
      state.spanStart = vertexHints[tri[0]];
    }
    const std::array<double, 3>& w = span.w;
    const double h0[3] = {w[0] * state.zx[0] + w[1] * state.zx[1] + w[2] * state.zx[2],
                          w[0] * state.zy[0] + w[1] * state.zy[1] + w[2] * state.zy[2],
                          w[0] + w[1] + w[2]};
    const double* const dh = state.dh;
    const float alpha = domain.lit.empty() || domain.lit[span.triangle] ? 1.0f : 0.0f;
    float* const texels = out.face(span.face).at(span.xBegin, span.y);
    const int count = span.xEnd - span.xBegin + 1;
    // The codomain triangle of the texel before (-1: none, or clamped outside the disk).
    int current = state.spanStart >= 0 ? state.spanStart : state.hint;
    // Texels k, k+1, ... while they stay in triangle f, with L and the direction linear in k:
    // cheaper per texel than a fresh frame evaluation once the set-up is shared by a few
    // texels (long spans at fine resolutions). Returns the first texel that left f.
    auto shadeWhileInside = [&](int k, const CodomainFrame& f) {
      const double l1Start = f.b1[0] * h0[0] + f.b1[1] * h0[1] + f.b1[2] * h0[2];
      const double l1Step = f.b1[0] * dh[0] + f.b1[1] * dh[1] + f.b1[2] * dh[2];
      const double l2Start = f.b2[0] * h0[0] + f.b2[1] * h0[1] + f.b2[2] * h0[2];
      const double l2Step = f.b2[0] * dh[0] + f.b2[1] * dh[1] + f.b2[2] * dh[2];
      const Vec3d start = h0[0] * f.dx + h0[1] * f.dy + h0[2] * f.dw;
      const Vec3d step = dh[0] * f.dx + dh[1] * f.dy + dh[2] * f.dw;
      for (; k < count; ++k) {
        const double hw = h0[2] + k * dh[2];
        const double l1 = l1Start + k * l1Step, l2 = l2Start + k * l2Step, l0 = hw - l1 - l2;
        const double tolerance = -1e-12 * hw;
        if (!(l0 >= tolerance && l1 >= tolerance && l2 >= tolerance)) break;
        writeDirection(texels + 4 * k, start + static_cast<double>(k) * step, f.corner, alpha);
      }
      return k;
    };
    for (int k = 0; k < count;) {
      const double hx = h0[0] + k * dh[0], hy = h0[1] + k * dh[1], hw = h0[2] + k * dh[2];
      const double tolerance = -1e-12 * hw;
      bool inside = false;
      for (int crossings = 0; current >= 0 && crossings <= kMaxCrossings; ++crossings) {
        const CodomainFrame& f = frames[current];
        const double l1 = f.b1[0] * hx + f.b1[1] * hy + f.b1[2] * hw;
        const double l2 = f.b2[0] * hx + f.b2[1] * hy + f.b2[2] * hw;
        const double l0 = hw - l1 - l2;
        if (l0 >= tolerance && l1 >= tolerance && l2 >= tolerance) {
          writeDirection(texels + 4 * k, hx * f.dx + hy * f.dy + hw * f.dw, f.corner, alpha);
          inside = true;
          break;
        }
        // Across the edge opposite the most negative coordinate.
        const int next = codomainDisk.neighbour(current, l0 <= l1 && l0 <= l2 ? 0 : l1 <= l2 ? 1 : 2);
        if (next < 0 || !codomainDisk.affine(next).valid) break;
        current = next;
      }
      if (!inside) {
        if (current >= 0) state.hint = current;
        const detail::DiskLocator::Hit hit = codomainDisk.locate({hx / hw, hy / hw}, state.hint);
        const auto& image = codomain.triangles[hit.triangle];
        const std::array<double, 3>& l = hit.barycentric;
        const Vec3d sum = l[0] * codomain.sphere[image[0]] + l[1] * codomain.sphere[image[1]] +
                          l[2] * codomain.sphere[image[2]];
        writeDirection(texels + 4 * k, sum, codomain.sphere[image[0]], alpha);
        // Outside: clamped, no walk from there.
        current = hit.inside ? hit.triangle : -1;
      }
      if (k == 0) state.spanStart = current;
      ++k;
      if (inside && count - k >= kLinearRun) k = shadeWhileInside(k, frames[current]);
    }
    if (current >= 0) state.hint = current;
    std::fill_n(&covered_[detail::texelIndex(span.face, span.xBegin, span.y, n)], count, 1);
  }

  const SphereDiskMesh& domain_;
  const SphereDiskMesh& codomain_;
  const detail::DiskLocator& codomainDisk_;
  CubeMap& out_;
  std::vector<std::uint8_t>& covered_;
  const std::vector<CodomainFrame> frames_;
  const std::vector<int> vertexHints_;
  const detail::SphereRaster raster_;
};

}  // namespace

std::size_t detail::retargetBakeCount() { return bakes.load(std::memory_order_relaxed); }

void validateDisplayMap(const DisplayMap& map) {
  validateMesh(map.source, "source");
  validateMesh(map.target, "target");
}

RetargetMap bakeRetargetMap(const DisplayMap& map, int resolution, const BakeOptions& options,
                            BakeTimings* timings) {
  RetargetMap result;
  bakeRetargetMapInto(map, resolution, options, result, timings);
  return result;
}

void bakeRetargetMapInto(const DisplayMap& map, int resolution, const BakeOptions& options,
                         RetargetMap& result, BakeTimings* timings) {
  if (resolution < 1 || resolution > kMaxResolution)
    throw Error(ErrorCode::InvalidInput, "bake resolution must be between 1 and " +
                                             std::to_string(kMaxResolution) + " texels, got " +
                                             std::to_string(resolution));
  if (!isFinite(options.reference))
    throw Error(ErrorCode::InvalidInput, "bake reference point is not finite");
  validateDisplayMap(map);
  bakes.fetch_add(1, std::memory_order_relaxed);
  BakeTimings t;
  const auto start = SteadyClock::now();
  auto stage = SteadyClock::now();
  const bool smooth = options.interpolation == MapInterpolation::Mobius;
  const int bands = (resolution + detail::kRasterBandRows - 1) / detail::kRasterBandRows;
  std::unique_ptr<Progress> progress;
  if (options.showProgress) progress = std::make_unique<Progress>("bake", 12 * bands, true);
  result.reference = options.reference;
  for (CubeMap* cube : {&result.ray, &result.geom})
    if (cube->faceSize != resolution) *cube = CubeMap(resolution);
  // ray: from the target (physical directions) to the source; geom: the other way round.
  std::vector<std::uint8_t> rayCovered, geomCovered;
  std::optional<detail::DiskLocator> sourceLocator, targetLocator;
  if (smooth) {
    // Both point-location structures at once (a tracked head re-bakes: wall time counts).
    std::optional<detail::MobiusBlend> sourceBlend, targetBlend;
    detail::parallelFor(2, options.threads, [&](std::size_t which) {
      if (which == 0) {
        sourceLocator.emplace(map.source.disk, map.source.triangles);
        sourceBlend.emplace(map.source);
      } else {
        targetLocator.emplace(map.target.disk, map.target.triangles);
        targetBlend.emplace(map.target);
      }
    });
    t.locators = secondsSince(stage);
    auto bakeDirection = [&](bool ray, CubeMap& out, std::vector<std::uint8_t>& covered) {
      const auto directionStart = SteadyClock::now();
      detail::bakeDirectionMapSmooth(ray ? map.target : map.source, ray ? map.source : map.target,
                                     ray ? *targetBlend : *sourceBlend,
                                     ray ? *sourceBlend : *targetBlend,
                                     ray ? *sourceLocator : *targetLocator, options.threads, out,
                                     covered, progress.get());
      return secondsSince(directionStart);
    };
    t.ray = bakeDirection(true, result.ray, rayCovered);
    t.geom = bakeDirection(false, result.geom, geomCovered);
  } else {
    // Each of two threads builds one disk's locator and the pass that reads it (its codomain
    // frames, vertex hints and raster bins); then the raster tasks of both passes share one
    // parallel loop, so that no thread waits at a barrier between the passes.
    std::optional<DirectionPass> rayPass, geomPass;
    detail::parallelFor(2, options.threads, [&](std::size_t which) {
      if (which == 0) {
        sourceLocator.emplace(map.source.disk, map.source.triangles);
        rayPass.emplace(map.target, map.source, *sourceLocator, result.ray, rayCovered);
      } else {
        targetLocator.emplace(map.target.disk, map.target.triangles);
        geomPass.emplace(map.source, map.target, *targetLocator, result.geom, geomCovered);
      }
    });
    t.locators = secondsSince(stage);
    stage = SteadyClock::now();
    const std::size_t rayTasks = rayPass->taskCount();
    std::atomic<double> raySeconds{0.0}, geomSeconds{0.0};
    detail::parallelFor(rayTasks + geomPass->taskCount(), options.threads, [&](std::size_t task) {
      const auto taskStart = SteadyClock::now();
      const bool ray = task < rayTasks;
      if (ray) rayPass->runTask(task);
      else geomPass->runTask(task - rayTasks);
      std::atomic<double>& seconds = ray ? raySeconds : geomSeconds;
      seconds.fetch_add(secondsSince(taskStart), std::memory_order_relaxed);
      if (progress) progress->advance();
    });
    // The joint loop's wall time, shared out in proportion to each pass's task time.
    const double joint = secondsSince(stage), busy = raySeconds + geomSeconds;
    t.ray = busy > 0 ? joint * raySeconds / busy : 0.5 * joint;
    t.geom = joint - t.ray;
  }
  stage = SteadyClock::now();
  detail::parallelFor(2, options.threads, [&](std::size_t which) {
    CubeMap& cube = which == 0 ? result.ray : result.geom;
    const std::vector<std::uint8_t>& covered = which == 0 ? rayCovered : geomCovered;
    detail::extendPastBoundary(cube, covered);
    // Uncovered texels are invalid; a reused map may hold an earlier bake's alpha there.
    // Never NaN: every path above normalises a non-zero vector, but a broken invariant must not
    // reach a renderer. v - v is 0 for a finite v and NaN otherwise, so `probe` stays 0 exactly
    // when every direction is finite (alpha is 0 or 1); the same pass as alpha, unlike a
    // separate isfinite scan of all four channels.
    const std::size_t perFace = static_cast<std::size_t>(resolution) * resolution;
    float probe = 0.0f;
    for (int f = 0; f < 6; ++f) {
      float* texel = cube.faces[f].pixels.data();
      const std::uint8_t* mark = covered.data() + f * perFace;
      for (std::size_t i = 0; i < perFace; ++i, texel += 4) {
        if (!mark[i]) texel[3] = 0.0f;
        probe += (texel[0] - texel[0]) + (texel[1] - texel[1]) + (texel[2] - texel[2]);
      }
    }
    if (probe != 0.0f) throw Error(ErrorCode::Internal, "bake produced a non-finite texel");
  });
  t.extend = secondsSince(stage);
  if (progress) progress->finish();
  t.total = secondsSince(start);
  if (timings) *timings = t;
}

}  // namespace confvis
