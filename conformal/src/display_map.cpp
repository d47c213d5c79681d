// The display map pipeline (design note §3 steps 1-5): templates, projection to the sphere
// around the reference, the two Riemann maps (in parallel) and the Möbius alignment at the
// forward direction (display_alignment.hpp).
#include "confvis/conformal/display_map.hpp"

#include <algorithm>
#include <cstdio>
#include <future>
#include <limits>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/conformal/mobius.hpp"
#include "confvis/engine/display_config.hpp"
#include "display_alignment.hpp"
#include "flow_progress.hpp"

namespace confvis {
namespace {

SphereDiskMesh projectToSphere(const TemplateMesh& mesh, const glm::dvec3& reference) {
  SphereDiskMesh out;
  out.sphere.reserve(mesh.points.size());
  for (const glm::dvec3& p : mesh.points) {
    const glm::dvec3 d = glm::normalize(p - reference);
    out.sphere.push_back({d.x, d.y, d.z});
  }
  out.triangles = mesh.triangles;
  out.boundary = mesh.boundary;
  out.lit = mesh.lit;
  return out;
}

// What both choices of the Euclidean route's hole weigh: each vertex's distance from the
// boundary (arc lengths on the sphere along edges) and each face's area, with the smallest area
// a hole may touch (a quarter of the median: a tiny bezel-corner face at the centre of a tiled
// wall would make the annulus extremely thin inside and the flow crawl).
struct HoleCandidates {
  std::vector<double> distance, area;
  double minArea = 0;
};

HoleCandidates measureHoleCandidates(const SphereDiskMesh& mesh,
                                     const conformal::IntrinsicTriangulation& tri) {
  HoleCandidates out;
  std::vector<double> arc(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e)
    arc[e] = angleBetween(mesh.sphere[tri.edgeVertices[e][0]], mesh.sphere[tri.edgeVertices[e][1]]);
  out.distance = conformal::distanceToBoundary(tri, arc);
  out.area.resize(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    out.area[f] =
        norm(cross(mesh.sphere[t[1]] - mesh.sphere[t[0]], mesh.sphere[t[2]] - mesh.sphere[t[0]]));
  }
  std::vector<double> sorted = out.area;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  out.minArea = 0.25 * sorted[sorted.size() / 2];
  return out;
}

// The face the Riemann map removes (dissertation 8.3.3: "at the center of the mesh, or farthest
// from the original boundary"), among faces of at least a quarter of the median area.
int chooseRemovedFace(const SphereDiskMesh& mesh, const conformal::IntrinsicTriangulation& tri) {
  const auto [distance, area, minArea] = measureHoleCandidates(mesh, tri);
  int best = -1;
  double bestScore = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const double score = std::min({distance[t[0]], distance[t[1]], distance[t[2]]});
    if (area[f] >= minArea && score > bestScore) bestScore = score, best = static_cast<int>(f);
  }
  return best;  // -1: computeDiskMap picks (and reports a mesh too coarse)
}

// The vertex whose star the Euclidean route removes instead of one face, so that the hole is as
// symmetric as the display (one triangle never is: cave5's fast map was 3.5 px off its mirror
// image, conformal/README.md "Presets"): among the vertices nearly as far from the boundary as
// the farthest (within 5 %, arc lengths as chooseRemovedFace) whose neighbours are all off the
// boundary and whose triangles are all of at least a quarter of the median area, the one
// nearest to those candidates' mean direction. A mirror symmetry of the mesh maps the
// candidates onto themselves, so their mean lies on the mirror plane, and so does the vertex
// picked where the mesh has one there (cave5: the floor's centre). -1 if there is none.
int chooseRemovedVertex(const SphereDiskMesh& mesh, const conformal::IntrinsicTriangulation& tri) {
  const auto [distance, area, minArea] = measureHoleCandidates(mesh, tri);
  // Vertices with a small triangle or a boundary neighbour are out.
  std::vector<char> eligible(tri.vertexCount, 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    bool touchesBoundary = false;
    for (int v : t) touchesBoundary = touchesBoundary || tri.vertexOnBoundary[v];
    for (int v : t)
      if (touchesBoundary || area[f] < minArea) eligible[v] = 0;
  }
  double farthest = 0;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (eligible[v]) farthest = std::max(farthest, distance[v]);
  if (!(farthest > 0)) return -1;
  std::vector<int> candidates;
  glm::dvec3 mean(0.0);
  for (int v = 0; v < tri.vertexCount; ++v)
    if (eligible[v] && distance[v] >= 0.95 * farthest) {
      candidates.push_back(v);
      mean += mesh.sphere[v];
    }
  int best = -1;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  for (int v : candidates) {
    const glm::dvec3 d = mesh.sphere[v] - mean / static_cast<double>(candidates.size());
    if (dot(d, d) < bestDistance2) bestDistance2 = dot(d, d), best = v;
  }
  return best;
}

// `uv` moved by a disk automorphism so that the boundary's points, weighted by their share of
// the boundary on the sphere, have mean 0 (a conformal barycentre, fixed-point iteration).
std::vector<std::complex<double>> centredOnBoundary(const SphereDiskMesh& mesh,
                                                    std::vector<std::complex<double>> uv) {
  const std::size_t n = mesh.boundary.size();
  std::vector<double> weight(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double side =
        glm::length(mesh.sphere[mesh.boundary[k]] - mesh.sphere[mesh.boundary[(k + 1) % n]]);
    weight[k] += 0.5 * side;
    weight[(k + 1) % n] += 0.5 * side;
  }
  conformal::Mobius centring;  // moves the boundary's current barycentre to 0
  for (int iteration = 0; iteration < 100; ++iteration) {
    std::complex<double> mean = 0;
    double total = 0;
    for (std::size_t k = 0; k < n; ++k) {
      mean += weight[k] * centring(uv[mesh.boundary[k]]);
      total += weight[k];
    }
    mean /= total;
    if (std::abs(mean) < 1e-15) break;
    // Half a step towards the barycentre, in the disk before this iteration's centring.
    centring = conformal::Mobius::diskAutomorphism(centring.inverse()(0.5 * mean), 0);
  }
  for (auto& z : uv) z = centring(z);
  return uv;
}

struct FlowResult {
  conformal::DiskMap map;
  double seconds = 0;
  std::string directFailure;  // why the direct spherical flow failed, if it did
};

FlowResult runDiskMap(const SphereDiskMesh& mesh, DisplayMapRoute route, bool graded,
                      Progress& progress) {
  const auto start = SteadyClock::now();
  FlowResult result;
  // Inversive distance (exact for any initial lengths, like Yamabe) converged in 5 Newton
  // iterations where Yamabe took 7 on the cut cube sources (tools/bench/display_map_bench.cpp).
  conformal::DiskMapOptions options;
  options.scheme = conformal::Scheme::InversiveDistance;
  const conformal::IntrinsicTriangulation whole =
      conformal::buildTriangulation(static_cast<int>(mesh.sphere.size()), mesh.triangles);
  // Newton converges in under 10 iterations here; one that needs more is stuck on a mesh only
  // Delaunay flips can flatten (thin bezel strips), so give up early and retry with flips.
  options.maxIterations = 30;
  // The spherical route first: it removes nothing, so a symmetric mesh gets an exactly symmetric
  // map, and it is far closer to the true Riemann map. The Euclidean route's hole (a vertex's
  // star, chooseRemovedVertex, made round) bends the map around it; it keeps a mirror symmetry
  // only where the vertex lies on the mirror plane (cave5, flat-wall: 0.0000 px; cave3 9 px,
  // tools/bench/alignment_bench.cpp), for about 1.5 x the flow time (conformal/README.md).
  options.geometry = route == DisplayMapRoute::Spherical    ? conformal::Geometry::Spherical
                     : route == DisplayMapRoute::Hyperbolic ? conformal::Geometry::Hyperbolic
                                                            : conformal::Geometry::Euclidean;
  // Continuation reaches the hemisphere for cut sources (cave3's) in a stall or two; a display it
  // cannot reach after 3 (a thin band of monitors) takes the Euclidean route instead of minutes.
  // A graded mesh gives up after its direct flow: its fallback below (Euclidean, then spherical
  // from there) is cheaper than continuation, which can follow a branch of the non-convex energy
  // that folds before the hemisphere (cave3's graded target, conformal/README.md).
  options.maxStalledStages = graded ? 0 : 3;
  // A graded direct flow that converges does so in at most 8 Newton steps (cave3's source at
  // 20 cm; cave5's 4); one that fails costs most of the re-bake (cave3 at 10 cm: 4.3 + 2.1 s CPU
  // for 20 steps each, against ~0.4 s for the fallback), so it is given up after 12.
  if (graded) options.maxIterations = 12;
  // And sooner where it is not converging (flow_progress.hpp): cave3 at 10 cm then gives its
  // source up after 7 + 4 steps (without, then with flips) instead of 12 + 12, its target after
  // 4 + 4. A flow that converges is never given up (cave4-6 in 4 steps, cave3's source at 20 cm
  // in 8), so the maps and routes stay as they were.
  std::vector<double> directErrors;
  if (graded && route == DisplayMapRoute::Spherical)
    options.onIteration = [&](int iteration, double error) {
      if (iteration == 1) directErrors.clear();  // a retry with flips starts afresh
      directErrors.push_back(error);
      if (detail::flowIsNotConverging(directErrors)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the spherical flow is not converging (max curvature error %.3g after %d "
                      "Newton steps, %.3g three steps before)",
                      error, iteration, directErrors[directErrors.size() - 4]);
        throw Error(ErrorCode::Unreachable, text);
      }
    };
  // A graded mesh has many rings of tiny triangles around each corner, all of which must open:
  // start them near z^(π/α) (disk_map.hpp). Uniform meshes keep their start (and their maps).
  options.cornerGuess = graded;
  const bool spherical = options.geometry == conformal::Geometry::Spherical;
  try {
    if (options.geometry == conformal::Geometry::Euclidean)
      throw Error(ErrorCode::Unreachable, "the Euclidean route was asked for");
    result.map = conformal::computeDiskMap(mesh.sphere, mesh.triangles, whole, options);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Unreachable) throw;
    if (spherical) result.directFailure = e.what();
    // The flows below run to their own caps: only the direct flow is given up early.
    options.onIteration = nullptr;
    // The spherical energy is not convex; the Euclidean route's always is.
    conformal::DiskMapOptions euclidean = options;
    euclidean.geometry = conformal::Geometry::Euclidean;
    euclidean.removedVertex = chooseRemovedVertex(mesh, whole);
    if (euclidean.removedVertex < 0) euclidean.removedFace = chooseRemovedFace(mesh, whole);
    // Start near the flat metric: 6 + 5 -> 4 + 5 Newton steps for cave5 at 20 cm (README).
    euclidean.flatteningGuess = true;
    euclidean.maxIterations = 30;
    result.map = conformal::computeDiskMap(mesh.sphere, mesh.triangles, whole, euclidean);
    // Its hemisphere is close to the spherical route's: from there the spherical flow converges
    // directly (cave3's graded target: 4 Newton steps), and the map is the spherical one again,
    // without the removed face that breaks a display's symmetry. Kept if that fails too. The
    // start is centred first (the spherical solution is only weakly pinned against disk Möbius
    // moves, so the flow stays near the start's centring): a display's symmetry then decides it,
    // not the removed face.
    if (spherical) {
      options.hemisphereGuess = centredOnBoundary(mesh, result.map.uv);
      options.maxStalledStages = 0;
      try {
        conformal::DiskMap sphericalMap =
            conformal::computeDiskMap(mesh.sphere, mesh.triangles, whole, options);
        result.map = std::move(sphericalMap);
      } catch (const Error& again) {
        if (again.code() != ErrorCode::Unreachable) throw;
      }
    }
  }
  result.seconds = secondsSince(start);
  progress.advance();
  return result;
}

nlohmann::json meshStats(const SphereDiskMesh& mesh, const FlowResult& flow) {
  nlohmann::json stats = {{"route", conformal::toString(flow.map.geometry)},
                           {"vertices", mesh.sphere.size()},
                           {"triangles", mesh.triangles.size()},
                           {"boundary_vertices", mesh.boundary.size()},
                           {"flow_iterations", flow.map.flow.iterations},
                           {"flow_seconds", flow.seconds},
                           {"used_flips", flow.map.usedFlips},
                           {"max_curvature_error", flow.map.flow.maxCurvatureError}};
  if (!flow.directFailure.empty()) stats["direct_spherical_flow"] = flow.directFailure;
  return stats;
}

}  // namespace

DisplayMap computeDisplayMap(const DisplayConfig& config, const DisplayMapOptions& options) {
  Progress progress("display map " + config.name, 4, options.showProgress);
  auto start = SteadyClock::now();
  const DisplayTemplates templates = buildDisplayTemplates(config, options.edgeLength, options.grading);
  DisplayMap map;
  map.source = projectToSphere(templates.source, config.reference);
  map.target = projectToSphere(templates.target, config.reference);
  map.sourceMarkers = templates.sourceMarkers;
  map.targetMarkers = templates.targetMarkers;
  const double templateSeconds = secondsSince(start);
  progress.advance();

  // The two Riemann maps are independent (dissertation 8.3.3: "processed independently and in
  // parallel"); a closed display's source is its target, so one map serves both.
  start = SteadyClock::now();
  const bool identical = templates.sourceKind == SourceKind::Closed;
  const bool graded = options.grading.radiusDegrees > 0;
  auto sourceFuture = std::async(std::launch::async, [&] {
    return identical ? FlowResult{} : runDiskMap(map.source, options.route, graded, progress);
  });
  const FlowResult targetFlow = runDiskMap(map.target, options.route, graded, progress);
  FlowResult sourceFlow = sourceFuture.get();
  if (identical) {
    sourceFlow = targetFlow;
    progress.advance();
  }
  const double flowSeconds = secondsSince(start);

  start = SteadyClock::now();
  map.source.disk = sourceFlow.map.uv;
  map.target.disk = targetFlow.map.uv;
  // The forward direction: the hemisphere's axis, else -z (design note §2).
  const glm::dvec3 axis = config.source == SourceField::Hemisphere
                              ? glm::normalize(config.hemisphereAxis)
                              : glm::dvec3(0, 0, -1);
  const nlohmann::json anchor = detail::alignAtForward(map, {axis.x, axis.y, axis.z}, config.name);
  const double alignmentSeconds = secondsSince(start);
  progress.advance();
  progress.finish();

  map.stats = {{"template", templateSeconds},
               {"flow", flowSeconds},
               {"alignment", alignmentSeconds},
               {"anchor", anchor},
               {"source_kind", toString(templates.sourceKind)},
               {"edge_length", options.edgeLength > 0 ? options.edgeLength : config.edgeLength},
               {"source", meshStats(map.source, sourceFlow)},
               {"target", meshStats(map.target, targetFlow)}};
  return map;
}

}  // namespace confvis
