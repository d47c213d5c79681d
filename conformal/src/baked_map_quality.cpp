#include "confvis/conformal/baked_map_quality.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "confvis/base/error.hpp"
#include "cube_texels.hpp"
#include "cut_aware_lookup.hpp"

namespace confvis {

namespace {

Vec3d storedDirection(const CubeMap& map, const TexelRef& t) {
  const float* p = map.face(t.face).at(t.x, t.y);
  const Vec3d v{p[0], p[1], p[2]};
  const double length = norm(v);
  return length > 0 ? (1.0 / length) * v : v;
}

bool isValid(const CubeMap& map, const TexelRef& t) { return map.face(t.face).at(t.x, t.y)[3] >= 0.5f; }

double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0;
  const auto i = static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1) + 0.5);
  return sorted[std::min(i, sorted.size() - 1)];
}

void requireMap(const CubeMap& map, const char* what) {
  if (map.faceSize <= 0)
    throw Error(ErrorCode::InvalidInput, std::string(what) + ": empty cube map");
  for (const ImageRGBA& f : map.faces)
    if (f.width != map.faceSize || f.height != map.faceSize)
      throw Error(ErrorCode::InvalidInput, std::string(what) + ": malformed cube map");
}

// Largest angle between the directions a bilinear lookup of `dir` in `map` blends (beyond a
// face edge, the neighbouring-face texels standing in for the missing ones).
double footprintSpread(const CubeMap& map, const Vec3d& dir) {
  const int n = map.faceSize;
  CubeFace face;
  double x, y;
  directionToTexel(dir, n, face, x, y);
  const int x0 = static_cast<int>(std::floor(x - 0.5)), y0 = static_cast<int>(std::floor(y - 0.5));
  std::array<Vec3d, 32> blended;
  int count = 0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const TexelStandIn standIn = texelAcrossFaceEdge(face, x0 + i, y0 + j, n);
      for (int k = 0; k < standIn.count; ++k)
        blended[count++] = storedDirection(map, standIn.texels[k].texel);
    }
  double spread = 0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j)
      spread = std::max(spread, angleBetween(blended[i], blended[j]));
  return spread;
}

// Symmetric 2x2 Gram matrix of two 3-vectors.
struct Gram {
  double a11, a12, a22;
};
Gram gram(const Vec3d& u, const Vec3d& v) { return {dot(u, u), dot(u, v), dot(v, v)}; }

}  // namespace

BakedConformality measureBakedConformality(const CubeMap& map, const ConformalityOptions& options) {
  requireMap(map, "measureBakedConformality");
  const int n = map.faceSize;
  const int stride = std::max(1, options.stride);
  std::vector<std::uint8_t> validMask(6 * static_cast<std::size_t>(n) * n);
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        validMask[detail::texelIndex(face, x, y, n)] = isValid(map, {face, x, y});
  const auto cap = static_cast<std::uint8_t>(std::clamp(options.margin + 1, 1, 255));
  const std::vector<std::uint8_t> distance = detail::distanceToUnmasked(validMask, n, cap);

  BakedConformality stats;
  std::vector<double> ratios;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; y += stride)
      for (int x = 0; x < n; x += stride) {
        const std::size_t index = detail::texelIndex(face, x, y, n);
        if (!validMask[index]) continue;
        if (distance[index] <= options.margin) {
          ++stats.nearBoundary;
          continue;
        }
        // Central differences of the texel directions d and their images f.
        const Vec3d d0 = normalized(texelDirection(face, x, y, n));
        const Vec3d f0 = storedDirection(map, {face, x, y});
        std::array<Vec3d, 4> dStep, fStep;  // one-sided: +x, -x, +y, -y
        for (int k = 0; k < 4; ++k) {
          const TexelRef t =
              detail::neighbourTexel(face, x, y, detail::kNeighbourSteps[k][0], detail::kNeighbourSteps[k][1], n);
          dStep[k] = normalized(texelDirection(t.face, t.x, t.y, n)) - d0;
          fStep[k] = storedDirection(map, t) - f0;
        }
        const std::array<Vec3d, 2> dDiff{dStep[0] - dStep[1], dStep[2] - dStep[3]};
        const std::array<Vec3d, 2> fDiff{fStep[0] - fStep[1], fStep[2] - fStep[3]};
        // Singular values squared = generalised eigenvalues of (F^T F, D^T D).
        const Gram g = gram(dDiff[0], dDiff[1]), h = gram(fDiff[0], fDiff[1]);
        const double detG = g.a11 * g.a22 - g.a12 * g.a12;
        // The central-difference Jacobian J (F = J D) must also predict each one-sided step;
        // across a jump or a branch point it does not. J u = F (D^T D)^-1 D^T u.
        bool jump = !(detG > 0);
        for (int k = 0; k < 4 && !jump; ++k) {
          const double a = dot(dDiff[0], dStep[k]), b = dot(dDiff[1], dStep[k]);
          const double c0 = (g.a22 * a - g.a12 * b) / detG, c1 = (g.a11 * b - g.a12 * a) / detG;
          const Vec3d predicted = c0 * fDiff[0] + c1 * fDiff[1];
          if (norm(fStep[k] - predicted) > options.discontinuityTolerance * norm(predicted) + 1e-12)
            jump = true;
        }
        if (jump) {
          ++stats.discontinuous;
          continue;
        }
        const double detH = h.a11 * h.a22 - h.a12 * h.a12;
        const double mid = h.a11 * g.a22 + h.a22 * g.a11 - 2 * h.a12 * g.a12;
        const double disc = std::sqrt(std::max(0.0, mid * mid - 4 * detG * detH));
        const double large = (mid + disc) / (2 * detG), small = (mid - disc) / (2 * detG);
        const double ratio = small > 0 ? std::sqrt(large / small) : 1e9;
        ratios.push_back(std::isfinite(ratio) ? ratio : 1e9);
        const double orientD = dot(d0, cross(dDiff[0], dDiff[1]));
        const double orientF = dot(f0, cross(fDiff[0], fDiff[1]));
        if (!(orientD * orientF > 0)) ++stats.flipped;
      }
  stats.measured = ratios.size();
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    double sum = 0;
    for (double r : ratios) sum += r;
    stats.ratioMean = sum / static_cast<double>(ratios.size());
    stats.ratioP50 = percentile(ratios, 0.50);
    stats.ratioP95 = percentile(ratios, 0.95);
    stats.ratioP99 = percentile(ratios, 0.99);
    stats.ratioMax = ratios.back();
  }
  return stats;
}

namespace {

// 4-neighbour distance (capped) of every texel to the nearest edge of `map`: an invalid texel or
// one whose stored direction jumps by more than `jump` radians to a valid neighbour.
std::vector<std::uint8_t> distanceToEdge(const CubeMap& map, double jump, std::uint8_t cap) {
  const int n = map.faceSize;
  std::vector<std::uint8_t> smooth(6 * static_cast<std::size_t>(n) * n);
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        bool ok = isValid(map, {face, x, y});
        const Vec3d v = storedDirection(map, {face, x, y});
        for (int k = 0; k < 4 && ok; ++k) {
          const TexelRef t = detail::neighbourTexel(face, x, y, detail::kNeighbourSteps[k][0],
                                                    detail::kNeighbourSteps[k][1], n);
          ok = !isValid(map, t) || angleBetween(v, storedDirection(map, t)) <= jump;
        }
        smooth[detail::texelIndex(face, x, y, n)] = ok;
      }
  return detail::distanceToUnmasked(smooth, n, cap);
}

void summarise(std::vector<double>& errors, RoundTripErrors& stats) {
  stats.measured = errors.size();
  std::sort(errors.begin(), errors.end());
  const std::size_t valid = stats.valid();
  const auto below = static_cast<std::size_t>(
      std::lower_bound(errors.begin(), errors.end(), 1.0) - errors.begin());
  stats.fractionBelowOneTexel = valid ? static_cast<double>(below) / static_cast<double>(valid) : 0;
  stats.p50 = percentile(errors, 0.5);
  stats.p95 = percentile(errors, 0.95);
  stats.p99 = percentile(errors, 0.99);
  stats.max = errors.empty() ? 0 : errors.back();
}

}  // namespace

RoundTripStats measureRoundTrip(const RetargetMap& map, RoundTrip which, int stride,
                                double discontinuityTexels, int boundaryTexels) {
  const bool rayFirst = which == RoundTrip::RayThenGeom;
  const CubeMap& forward = rayFirst ? map.ray : map.geom;
  const CubeMap& inverse = rayFirst ? map.geom : map.ray;
  requireMap(forward, "measureRoundTrip");
  requireMap(inverse, "measureRoundTrip");
  const int n = forward.faceSize, m = inverse.faceSize;
  stride = std::max(1, stride);
  boundaryTexels = std::clamp(boundaryTexels, 0, 254);
  const auto cap = static_cast<std::uint8_t>(boundaryTexels + 1);
  const std::vector<std::uint8_t> forwardEdge =
      distanceToEdge(forward, discontinuityTexels * texelAngle(n), cap);
  const std::vector<std::uint8_t> inverseEdge =
      distanceToEdge(inverse, discontinuityTexels * texelAngle(m), cap);
  RoundTripStats stats;
  stats.boundaryTexels = boundaryTexels;
  std::vector<double> all, interior, boundary;
  auto count = [&](RoundTripErrors& part, std::size_t RoundTripErrors::*counter) {
    ++(part.*counter);
    ++(stats.all.*counter);
  };
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; y += stride)
      for (int x = 0; x < n; x += stride) {
        if (!isValid(forward, {face, x, y})) continue;
        const Vec3d v = storedDirection(forward, {face, x, y});
        CubeFace imageFace;
        double ix, iy;
        directionToTexel(v, m, imageFace, ix, iy);
        const std::size_t image = detail::texelIndex(
            imageFace, std::clamp(static_cast<int>(ix), 0, m - 1),
            std::clamp(static_cast<int>(iy), 0, m - 1), m);
        const bool onBoundary = forwardEdge[detail::texelIndex(face, x, y, n)] <= boundaryTexels ||
                                inverseEdge[image] <= boundaryTexels;
        RoundTripErrors& part = onBoundary ? stats.boundary : stats.interior;
        std::vector<double>& partErrors = onBoundary ? boundary : interior;
        Vec3d back;
        double spread;
        if (rayFirst) {
          const detail::OneSidedSample s = detail::lookupGeomAcrossCut(map, v);
          if (!(s.alpha >= 0.5f)) {
            count(part, &RoundTripErrors::invalid);
            continue;
          }
          if (s.straddles) count(part, &RoundTripErrors::acrossCut);
          back = s.direction;
          spread = s.footprintSpread;
        } else {
          const std::optional<Vec3d> looked = map.toVirtual(v);
          if (!looked) {
            count(part, &RoundTripErrors::invalid);
            continue;
          }
          back = *looked;
          // The same side rule as geom's: ray magnifies strongly at the rim, which is no jump.
          const detail::OneSidedSample s = *detail::sampleOneSide(map.ray, v, 0, detail::jumpChord(m));
          if (s.straddles) count(part, &RoundTripErrors::acrossCut);
          spread = s.footprintSpread;
        }
        const double error = angleBetween(back, texelDirection(face, x, y, n)) / texelAngle(n);
        const double footprints = error / std::max(1.0, spread / texelAngle(n));
        for (RoundTripErrors* errors : {&part, &stats.all}) {
          errors->maxInFootprints = std::max(errors->maxInFootprints, footprints);
          if (footprints > 1.0) ++errors->beyondFootprint;
        }
        all.push_back(error);
        partErrors.push_back(error);
      }
  summarise(all, stats.all);
  summarise(interior, stats.interior);
  summarise(boundary, stats.boundary);
  return stats;
}

CoverageStats measureCoverage(const RetargetMap& map, double toleranceTexels, int stride) {
  requireMap(map.ray, "measureCoverage");
  requireMap(map.geom, "measureCoverage");
  const int n = map.geom.faceSize;
  stride = std::max(1, stride);
  CoverageStats stats;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; y += stride)
      for (int x = 0; x < n; x += stride) {
        if (!isValid(map.geom, {face, x, y})) continue;
        ++stats.sourceTexels;
        const Vec3d d = storedDirection(map.geom, {face, x, y});
        const std::optional<Vec3d> v = map.toVirtual(d);
        if (!v) {
          ++stats.unlit;
          continue;
        }
        const double error = angleBetween(*v, texelDirection(face, x, y, n)) / texelAngle(n);
        const double footprint = footprintSpread(map.ray, d) / texelAngle(n);
        stats.maxErrorTexels = std::max(stats.maxErrorTexels, error);
        if (error <= std::max(toleranceTexels, footprint)) ++stats.covered;
      }
  stats.fraction = stats.sourceTexels > 0 ? static_cast<double>(stats.covered) /
                                                static_cast<double>(stats.sourceTexels)
                                          : 0.0;
  return stats;
}

nlohmann::json toJson(const BakedConformality& s) {
  return {{"measured_texels", s.measured}, {"near_boundary_texels", s.nearBoundary},
          {"discontinuous_texels", s.discontinuous}, {"flipped_texels", s.flipped},
          {"ratio_mean", s.ratioMean}, {"ratio_p50", s.ratioP50}, {"ratio_p95", s.ratioP95},
          {"ratio_p99", s.ratioP99}, {"ratio_max", s.ratioMax}};
}

nlohmann::json toJson(const RoundTripErrors& s) {
  return {{"valid_texels", s.valid()}, {"measured_texels", s.measured},
          {"across_cut_texels", s.acrossCut}, {"invalid_texels", s.invalid},
          {"error_p50_texels", s.p50}, {"error_p95_texels", s.p95}, {"error_p99_texels", s.p99},
          {"error_max_texels", s.max}, {"fraction_below_one_texel", s.fractionBelowOneTexel},
          {"error_max_in_footprints", s.maxInFootprints},
          {"beyond_footprint_texels", s.beyondFootprint}};
}

nlohmann::json toJson(const RoundTripStats& s) {
  return {{"boundary_width_texels", s.boundaryTexels},
          {"all", toJson(s.all)},
          {"interior", toJson(s.interior)},
          {"boundary", toJson(s.boundary)}};
}

nlohmann::json toJson(const CoverageStats& s) {
  return {{"source_texels", s.sourceTexels}, {"covered_texels", s.covered},
          {"unlit_texels", s.unlit}, {"fraction", s.fraction},
          {"max_error_texels", s.maxErrorTexels}};
}

}  // namespace confvis
