#include "disk_map_routes.hpp"

#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"

namespace confvis::conformal::detail {

RicciFlowOptions diskMapFlowOptions(const DiskMapOptions& options) {
  RicciFlowOptions flowOptions;
  flowOptions.tolerance = options.tolerance;
  flowOptions.maxIterations = options.maxIterations;
  flowOptions.delaunayFlips = options.flips == FlipPolicy::On;
  flowOptions.flipsWhenStuck = options.flips == FlipPolicy::Auto;
  flowOptions.onIteration = options.onIteration;
  return flowOptions;
}

std::vector<double> lengthsScaledToArea(const IntrinsicTriangulation& tri,
                                        const std::vector<Vec3d>& points, double area) {
  std::vector<double> lengths = embeddedEdgeLengths(tri, points);
  double meshArea = 0;
  for (const auto& fe : tri.faceEdges) {
    const double a = lengths[fe[0]], b = lengths[fe[1]], c = lengths[fe[2]];
    meshArea += 0.25 * std::sqrt(std::max(0.0, (a + b + c) * (b + c - a) * (c + a - b) * (a + b - c)));
  }
  if (!(meshArea > 0)) throw Error(ErrorCode::InvalidInput, "mesh has zero area");
  const double scale = std::sqrt(area / meshArea);
  for (double& l : lengths) l *= scale;
  return lengths;
}

BoundaryCycle boundaryCycle(const IntrinsicTriangulation& tri) {
  // A boundary edge runs as in its face, counter-clockwise around the disk.
  std::vector<int> outgoing(tri.vertexCount, -1);
  int first = -1;
  for (int e = 0; e < tri.edgeCount(); ++e)
    if (tri.edgeOnBoundary(e)) {
      outgoing[tri.edgeVertices[e][0]] = e;
      if (first < 0) first = e;
    }
  BoundaryCycle cycle;
  for (int e = first; e >= 0;) {
    cycle.vertices.push_back(tri.edgeVertices[e][0]);
    cycle.edges.push_back(e);
    e = outgoing[tri.edgeVertices[e][1]];
    if (e == first) break;
    if (cycle.edges.size() > static_cast<std::size_t>(tri.edgeCount()))
      throw Error(ErrorCode::InvalidInput, "the mesh boundary is not a single loop");
  }
  return cycle;
}

void accumulateFlowReport(RicciFlowReport& total, const RicciFlowReport& flow) {
  total.iterations += flow.iterations;
  total.maxCurvatureError = flow.maxCurvatureError;
  total.flips += flow.flips;
  if (total.flipsStartedAt < 0 && flow.flipsStartedAt >= 0) total.flipsStartedAt = flow.flipsStartedAt;
  total.stepHalvings += flow.stepHalvings;
  total.evaluations += flow.evaluations;
  total.factorizations += flow.factorizations;
  total.symbolicAnalyses += flow.symbolicAnalyses;
  total.cgIterations += flow.cgIterations;
  total.errorHistory.insert(total.errorHistory.end(), flow.errorHistory.begin(),
                            flow.errorHistory.end());
  total.seconds.evaluation += flow.seconds.evaluation;
  total.seconds.assembly += flow.seconds.assembly;
  total.seconds.analysis += flow.seconds.analysis;
  total.seconds.factorization += flow.seconds.factorization;
  total.seconds.solve += flow.seconds.solve;
  total.seconds.flips += flow.seconds.flips;
}

double curvedCornerAngle(Geometry geometry, double opposite, double adjacent1, double adjacent2) {
  std::array<double, 3> angles;
  if (!cornerAngles(geometry, {opposite, adjacent1, adjacent2}, angles))
    throw Error(ErrorCode::Internal, "curved metric has a degenerate triangle");
  return angles[0];
}

}  // namespace confvis::conformal::detail
