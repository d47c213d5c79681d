// confvis flow: conformal map of a disk-shaped mesh onto the unit disk by Ricci flow.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/real_mesh_map.hpp"
#include "confvis/conformal/obj_output.hpp"

namespace confvis::cli {
namespace {

using namespace confvis::conformal;

struct FlowArgs {
  std::string input, output, report, scheme = "yamabe", geometry = "euclidean", flips = "auto";
  std::string markers;
  double tolerance = 1e-10;
  int maxIterations = 100;
  bool quiet = false;
};

// Marker indices count the file's vertices from 0; the mesh may have welded or left some out.
std::array<int, 3> parseMarkers(const std::string& text, const TriMesh& mesh,
                                const MeshSource& source) {
  std::array<int, 3> m{};
  if (std::sscanf(text.c_str(), "%d,%d,%d", &m[0], &m[1], &m[2]) != 3)
    throw Error(ErrorCode::InvalidInput, "--markers expects three vertex indices i,j,k");
  for (int& v : m) {
    const auto it = std::find(source.fileVertex.begin(), source.fileVertex.end(), v);
    if (it == source.fileVertex.end())
      throw Error(ErrorCode::InvalidInput, "marker vertex " + std::to_string(v) +
                                               " does not exist or is used by no face");
    const int fileIndex = v;
    v = static_cast<int>(it - source.fileVertex.begin());
    if (!mesh.is_boundary(TriMesh::VertexHandle(v)))
      throw Error(ErrorCode::InvalidInput,
                  "marker vertex " + std::to_string(fileIndex) + " is not on the boundary");
  }
  if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2])
    throw Error(ErrorCode::InvalidInput, "--markers must name three different vertices");
  return m;
}

int runFlow(const FlowArgs& args) {
  const Geometry geometry = parseGeometry(args.geometry);
  DiskMapOptions options;
  options.geometry = geometry;
  options.scheme = parseScheme(args.scheme);
  options.tolerance = args.tolerance;
  options.maxIterations = args.maxIterations;
  options.flips = args.flips == "on" ? FlipPolicy::On
                  : args.flips == "off" ? FlipPolicy::Off
                                        : FlipPolicy::Auto;
  if (!args.quiet)
    options.onIteration = [](int it, double err) {
      std::fprintf(stderr, "flow: iteration %d, max curvature error %.3g\n", it, err);
    };
  MeshSource source;
  const TriMesh mesh = readMesh(args.input, source);
  requireDisk(mesh, source);
  if (!args.quiet && (source.weldedVertices > 0 || source.unreferencedVertices > 0))
    std::fprintf(stderr,
                 "flow: note: %d vertices at the position of an earlier one welded into it, %d "
                 "vertices used by no face left out; the output numbers the %zu vertices left\n",
                 source.weldedVertices, source.unreferencedVertices, mesh.n_vertices());
  std::array<int, 3> markers{};
  if (!args.markers.empty()) markers = parseMarkers(args.markers, mesh, source);

  const auto start = SteadyClock::now();
  const RealMeshMap real = computeRealMeshDiskMap(mesh, source, options);
  DiskMap map = real.map;
  if (!args.markers.empty()) alignDiskMap(map.uv, markers[0], markers[1], markers[2]);
  const double seconds = secondsSince(start);
  const DistortionStats stats = measureDistortion(mesh, map.uv);

  const std::filesystem::path output =
      args.output.empty() ? std::filesystem::path(std::filesystem::path(args.input).stem().string() + "-disk.obj")
                          : std::filesystem::path(args.output);
  writeObjWithDiskCoordinates(output, mesh, map.uv);
  nlohmann::json report = {{"input", args.input},
                           {"output", output.string()},
                           {"vertices", mesh.n_vertices()},
                           {"faces", mesh.n_faces()},
                           {"scheme", toString(options.scheme)},
                           {"geometry", toString(geometry)},
                           {"iterations", map.flow.iterations},
                           {"max_curvature_error", map.flow.maxCurvatureError},
                           {"tolerance", args.tolerance},
                           {"delaunay_flips", map.flow.flips},
                           {"used_flips", map.usedFlips},
                           {"removed_face", map.removedFace},
                           {"boundary_updates", map.boundaryUpdates},
                           {"welded_vertices", source.weldedVertices},
                           {"mollified_faces", real.mollifiedFaces},
                           {"untangled_vertices", real.untangledVertices},
                           {"largest_untangle_shift", real.largestUntangleShift},
                           {"unreferenced_vertices", source.unreferencedVertices},
                           {"seconds", seconds},
                           {"distortion", toJson(stats)}};
  if (!args.report.empty()) writeTextAtomically(args.report, report.dump(2) + "\n");
  std::printf("%s: %zu vertices, %d Newton iterations, max curvature error %.2e, %.3f s; "
              "singular-value ratio p50 %.4f p99 %.4f, %d flipped faces -> %s\n",
              args.input.c_str(), mesh.n_vertices(), map.flow.iterations,
              map.flow.maxCurvatureError, seconds, stats.ratioP50, stats.ratioP99,
              stats.flippedFaces, output.string().c_str());
  return 0;
}

const RegisterCommand registration{Command{
    "flow", "Map a disk-shaped mesh conformally onto the unit disk (discrete Ricci flow)",
    [](CLI::App& sub) {
      auto args = std::make_shared<FlowArgs>();
      sub.add_option("input", args->input, "Mesh to map (OBJ, OFF, PLY, STL); must be a disk")
          ->required();
      sub.add_option("-o,--output", args->output,
                     "OBJ with the disk coordinates as vt (default: INPUT-disk.obj)");
      sub.add_option("--scheme", args->scheme, "Circle packing scheme")
          ->check(CLI::IsMember({"tangential", "thurston", "inversive", "yamabe", "virtual", "mixed"}))
          ->capture_default_str();
      sub.add_option("--geometry", args->geometry,
                     "Route: background geometry of the flow (euclidean: annulus flow and exp; "
                     "spherical: hemisphere and stereographic projection; hyperbolic: boundary "
                     "iterated to a circle in the Poincaré disk)")
          ->capture_default_str();
      sub.add_option("--tolerance", args->tolerance, "Target max |K̄ - K|")
          ->check(kPositiveNumber)
          ->capture_default_str();
      sub.add_option("--max-iterations", args->maxIterations, "Newton iteration cap")
          ->check(kPositiveNumber)
          ->capture_default_str();
      sub.add_option("--flips", args->flips,
                     "Delaunay edge flips during the flow: auto retries with flips if it stalls")
          ->check(CLI::IsMember({"auto", "on", "off"}))
          ->capture_default_str();
      sub.add_option("--markers", args->markers,
                     "Three boundary vertex indices i,j,k (counter-clockwise) sent to 1, i, -1");
      sub.add_option("--report", args->report, "Write a JSON report (iterations, error, timing, "
                                               "distortion statistics)");
      sub.add_flag("-q,--quiet", args->quiet, "No per-iteration progress");
      return [args] { return runFlow(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
