// Map error against a reference and kinks of straight lines (map_accuracy.hpp).
#include "confvis/conformal/map_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "disk_locator.hpp"
#include "map_accuracy_detail.hpp"
#include "parallel_for.hpp"
#include "smooth_interpolation.hpp"
#include "sphere_locator.hpp"

namespace confvis {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

Vec3d someTangent(const Vec3d& v) {
  const Vec3d a = std::abs(v.y) < 0.9 ? Vec3d(0, 1, 0) : Vec3d(1, 0, 0);
  return normalized(cross(v, a));
}

}  // namespace

DisplayMapEvaluator::DisplayMapEvaluator(const DisplayMap& map, MapInterpolation interpolation)
    : map_(map),
      sourceSphere_(std::make_unique<detail::SphereLocator>(map.source.sphere, map.source.triangles)),
      targetSphere_(std::make_unique<detail::SphereLocator>(map.target.sphere, map.target.triangles)),
      sourceDisk_(std::make_unique<detail::DiskLocator>(map.source.disk, map.source.triangles)),
      targetDisk_(std::make_unique<detail::DiskLocator>(map.target.disk, map.target.triangles)) {
  if (interpolation == MapInterpolation::Mobius) {
    sourceBlend_ = std::make_unique<detail::MobiusBlend>(map.source);
    targetBlend_ = std::make_unique<detail::MobiusBlend>(map.target);
  }
}

DisplayMapEvaluator::~DisplayMapEvaluator() = default;

std::optional<DisplayMapEvaluator::Image> DisplayMapEvaluator::evaluate(const Vec3d& d,
                                                                       bool ray) const {
  const SphereDiskMesh& domain = ray ? map_.target : map_.source;
  const SphereDiskMesh& codomain = ray ? map_.source : map_.target;
  const detail::SphereLocator& sphere = ray ? *targetSphere_ : *sourceSphere_;
  const detail::DiskLocator& disk = ray ? *sourceDisk_ : *targetDisk_;
  const detail::SphereLocator::Hit hit = sphere.locate(normalized(d));
  if (hit.triangle < 0) return std::nullopt;
  const detail::MobiusBlend* domainBlend = ray ? targetBlend_.get() : sourceBlend_.get();
  const detail::MobiusBlend* codomainBlend = ray ? sourceBlend_.get() : targetBlend_.get();
  std::complex<double> z = 0;
  const auto& corners = domain.triangles[hit.triangle];
  if (domainBlend) z = domainBlend->toDisk(hit.triangle, hit.barycentric, normalized(d));
  else
    for (int i = 0; i < 3; ++i) z += hit.barycentric[i] * domain.disk[corners[i]];
  int hint = -1;
  const detail::DiskLocator::Hit image = disk.locate(z, hint);
  const auto& to = codomain.triangles[image.triangle];
  Vec3d sum{0.0};
  if (codomainBlend)  // outside the codomain's polygon: extended by the nearest blend, as the bake
    sum = codomainBlend->toSphere(image.triangle, image.barycentric, z);
  else
    for (int i = 0; i < 3; ++i) sum += image.barycentric[i] * codomain.sphere[to[i]];
  return Image{normalized(sum), hit.triangle, image.triangle};
}

std::optional<DisplayMapEvaluator::Image> DisplayMapEvaluator::toVirtual(const Vec3d& d) const {
  return evaluate(d, true);
}

std::optional<DisplayMapEvaluator::Image> DisplayMapEvaluator::toPhysical(const Vec3d& v) const {
  return evaluate(v, false);
}

std::vector<Vec3d> singularCorners(const DisplayMap& map, double minTurn) {
  // Boundary vertices of `mesh` whose angle (sum of the chord triangles' angles) is off π.
  auto corners = [minTurn](const SphereDiskMesh& mesh) {
    std::vector<double> angle(mesh.sphere.size(), 0.0);
    for (const auto& t : mesh.triangles)
      for (int i = 0; i < 3; ++i) {
        const Vec3d& p = mesh.sphere[t[i]];
        angle[t[i]] +=
            angleBetween(mesh.sphere[t[(i + 1) % 3]] - p, mesh.sphere[t[(i + 2) % 3]] - p);
      }
    std::vector<int> out;
    for (int v : mesh.boundary)
      if (std::abs(angle[v] - std::numbers::pi) > minTurn) out.push_back(v);
    return out;
  };
  std::vector<Vec3d> out;
  for (int v : corners(map.target)) out.push_back(map.target.sphere[v]);
  // The source's corners (cut leaves and the copies of the cut's centres) where T_geom puts them.
  const DisplayMapEvaluator eval(map);
  for (int v : corners(map.source)) {
    const auto image = eval.toPhysical(map.source.sphere[v]);
    if (!image) continue;
    bool known = false;
    // A cut leaf lands on (or within the alignment's leaf offset of) its display corner.
    for (const Vec3d& d : out) known |= angleBetween(d, image->direction) < kDegree;
    if (!known) out.push_back(image->direction);
  }
  return out;
}

MapError measureMapError(const DisplayConfig& config, const DisplayMap& test,
                         const DisplayMap& reference, int samplesPerSide, int threads,
                         MapInterpolation testInterpolation,
                         MapInterpolation referenceInterpolation) {
  const DisplayMapEvaluator testMap(test, testInterpolation),
      referenceMap(reference, referenceInterpolation);
  const Vec3d c = config.reference;
  const int n = samplesPerSide;
  std::vector<std::vector<detail::WallSample>> rows(config.walls.size() * n);
  detail::forEachWallGridPoint(config, n, threads, [&](std::size_t row, const Wall& lit,
                                                      const detail::WallGridPoint& at) {
    const auto v = testMap.toVirtual(at.p - c);
    if (!v) return;
    const std::optional<Vec3d> q = detail::shownAt(config, referenceMap, lit, v->direction);
    if (!q) return;
    rows[row].push_back({norm(*q - at.p) / at.pitch, at.wall, at.s, at.t});
  });
  return detail::summarizeWallSamples(config, rows);
}

std::vector<double> kinkTurns(const DisplayMapEvaluator& eval, const std::vector<VirtualLine>& lines,
                              double half, double step, const std::vector<Vec3d>& excluded,
                              double excludeDegrees, int threads) {
  using Image = DisplayMapEvaluator::Image;
  const double cosExclude = std::cos(excludeDegrees * kDegree);
  // An image moving this much in one step jumped (across the source's cut), not crossed an edge.
  const double jump = 50 * step;
  auto same = [](const Image& x, const Image& y) {
    return x.domainTriangle == y.domainTriangle && x.codomainTriangle == y.codomainTriangle;
  };
  std::vector<std::vector<double>> turns(lines.size());
  detail::parallelFor(lines.size(), threads, [&](std::size_t task) {
    const VirtualLine& line = lines[task];
    auto at = [&](double s) {
      return eval.toPhysical(std::cos(s) * line.point + std::sin(s) * line.tangent);
    };
    // One-sided tangent beside s0 towards `dir`: from two points at delta and 2 delta inside one
    // element (the locators of the sphere and of the disk may disagree within rounding of an
    // edge, a sliver the tangent steps over), and the image at delta.
    struct Side {
      Vec3d tangent;
      Image image;
      double s;
    };
    auto side = [&](double s0, double dir) -> std::optional<Side> {
      for (double delta = 1e-7; delta >= 1e-10; delta *= 0.1) {
        const auto q1 = at(s0 + dir * delta), q2 = at(s0 + dir * 2 * delta);
        if (q1 && q2 && same(*q1, *q2))
          return Side{dir * (q2->direction - q1->direction), *q1, s0 + dir * delta};
      }
      return std::nullopt;
    };
    std::optional<Image> prev = at(-half);
    double sPrev = -half;
    for (int i = 1; sPrev < half; ++i) {
      const double sNext = std::min(half, -half + i * step);
      const auto next = at(sNext);
      // Every element boundary between sPrev and sNext, one after another.
      while (prev && next && !same(*prev, *next) && sPrev < sNext) {
        if (angleBetween(prev->direction, next->direction) > jump) break;
        double lo = sPrev, hi = sNext;
        std::optional<Image> loImage = prev, hiImage = next;
        while (hi - lo > 1e-13) {
          const double mid = 0.5 * (lo + hi);
          const auto m = at(mid);
          if (m && same(*m, *prev)) lo = mid, loImage = m;
          else hi = mid, hiImage = m;
        }
        if (!hiImage) break;
        const auto left = side(lo, -1.0);
        const auto right = side(hi, 1.0);
        if (!right) break;
        const Vec3d x = loImage->direction;
        bool near = false;
        for (const Vec3d& e : excluded) near |= dot(e, x) > cosExclude;
        if (left && !near) {
          const Vec3d l = left->tangent - dot(left->tangent, x) * x;
          const Vec3d r = right->tangent - dot(right->tangent, x) * x;
          turns[task].push_back(angleBetween(l, r) / kDegree);
        }
        prev = right->image;
        sPrev = right->s;
      }
      prev = next;
      sPrev = sNext;
    }
  });
  std::vector<double> all;
  for (const auto& t : turns) all.insert(all.end(), t.begin(), t.end());
  return all;
}

KinkStats measureKinks(const DisplayConfig& config, const DisplayMap& map, int linesPerSide,
                       double arcDegrees, double stepDegrees, double excludeDegrees,
                       int threads, MapInterpolation interpolation) {
  const DisplayMapEvaluator eval(map, interpolation);
  const Vec3d c = config.reference;
  const int n = linesPerSide;
  std::vector<VirtualLine> lines;
  for (const Wall& wall : config.walls) {
    const Wall lit = wall.litRectangle();
    for (int k = 0; k < n * n; ++k) {
      const auto start = eval.toVirtual(lit.pointAt((k % n + 0.5) / n, (k / n + 0.5) / n) - c);
      if (!start) continue;
      const Vec3d v0 = start->direction;
      const Vec3d a = someTangent(v0), b = cross(v0, a);
      for (int line = 0; line < 2; ++line) {
        // Directions spread over the half-turn by the golden angle.
        const double theta = std::fmod((2 * k + line) * 2.39996322972865332, std::numbers::pi);
        lines.push_back({v0, std::cos(theta) * a + std::sin(theta) * b});
      }
    }
  }
  std::vector<double> turns = kinkTurns(eval, lines, 0.5 * arcDegrees * kDegree,
                                        stepDegrees * kDegree, singularCorners(map),
                                        excludeDegrees, threads);
  KinkStats out;
  detail::fillPercentiles(turns, out);
  out.lines = lines.size();
  return out;
}

}  // namespace confvis
