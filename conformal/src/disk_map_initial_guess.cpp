#include "disk_map_initial_guess.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>


namespace confvis::conformal::detail {
namespace {

// A boundary corner to open to π: position, exponent π/α - 1, squared smoothing radius.
struct Cone {
  Vec3d position{0.0};
  double exponent;
  double smoothing2;
  int copies;
};

// Boundary corners (not of the hole) whose angle α differs from π by more than ~17°.
// Copies of one point (a cut's centre on a cut-open sphere) make one cone with their mean
// exponent: each copy's sector opens alike, so the factor is counted once around the point.
std::vector<Cone> boundaryCones(const IntrinsicTriangulation& tri, const std::vector<Vec3d>& points,
                                const std::vector<double>& lengths,
                                const std::vector<int>& inner) {
  std::vector<double> angle(tri.vertexCount, 0.0), sideSum(tri.vertexCount, 0.0);
  std::vector<int> sides(tri.vertexCount, 0);
  auto isOuterBoundary = [&](int v) {
    return tri.vertexOnBoundary[v] && std::find(inner.begin(), inner.end(), v) == inner.end();
  };
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = tri.faceVertices[f][k];
      if (!isOuterBoundary(v)) continue;
      const double a = lengths[tri.faceEdges[f][k]], b = lengths[tri.faceEdges[f][(k + 1) % 3]],
                   c = lengths[tri.faceEdges[f][(k + 2) % 3]];
      angle[v] += std::acos(std::clamp((b * b + c * c - a * a) / (2 * b * c), -1.0, 1.0));
      sideSum[v] += b + c;
      sides[v] += 2;
    }
  // The log singularity smoothed over about a fifth of the corner's mean side: over the 40 maps
  // of cave3/4/5, flat-wall and md230x6 at 20 and 10 cm, two references each, radii of 0.1,
  // 0.2, 0.22, 0.32 and 0.5 sides took 185, 182, 181, 183 and 188 Newton steps (216 unguessed;
  // measured before the CG budget floor of ricci_flow.cpp, 186 with it at 0.22).
  constexpr double kSmoothing = 0.22;
  std::vector<Cone> cones;
  for (int v = 0; v < tri.vertexCount; ++v) {
    if (!isOuterBoundary(v) || std::abs(angle[v] - std::numbers::pi) < 0.3) continue;
    const double exponent = std::numbers::pi / angle[v] - 1;
    const double radius = kSmoothing * sideSum[v] / sides[v];
    auto same = std::find_if(cones.begin(), cones.end(), [&](const Cone& c) {
      return norm(c.position - points[v]) <= 1e-9 * radius;
    });
    if (same == cones.end()) {
      cones.push_back({points[v], exponent, radius * radius, 1});
    } else {
      same->exponent += exponent;
      same->smoothing2 += radius * radius;
      ++same->copies;
    }
  }
  for (Cone& c : cones) c.exponent /= c.copies, c.smoothing2 /= c.copies;
  return cones;
}

// The faces the metric leaves invalid (all of them if an edge has no length).
std::vector<int> invalidFaces(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                              std::vector<double>& scratch) {
  std::vector<int> invalid;
  if (!euclideanEdgeLengths(tri, metric, scratch)) {
    invalid.resize(tri.faceCount());
    for (int f = 0; f < tri.faceCount(); ++f) invalid[f] = f;
    return invalid;
  }
  for (int f = 0; f < tri.faceCount(); ++f) {
    const auto& fe = tri.faceEdges[f];
    const double a = scratch[fe[0]], b = scratch[fe[1]], c = scratch[fe[2]];
    if (!(a < b + c && b < a + c && c < a + b)) invalid.push_back(f);
  }
  return invalid;
}

}  // namespace

bool euclideanEdgeLengths(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                          std::vector<double>& lengths) {
  std::vector<double> x(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) x[v] = std::exp(metric.u[v]);
  lengths.resize(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
    const double l2 = 2 * (metric.eta[e] * x[a] * x[b]) + metric.epsilon[a] * x[a] * x[a] +
                      metric.epsilon[b] * x[b] * x[b];
    if (!(l2 > 0) || !std::isfinite(l2)) return false;
    lengths[e] = std::sqrt(l2);
  }
  return true;
}

void addFlatteningGuess(const IntrinsicTriangulation& annulus, const std::vector<Vec3d>& points,
                        const std::vector<double>& lengths, const std::vector<int>& inner,
                        const Vec3d& centre, CirclePackingMetric& metric) {
  const std::vector<Cone> cones = boundaryCones(annulus, points, lengths, inner);
  const int n = annulus.vertexCount, coneCount = static_cast<int>(cones.size());
  // The log term and each cone's term apart: a cone can be weakened alone.
  std::vector<double> logTerm(n), coneTerm(static_cast<std::size_t>(n) * coneCount);
  for (int v = 0; v < n; ++v) {
    const Vec3d toCentre = points[v] - centre;
    logTerm[v] = -0.5 * std::log(dot(toCentre, toCentre));
    for (int k = 0; k < coneCount; ++k) {
      const Vec3d d = points[v] - cones[k].position;
      coneTerm[static_cast<std::size_t>(v) * coneCount + k] =
          0.5 * cones[k].exponent * std::log(dot(d, d) + cones[k].smoothing2);
    }
  }
  // Where the guess leaves triangles invalid, the factor is halved: a cone's alone where the
  // triangles are nearer to that corner than to the removed face (the corners of a fine mesh
  // sit in a few tiny triangles that a full opening inverts: lopsided disk of 100k vertices,
  // 8 faces at its four corners), else the whole guess. Nothing is left after 4 halvings.
  const std::vector<double> start = metric.u;
  std::vector<double> scratch, coneScale(coneCount, 1.0);
  double scale = 1;
  for (int attempt = 0; attempt < 4 * (coneCount + 1); ++attempt) {
    for (int v = 0; v < n; ++v) {
      double g = logTerm[v];
      for (int k = 0; k < coneCount; ++k)
        g += coneScale[k] * coneTerm[static_cast<std::size_t>(v) * coneCount + k];
      metric.u[v] = start[v] + scale * g;
    }
    const std::vector<int> invalid = invalidFaces(annulus, metric, scratch);
    if (invalid.empty()) return;
    std::vector<char> halve(coneCount, 0);
    bool halveAll = false;
    for (int f : invalid) {
      const Vec3d& p = points[annulus.faceVertices[f][0]];
      int nearest = -1;
      double nearestDistance2 = dot(p - centre, p - centre);
      for (int k = 0; k < coneCount; ++k) {
        const Vec3d d = p - cones[k].position;
        if (dot(d, d) < nearestDistance2) nearest = k, nearestDistance2 = dot(d, d);
      }
      if (nearest < 0 || coneScale[nearest] < 0.1)
        halveAll = true;
      else
        halve[nearest] = 1;
    }
    if (halveAll) scale *= 0.5;
    if (scale < 0.1) break;
    for (int k = 0; k < coneCount; ++k)
      if (halve[k]) coneScale[k] *= 0.5;
  }
  metric.u = start;
}

}  // namespace confvis::conformal::detail
