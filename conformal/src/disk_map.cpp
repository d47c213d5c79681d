#include "confvis/conformal/disk_map.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <algorithm>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mobius.hpp"
#include "disk_map_initial_guess.hpp"
#include "disk_map_layout.hpp"
#include "disk_map_routes.hpp"

namespace confvis::conformal {
namespace {

using Complex = std::complex<double>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Min-heap of vertices keyed by (distance, index), with decrease-key: a vertex sits in it at
// most once (a lazy std::priority_queue holds one entry per improvement) and the heap is 4-ary,
// so sifts are shallow. Ties settle by index, as with std::priority_queue over pairs, so the
// paths found do not depend on the heap.
class VertexHeap {
 public:
  explicit VertexHeap(int vertexCount) : slot_(vertexCount, -1) { heap_.reserve(vertexCount); }
  bool empty() const { return heap_.empty(); }
  // Inserts v with key d, or lowers its key to d.
  void decrease(int v, double d) {
    int i = slot_[v];
    if (i < 0) {
      i = static_cast<int>(heap_.size());
      heap_.push_back({d, v});
    }
    siftUp(i, {d, v});
  }
  int pop() {
    const int top = heap_[0].vertex;
    slot_[top] = -1;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) siftDown(last);
    return top;
  }

 private:
  struct Entry {
    double key;
    int vertex;
    bool operator<(const Entry& o) const {
      return key < o.key || (key == o.key && vertex < o.vertex);
    }
  };
  void place(int i, const Entry& entry) {
    heap_[i] = entry;
    slot_[entry.vertex] = i;
  }
  void siftUp(int i, const Entry& entry) {
    while (i > 0) {
      const int parent = (i - 1) / 4;
      if (!(entry < heap_[parent])) break;
      place(i, heap_[parent]);
      i = parent;
    }
    place(i, entry);
  }
  void siftDown(const Entry& entry) {  // `entry` goes in at the root
    const int n = static_cast<int>(heap_.size());
    int i = 0;
    for (;;) {
      const int first = 4 * i + 1;
      if (first >= n) break;
      int best = first;
      for (int c = first + 1; c < std::min(first + 4, n); ++c)
        if (heap_[c] < heap_[best]) best = c;
      if (!(heap_[best] < entry)) break;
      place(i, heap_[best]);
      i = best;
    }
    place(i, entry);
  }
  std::vector<Entry> heap_;
  std::vector<int> slot_;  // position in heap_, -1 when not in it
};

// Shortest distances along edges from a set of source vertices. `blocked(v)` vertices are
// never expanded (they may still be reached); `edgeAllowed(e)` filters edges. Stops when a
// vertex with `stop(v)` is settled (pass `stop` false everywhere for all distances); returns
// that vertex, or -1.
template <typename Blocked, typename EdgeAllowed, typename Stop>
int dijkstra(const IntrinsicTriangulation& tri, const std::vector<double>& lengths,
             const std::vector<int>& sources, std::vector<double>& dist,
             std::vector<int>& parentEdge, Blocked blocked, EdgeAllowed edgeAllowed, Stop stop) {
  // Incident edges per vertex with the far end and length beside each (one allocation, and
  // no look-up of the edge's vertices while relaxing), in increasing edge order.
  struct Step {
    int edge, to;
    double length;
  };
  std::vector<int> offset(tri.vertexCount + 1, 0);
  std::vector<Step> steps(2 * tri.edgeCount());
  for (const auto& ev : tri.edgeVertices) ++offset[ev[0] + 1], ++offset[ev[1] + 1];
  for (int v = 0; v < tri.vertexCount; ++v) offset[v + 1] += offset[v];
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (int e = 0; e < tri.edgeCount(); ++e) {
      const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
      steps[fill[a]++] = {e, b, lengths[e]};
      steps[fill[b]++] = {e, a, lengths[e]};
    }
  }
  dist.assign(tri.vertexCount, kInf);
  parentEdge.assign(tri.vertexCount, -1);
  VertexHeap queue(tri.vertexCount);
  for (int s : sources) {
    dist[s] = 0;
    queue.decrease(s, 0.0);
  }
  while (!queue.empty()) {
    const int v = queue.pop();
    const double d = dist[v];
    if (stop(v)) return v;
    if (blocked(v)) continue;
    for (int k = offset[v]; k < offset[v + 1]; ++k) {
      const Step& step = steps[k];
      if (!edgeAllowed(step.edge)) continue;
      if (d + step.length < dist[step.to]) {
        dist[step.to] = d + step.length;
        parentEdge[step.to] = step.edge;
        queue.decrease(step.to, dist[step.to]);
      }
    }
  }
  return -1;
}

// The face to remove: among the faces nearly as far from the boundary as the farthest (within
// 5%), the roundest. The removed face's corners carry the flow's largest initial error (their
// angle sums must open to π), and an obtuse one (angles 0.30, 0.66, 2.18 on the 100k-vertex
// lopsided benchmark disk) also leaves the flattening guess's log term far off near it: max
// initial error 2.8 -> 2.2 plain, 1.6 -> 1.2 with the guess (Yamabe, 100k). Faces between 2% and
// 10% off gave the same Newton steps at 10k and 100k for all four conformal schemes.
int faceToRemove(const IntrinsicTriangulation& tri, const std::vector<double>& lengths) {
  const std::vector<double> dist = distanceToBoundary(tri, lengths);
  auto distance = [&](int f) {
    const auto& fv = tri.faceVertices[f];
    return std::min({dist[fv[0]], dist[fv[1]], dist[fv[2]]});
  };
  double farthest = 0;
  for (int f = 0; f < tri.faceCount(); ++f) farthest = std::max(farthest, distance(f));
  if (!(farthest > 0))
    throw Error(ErrorCode::InvalidInput,
                "mesh is too coarse for a disk map: every face touches the boundary (refine it)");
  int best = -1;
  double bestRoundness = -1;
  for (int f = 0; f < tri.faceCount(); ++f) {
    if (distance(f) < 0.95 * farthest) continue;
    const auto& fe = tri.faceEdges[f];
    const double a = lengths[fe[0]], b = lengths[fe[1]], c = lengths[fe[2]];
    // 8 × (inradius / circumradius): 1 for an equilateral triangle, 0 for a degenerate one.
    const double roundness = (b + c - a) * (c + a - b) * (a + b - c) / (a * b * c);
    if (roundness > bestRoundness) bestRoundness = roundness, best = f;
  }
  return best;
}

// Develops the cut annulus into the plane face by face; returns per-corner positions.
std::vector<std::array<Complex, 3>> layOut(const IntrinsicTriangulation& tri,
                                           const std::vector<double>& lengths,
                                           const std::vector<char>& edgeCut) {
  // Third corner of face f given corners c1 = c0+1 and c2 = c0+2 already placed (CCW order):
  // in a CCW triangle c0 lies to the right of the ray c2→c1, at distance x along it (cosine
  // law) and height 2·area / |c1 c2| (Heron), so no trigonometry is needed.
  auto placeThird = [&](int f, int c0, std::array<Complex, 3>& corner) {
    const int c1 = (c0 + 1) % 3, c2 = (c0 + 2) % 3;
    const auto& fe = tri.faceEdges[f];
    const double base = lengths[fe[c0]], toC2 = lengths[fe[c1]], toC1 = lengths[fe[c2]];
    const double area4 = std::sqrt((base + toC2 + toC1) * (toC2 + toC1 - base) *
                                   (base + toC1 - toC2) * (base + toC2 - toC1));
    if (!(area4 > 0))
      throw Error(ErrorCode::Internal, "flat metric has a degenerate face " + std::to_string(f));
    const Complex side = corner[c1] - corner[c2];
    const Complex direction = side / std::sqrt(std::norm(side));  // not abs: hypot is slow
    const double x = (toC2 * toC2 + base * base - toC1 * toC1) / (2 * base);
    const double y = area4 / (2 * base);
    corner[c0] = corner[c2] + direction * Complex(x, -y);
  };
  auto placeFirstEdge = [&](std::array<Complex, 3>& corner) {
    corner[0] = 0;
    corner[1] = lengths[tri.faceEdges[0][2]];  // edge 0-1 is opposite corner 2
  };
  return detail::developFaces<Complex>(tri, edgeCut, placeFirstEdge, placeThird);
}

// The hole the Euclidean route cuts: the annulus, the hole's corners (its inner boundary) and
// its centre (for the flattening guess), on `*points` (the input's), or where null `ownPoints`.
struct Hole {
  const std::vector<Vec3d>* points = nullptr;
  std::vector<Vec3d> ownPoints;
  IntrinsicTriangulation annulus;
  std::vector<int> inner;
  Vec3d centre{0.0};
};

// One face removed: the annulus keeps the whole disk's numbering.
Hole faceHole(const std::vector<Vec3d>& points, const std::vector<std::array<int, 3>>& triangles,
              const IntrinsicTriangulation& whole, int face) {
  const auto& t = triangles[face];
  return {&points, {}, withoutFace(whole, face), {t[0], t[1], t[2]},
          (1.0 / 3) * (points[t[0]] + points[t[1]] + points[t[2]])};
}

// The star of vertex `removed` removed: the annulus numbers the other vertices in order (those
// after `removed` one lower), as the flow needs no isolated vertex.
Hole vertexStarHole(const std::vector<Vec3d>& points,
                    const std::vector<std::array<int, 3>>& triangles,
                    const IntrinsicTriangulation& whole, int removed) {
  if (removed < 0 || removed >= whole.vertexCount)
    throw Error(ErrorCode::InvalidInput, "removed vertex " + std::to_string(removed) +
                                             " out of range");
  auto fail = [&](const std::string& why) {
    throw Error(ErrorCode::InvalidInput,
                "removed vertex " + std::to_string(removed) + " " + why + " (choose one farther in)");
  };
  if (whole.vertexOnBoundary[removed]) fail("is on the boundary");
  Hole hole;
  hole.ownPoints.reserve(points.size() - 1);
  for (int v = 0; v < whole.vertexCount; ++v)
    if (v != removed) hole.ownPoints.push_back(points[v]);
  hole.centre = points[removed];
  auto renumbered = [&](int v) { return v < removed ? v : v - 1; };
  std::vector<std::array<int, 3>> kept;
  kept.reserve(triangles.size());
  std::vector<char> isInner(whole.vertexCount, 0);
  for (const auto& t : triangles) {
    if (t[0] != removed && t[1] != removed && t[2] != removed) {
      kept.push_back({renumbered(t[0]), renumbered(t[1]), renumbered(t[2])});
      continue;
    }
    for (int v : t) {
      if (v == removed || isInner[v]) continue;
      if (whole.vertexOnBoundary[v]) fail("has a neighbour on the boundary");
      isInner[v] = 1;
      hole.inner.push_back(renumbered(v));
    }
  }
  hole.annulus = buildTriangulation(whole.vertexCount - 1, kept);
  return hole;  // points: null, ownPoints are its points
}

DiskMap mapAnnulus(const Hole& hole, const DiskMapOptions& options) {
  DiskMap result;
  IntrinsicTriangulation tri = hole.annulus;
  const std::vector<Vec3d>& points = hole.points ? *hole.points : hole.ownPoints;
  const std::vector<double> embedded = embeddedEdgeLengths(tri, points);
  CirclePackingMetric metric = initialMetric(tri, embedded, options.scheme, Geometry::Euclidean);
  if (options.flatteningGuess)
    detail::addFlatteningGuess(tri, points, embedded, hole.inner, hole.centre, metric);
  const RicciFlowOptions flowOptions = detail::diskMapFlowOptions(options);
  result.flow = runRicciFlow(tri, metric, std::vector<double>(tri.vertexCount, 0.0), flowOptions);
  result.usedFlips = result.flow.flipsStartedAt >= 0;
  std::vector<double> lengths;
  if (!detail::euclideanEdgeLengths(tri, metric, lengths))
    throw Error(ErrorCode::Internal, "flat metric has an edge without a length");

  // Inner boundary = the hole's corners.
  std::vector<char> inner(tri.vertexCount, 0);
  const std::vector<int>& innerVertices = hole.inner;
  for (int v : innerVertices) inner[v] = 1;
  // Shortest interior edge path from the inner to the outer boundary: the first outer vertex
  // Dijkstra settles.
  std::vector<int> parent;
  std::vector<double> dist;
  auto outer = [&](int v) { return tri.vertexOnBoundary[v] && !inner[v]; };
  const int outerEnd = dijkstra(tri, lengths, innerVertices, dist, parent, outer,
                                [&](int e) { return !tri.edgeOnBoundary(e); }, outer);
  if (outerEnd < 0) throw Error(ErrorCode::Internal, "no cut path from inner to outer boundary");
  std::vector<char> edgeCut(tri.edgeCount(), 0);
  int firstCutEdge = -1;
  for (int v = outerEnd; parent[v] >= 0;) {
    const int e = parent[v];
    edgeCut[e] = 1;
    firstCutEdge = e;
    v = tri.edgeVertices[e][0] == v ? tri.edgeVertices[e][1] : tri.edgeVertices[e][0];
    if (inner[v]) break;
  }
  const auto corner = layOut(tri, lengths, edgeCut);

  // The period: the same cut vertex seen from the two faces beside the cut edge.
  const int f0 = tri.edgeFaces[firstCutEdge][0], f1 = tri.edgeFaces[firstCutEdge][1];
  Complex period = 0;
  for (int v : tri.edgeVertices[firstCutEdge]) {
    Complex p0, p1;
    for (int c = 0; c < 3; ++c) {
      if (tri.faceVertices[f0][c] == v) p0 = corner[f0][c];
      if (tri.faceVertices[f1][c] == v) p1 = corner[f1][c];
    }
    period += 0.5 * (p1 - p0);
  }
  if (!(std::abs(period) > 0)) throw Error(ErrorCode::Internal, "degenerate cylinder period");
  const Complex scale = Complex(0, 2 * std::numbers::pi) / period;

  // Real parts of the two straight boundaries after scaling; the outer one must be larger.
  double innerRe = 0, outerRe = 0;
  int innerCount = 0, outerCount = 0;
  std::vector<Complex> w(tri.vertexCount);
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int c = 0; c < 3; ++c) w[tri.faceVertices[f][c]] = corner[f][c] * scale;
  for (int v = 0; v < tri.vertexCount; ++v) {
    if (!tri.vertexOnBoundary[v]) continue;
    (inner[v] ? innerRe : outerRe) += w[v].real();
    ++(inner[v] ? innerCount : outerCount);
  }
  innerRe /= innerCount;
  outerRe /= outerCount;
  const double sign = outerRe > innerRe ? 1.0 : -1.0;
  result.uv.resize(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) {
    result.uv[v] = std::exp(sign * w[v] - sign * outerRe);
    if (!std::isfinite(result.uv[v].real()) || !std::isfinite(result.uv[v].imag()))
      throw Error(ErrorCode::Internal, "disk map produced a non-finite coordinate");
  }
  return result;
}

// `route` with the options, and if the flow fails with FlipPolicy::Auto, once more with flips
// throughout (the last resort for a flow that failed without, or with late, flips).
template <typename Route>
DiskMap withFlipRetry(const DiskMapOptions& options, Route route) {
  if (options.flips != FlipPolicy::Auto) return route(options);
  try {
    return route(options);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Unreachable) throw;
    DiskMapOptions withFlips = options;
    withFlips.flips = FlipPolicy::On;
    return route(withFlips);
  }
}

// The Euclidean route once the input is known to be a disk (`whole`: its unflipped triangulation).
DiskMap euclideanDiskMap(const std::vector<Vec3d>& points,
                         const std::vector<std::array<int, 3>>& triangles,
                         const IntrinsicTriangulation& whole, const DiskMapOptions& options) {
  const int removedVertex = options.removedVertex;
  const int removed = removedVertex >= 0        ? -1
                      : options.removedFace >= 0 ? options.removedFace
                                                 : faceToRemove(whole, embeddedEdgeLengths(whole, points));
  if (removed >= static_cast<int>(triangles.size()))
    throw Error(ErrorCode::InvalidInput, "removed face index out of range");
  const Hole hole = removedVertex >= 0 ? vertexStarHole(points, triangles, whole, removedVertex)
                                       : faceHole(points, triangles, whole, removed);
  // The removed vertex maps to the hole's centre, 0 (the circle the inner boundary maps to
  // is centred there).
  auto annulusMap = [&](const DiskMapOptions& o) {
    DiskMap map = mapAnnulus(hole, o);
    map.removedFace = removed;
    map.removedVertex = removedVertex;
    if (removedVertex >= 0) map.uv.insert(map.uv.begin() + removedVertex, 0.0);
    return map;
  };
  // The guess corrects the embedded metric, which tangential and Thurston packings do not start
  // from: over the 720 maps of tools/bench/flow_sweep.sh it cost them Newton steps (mean 4.94 ->
  // 5.16 and 5.01 -> 5.59) while the other four gained (e.g. virtual 5.55 -> 5.15).
  DiskMapOptions routeOptions = options;
  if (options.scheme == Scheme::Tangential || options.scheme == Scheme::Thurston)
    routeOptions.flatteningGuess = false;
  return withFlipRetry(routeOptions, [&](const DiskMapOptions& o) {
    if (!o.flatteningGuess) return annulusMap(o);
    try {
      return annulusMap(o);
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Unreachable) throw;
      DiskMapOptions unguessed = o;
      unguessed.flatteningGuess = false;
      return annulusMap(unguessed);
    }
  });
}

// The route options.geometry picks, once the input is known to be a disk.
DiskMap diskMapByRoute(const std::vector<Vec3d>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const IntrinsicTriangulation& whole, const DiskMapOptions& options) {
  switch (options.geometry) {
    case Geometry::Spherical:
      return withFlipRetry(options, [&](const DiskMapOptions& o) {
        return detail::sphericalDiskMap(points, whole, o);
      });
    case Geometry::Hyperbolic:
      return withFlipRetry(options, [&](const DiskMapOptions& o) {
        return detail::hyperbolicDiskMap(points, whole, o);
      });
    case Geometry::Euclidean: break;
  }
  return euclideanDiskMap(points, triangles, whole, options);
}

}  // namespace

DiskMap computeDiskMap(const TriMesh& mesh, const DiskMapOptions& options) {
  requireDisk(mesh, "mesh");
  std::vector<Vec3d> points;
  points.reserve(mesh.n_vertices());
  for (int v = 0; v < static_cast<int>(mesh.n_vertices()); ++v) {
    const auto& p = mesh.point(TriMesh::VertexHandle(v));
    points.push_back({p[0], p[1], p[2]});
  }
  const std::vector<std::array<int, 3>> triangles = meshTriangles(mesh);
  const IntrinsicTriangulation whole =
      buildTriangulation(static_cast<int>(points.size()), triangles);
  return diskMapByRoute(points, triangles, whole, options);
}

std::vector<double> distanceToBoundary(const IntrinsicTriangulation& tri,
                                       const std::vector<double>& edgeLengths) {
  std::vector<int> boundary, parent;
  std::vector<double> dist;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (tri.vertexOnBoundary[v]) boundary.push_back(v);
  dijkstra(tri, edgeLengths, boundary, dist, parent, [](int) { return false; },
           [](int) { return true; }, [](int) { return false; });
  return dist;
}

DiskMap computeDiskMap(const std::vector<Vec3d>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const DiskMapOptions& options) {
  return computeDiskMap(points, triangles,
                        buildTriangulation(static_cast<int>(points.size()), triangles), options);
}

DiskMap computeDiskMap(const std::vector<Vec3d>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const IntrinsicTriangulation& whole, const DiskMapOptions& options) {
  if (whole.vertexCount != static_cast<int>(points.size()) ||
      whole.faceCount() != static_cast<int>(triangles.size()))
    throw Error(ErrorCode::InvalidInput,
                "disk map: the triangulation does not match the points and triangles");
  requireDisk(whole, "mesh");
  return diskMapByRoute(points, triangles, whole, options);
}

void alignDiskMap(std::vector<std::complex<double>>& uv, int a, int b, int c) {
  const Mobius m = Mobius::alignMarkers(uv.at(a), uv.at(b), uv.at(c));
  for (auto& z : uv) z = m(z);
}

}  // namespace confvis::conformal
