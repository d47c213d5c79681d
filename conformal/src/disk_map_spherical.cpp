// The spherical disk-map route: zero target curvature at every vertex, boundary included, makes
// the mesh a hemisphere (area 2π by Gauss-Bonnet, geodesic boundary: doubled along it, the
// mesh would be a smooth closed spherical surface, i.e. the round sphere). Developed onto the
// unit sphere, the boundary lies on a great circle; stereographic projection from the pole
// outside the mesh sends that hemisphere conformally onto the unit disk.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <numbers>

#include "confvis/base/error.hpp"
#include "disk_map_layout.hpp"
#include "disk_map_routes.hpp"

namespace confvis::conformal::detail {
namespace {

using Point = Eigen::Vector3d;

// Develops the spherical metric onto the unit sphere, faces counter-clockwise seen from
// outside.
std::vector<Point> layOutOnSphere(const IntrinsicTriangulation& tri,
                                  const std::vector<double>& lengths) {
  auto placeFirstEdge = [&](std::array<Point, 3>& corner) {
    const double l = lengths[tri.faceEdges[0][2]];
    corner[0] = Point(0, 0, 1);
    corner[1] = Point(std::sin(l), 0, std::cos(l));
  };
  // From c2, along the great circle that leaves towards c1 turned clockwise (seen from
  // outside) by the corner angle at c2, as far as the side c2–c0.
  auto placeThird = [&](int f, int c0, std::array<Point, 3>& corner) {
    const int c1 = (c0 + 1) % 3, c2 = (c0 + 2) % 3;
    const auto& fe = tri.faceEdges[f];
    const double base = lengths[fe[c0]], toC2 = lengths[fe[c1]], toC1 = lengths[fe[c2]];
    const double angle = curvedCornerAngle(Geometry::Spherical, toC1, base, toC2);
    const Point& p2 = corner[c2];
    const Point tangent = (corner[c1] - corner[c1].dot(p2) * p2).normalized();
    const Point normal = p2.cross(tangent);  // tangent turned counter-clockwise
    const Point direction = std::cos(angle) * tangent - std::sin(angle) * normal;
    corner[c0] = (std::cos(toC2) * p2 + std::sin(toC2) * direction).normalized();
  };
  return vertexPositions(tri, developFaces<Point>(tri, {}, placeFirstEdge, placeThird));
}

// Adds to metric.u the factor of z^(π/α) around each boundary corner of angle α off π by more
// than 0.3, (π/α − 1)·log|p − q| on the embedded points (copies of one point, a cut's centre,
// count once with their mean exponent), smoothed over 0.22 of the corner's mean side as the
// Euclidean flattening guess does (disk_map_initial_guess.cpp). A cone whose triangles the guess
// leaves invalid is halved, up to 4 times, then dropped.
void addCornerGuess(const IntrinsicTriangulation& tri, const std::vector<Vec3d>& points,
                    CirclePackingMetric& metric) {
  const std::vector<double> curvature = vertexCurvature(tri, metric);
  std::vector<double> sideSum(tri.vertexCount, 0.0);
  std::vector<int> sides(tri.vertexCount, 0);
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = tri.faceVertices[f][k];
      if (!tri.vertexOnBoundary[v]) continue;
      for (int j : {1, 2}) sideSum[v] += norm(points[tri.faceVertices[f][(k + j) % 3]] - points[v]);
      sides[v] += 2;
    }
  struct Cone {
    Vec3d position;
    double exponent, smoothing2;
    int copies;
  };
  std::vector<Cone> cones;
  for (int v = 0; v < tri.vertexCount; ++v) {
    const double angle = std::numbers::pi - curvature[v];  // boundary: K = π − angle
    if (!tri.vertexOnBoundary[v] || std::abs(angle - std::numbers::pi) < 0.3) continue;
    const double radius = 0.22 * sideSum[v] / sides[v];
    auto same = std::find_if(cones.begin(), cones.end(), [&](const Cone& c) {
      return norm(c.position - points[v]) <= 1e-9 * radius;
    });
    if (same == cones.end()) {
      cones.push_back({points[v], std::numbers::pi / angle - 1, radius * radius, 1});
    } else {
      same->exponent += std::numbers::pi / angle - 1;
      same->smoothing2 += radius * radius;
      ++same->copies;
    }
  }
  for (Cone& c : cones) c.exponent /= c.copies, c.smoothing2 /= c.copies;
  const std::vector<double> start = metric.u;
  std::vector<double> scale(cones.size(), 1.0);
  for (int attempt = 0; attempt <= 5 * static_cast<int>(cones.size()); ++attempt) {
    for (int v = 0; v < tri.vertexCount; ++v) {
      double g = 0;
      for (std::size_t k = 0; k < cones.size(); ++k) {
        const Vec3d d = points[v] - cones[k].position;
        g += scale[k] * 0.5 * cones[k].exponent * std::log(dot(d, d) + cones[k].smoothing2);
      }
      metric.u[v] = start[v] + g;
    }
    std::vector<int> invalid;
    try {
      const std::vector<double> l = metricEdgeLengths(tri, metric);
      for (int f = 0; f < tri.faceCount(); ++f) {
        const double a = l[tri.faceEdges[f][0]], b = l[tri.faceEdges[f][1]],
                     c = l[tri.faceEdges[f][2]];
        if (!(a < b + c && b < a + c && c < a + b && a + b + c < 2 * std::numbers::pi))
          invalid.push_back(f);
      }
    } catch (const Error&) {  // an edge without a length: blame every cone
      for (std::size_t k = 0; k < cones.size(); ++k) scale[k] = scale[k] > 0.07 ? scale[k] / 2 : 0;
      continue;
    }
    if (invalid.empty()) return;
    for (int f : invalid) {
      const Vec3d& p = points[tri.faceVertices[f][0]];
      std::size_t nearest = 0;
      for (std::size_t k = 1; k < cones.size(); ++k)
        if (norm(p - cones[k].position) < norm(p - cones[nearest].position)) nearest = k;
      scale[nearest] = scale[nearest] > 0.07 ? scale[nearest] / 2 : 0;
    }
  }
  metric.u = start;
}

// Adds to metric.u, per vertex, the mean log ratio of its edges' lengths on the hemisphere that
// `guess` (a disk map of the same mesh) lifts to by inverse stereographic projection, to their
// current lengths. Left unchanged if that leaves a triangle invalid.
void addHemisphereGuess(const IntrinsicTriangulation& tri,
                        const std::vector<std::complex<double>>& guess,
                        CirclePackingMetric& metric) {
  std::vector<Point> lifted(guess.size());
  for (std::size_t v = 0; v < guess.size(); ++v) {
    const double r2 = std::norm(guess[v]);
    lifted[v] = Point(2 * guess[v].real(), 2 * guess[v].imag(), 1 - r2) / (1 + r2);
  }
  const std::vector<double> current = metricEdgeLengths(tri, metric);
  std::vector<double> sum(tri.vertexCount, 0.0);
  std::vector<int> count(tri.vertexCount, 0);
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const auto [a, b] = tri.edgeVertices[e];
    const double target = 2 * std::asin(std::min(1.0, 0.5 * (lifted[a] - lifted[b]).norm()));
    if (!(target > 0) || !(current[e] > 0)) continue;
    const double logRatio = std::log(target / current[e]);
    for (int v : {a, b}) sum[v] += logRatio, ++count[v];
  }
  const std::vector<double> start = metric.u;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (count[v] > 0) metric.u[v] += sum[v] / count[v];
  try {
    const std::vector<double> l = metricEdgeLengths(tri, metric);
    for (const auto& fe : tri.faceEdges) {
      const double a = l[fe[0]], b = l[fe[1]], c = l[fe[2]];
      if (!(a < b + c && b < a + c && c < a + b && a + b + c < 2 * std::numbers::pi))
        throw Error(ErrorCode::Unreachable, "invalid");
    }
  } catch (const Error&) {
    metric.u = start;
  }
}

// The spherical energy is not convex: from a mesh far from a hemisphere (a lopsided disk) the
// flow straight to zero curvature can stall in a local minimum of |K̄ - K|. Then the target
// moves there by continuation, K̄(s) = (1 - s)·K₀ from the initial curvature K₀ (every stage
// admissible: Σ K̄(s) < 2π), the step in s halved after a stall and doubled after a success,
// intermediate stages to a loose tolerance.
RicciFlowReport flowToHemisphere(IntrinsicTriangulation& tri, CirclePackingMetric& metric,
                                 const RicciFlowOptions& options, int maxStalledStages) {
  const std::vector<double> initial = vertexCurvature(tri, metric);
  RicciFlowReport total;
  double reached = 0, step = 1;
  while (reached < 1) {
    const double s = std::min(1.0, reached + step);
    std::vector<double> target(initial.size());
    for (std::size_t v = 0; v < target.size(); ++v) target[v] = (1 - s) * initial[v];
    RicciFlowOptions stage = options;
    if (s < 1) stage.tolerance = std::max(options.tolerance, 1e-6);
    // A stage that converges takes under 10 Newton steps (measured: 3-8); one that has not
    // after 20 is crawling through a non-convex region (lopsided disks: 100 steps at an error
    // of ~0.3 twice, before the continuation took 24), so a smaller step in s is cheaper.
    stage.maxIterations = std::min(options.maxIterations, 20);
    const IntrinsicTriangulation savedTri = tri;
    const CirclePackingMetric savedMetric = metric;
    try {
      accumulateFlowReport(total, runRicciFlow(tri, metric, target, stage));
      reached = s;
      step *= 2;
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Unreachable || --maxStalledStages < 0) throw;
      tri = savedTri;
      metric = savedMetric;
      // A quarter of the distance that failed (not of the step before it: after a success
      // doubled the step past the end, step / 4 retried the same final stage).
      step = (s - reached) / 4;
      if (step < 1.0 / 1024)
        throw Error(ErrorCode::Unreachable,
                    std::string("spherical disk map: the flow to a hemisphere stalls (") +
                        e.what() + ") even by continuation from the initial curvature");
    }
  }
  return total;
}

}  // namespace

DiskMap sphericalDiskMap(const std::vector<Vec3d>& points, const IntrinsicTriangulation& whole,
                         const DiskMapOptions& options) {
  DiskMap result;
  result.geometry = Geometry::Spherical;
  IntrinsicTriangulation tri = whole;  // flips change it
  CirclePackingMetric metric = initialMetric(
      tri, lengthsScaledToArea(tri, points, 2 * std::numbers::pi), options.scheme,
      Geometry::Spherical);
  if (!options.hemisphereGuess.empty()) {
    if (options.hemisphereGuess.size() != static_cast<std::size_t>(tri.vertexCount))
      throw Error(ErrorCode::InvalidInput, "spherical disk map: the hemisphere guess has " +
                                               std::to_string(options.hemisphereGuess.size()) +
                                               " points for " + std::to_string(tri.vertexCount) +
                                               " vertices");
    addHemisphereGuess(tri, options.hemisphereGuess, metric);
  } else if (options.cornerGuess) {
    addCornerGuess(tri, points, metric);
  }
  result.flow =
      flowToHemisphere(tri, metric, diskMapFlowOptions(options), options.maxStalledStages);
  result.usedFlips = result.flow.flipsStartedAt >= 0;
  const std::vector<Point> p = layOutOnSphere(tri, metricEdgeLengths(tri, metric));

  // The boundary's great circle: its plane through the centre is the one the boundary
  // vertices are closest to (least squares); the pole on the mesh's side.
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  Point mean = Point::Zero();
  for (int v = 0; v < tri.vertexCount; ++v) {
    if (tri.vertexOnBoundary[v]) scatter += p[v] * p[v].transpose();
    mean += p[v];
  }
  Point pole = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  if (pole.dot(mean) < 0) pole = -pole;
  // A right-handed frame (e1, e2, pole): seen from outside above the pole, the projection keeps
  // the counter-clockwise order.
  const Point e1 = pole.unitOrthogonal(), e2 = pole.cross(e1);
  result.uv.resize(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) {
    const double height = p[v].dot(pole);
    if (!(height > -0.5))
      throw Error(ErrorCode::Internal, "spherical layout is not a hemisphere (vertex " +
                                           std::to_string(v) + ")");
    result.uv[v] = std::complex<double>(p[v].dot(e1), p[v].dot(e2)) / (1 + height);
  }
  return result;
}

}  // namespace confvis::conformal::detail
