// The display map pipeline (design note §3 steps 1-5): templates, projection to the sphere
// around the reference, the two Riemann maps (in parallel) and the Möbius alignment.
#include "confvis/conformal/display_map.hpp"

#include <chrono>
#include <future>

#include "confvis/base/error.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

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

conformal::TriMesh toTriMesh(const SphereDiskMesh& mesh) {
  conformal::TriMesh tri;
  std::vector<conformal::TriMesh::VertexHandle> handles;
  handles.reserve(mesh.sphere.size());
  for (const Vec3d& p : mesh.sphere) handles.push_back(tri.add_vertex({p.x, p.y, p.z}));
  for (const auto& t : mesh.triangles)
    if (!tri.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
      throw Error(ErrorCode::Internal,
                  "display map: template triangle rejected by the half-edge mesh");
  return tri;
}

struct FlowResult {
  conformal::DiskMap map;
  double seconds = 0;
};

FlowResult runDiskMap(const SphereDiskMesh& mesh, Progress& progress) {
  const auto start = Clock::now();
  FlowResult result;
  // Inversive distance (exact for any initial lengths, like Yamabe) converged in 5 Newton
  // iterations where Yamabe took 7 on the cut cube sources (tools/bench/display_map_bench.cpp).
  conformal::DiskMapOptions options;
  options.scheme = conformal::Scheme::InversiveDistance;
  result.map = conformal::computeDiskMap(toTriMesh(mesh), options);
  result.seconds = secondsSince(start);
  progress.advance();
  return result;
}

nlohmann::json meshStats(const SphereDiskMesh& mesh, const FlowResult& flow) {
  return {{"vertices", mesh.sphere.size()},
          {"triangles", mesh.triangles.size()},
          {"boundary_vertices", mesh.boundary.size()},
          {"flow_iterations", flow.map.flow.iterations},
          {"flow_seconds", flow.seconds},
          {"used_flips", flow.map.usedFlips},
          {"max_curvature_error", flow.map.flow.maxCurvatureError}};
}

}  // namespace

DisplayMap computeDisplayMap(const DisplayConfig& config, const DisplayMapOptions& options) {
  Progress progress("display map " + config.name, 4, options.showProgress);
  auto start = Clock::now();
  const DisplayTemplates templates = buildDisplayTemplates(config, options.edgeLength);
  DisplayMap map;
  map.source = projectToSphere(templates.source, config.reference);
  map.target = projectToSphere(templates.target, config.reference);
  map.sourceMarkers = templates.sourceMarkers;
  map.targetMarkers = templates.targetMarkers;
  const double templateSeconds = secondsSince(start);
  progress.advance();

  // The two Riemann maps are independent (dissertation 8.3.3: "processed independently and in
  // parallel"); a closed display's source is its target, so one map serves both.
  start = Clock::now();
  const bool identical = templates.sourceKind == SourceKind::Closed;
  auto sourceFuture = std::async(std::launch::async, [&] {
    return identical ? FlowResult{} : runDiskMap(map.source, progress);
  });
  const FlowResult targetFlow = runDiskMap(map.target, progress);
  FlowResult sourceFlow = sourceFuture.get();
  if (identical) {
    sourceFlow = targetFlow;
    progress.advance();
  }
  const double flowSeconds = secondsSince(start);

  start = Clock::now();
  map.source.disk = sourceFlow.map.uv;
  map.target.disk = targetFlow.map.uv;
  const auto& s = map.sourceMarkers;
  const auto& t = map.targetMarkers;
  conformal::alignDiskMap(map.source.disk, s[0], s[1], s[2]);
  conformal::alignDiskMap(map.target.disk, t[0], t[1], t[2]);
  const double alignmentSeconds = secondsSince(start);
  progress.advance();
  progress.finish();

  map.stats = {{"template", templateSeconds},
               {"flow", flowSeconds},
               {"alignment", alignmentSeconds},
               {"source_kind", toString(templates.sourceKind)},
               {"edge_length", options.edgeLength > 0 ? options.edgeLength : config.edgeLength},
               {"source", meshStats(map.source, sourceFlow)},
               {"target", meshStats(map.target, targetFlow)}};
  return map;
}

}  // namespace confvis
