#pragma once
// Analytic test scenes of the dissertation's Chapter 8 (Figs. 8.6, 8.7, 8.9), built as ordinary
// Scenes so both renderers draw them like any file, plus closed-form colours for the two checker
// scenes so tests and image checks have an exact answer to compare against.
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value (options): read it from any number of threads at once.
struct BuiltinSceneOptions {
  // Mesh density, 0 = the scene's default:
  //   checker-sphere: quads per cube-face edge (default 32; a multiple of 8 keeps every
  //                   triangle inside one checker square);
  //   checker-tunnel: quads per metre of wall (default 1);
  //   graph:          node detail level: 1 = icosahedron (20 triangles), each level more
  //                   splits every triangle in four (default 2, at most 5).
  int subdivision = 0;
  // Texels along one checker square edge, 0 = default (16). Small values make small tests.
  int texelsPerSquare = 0;
};

// Known names: "checker-sphere", "checker-tunnel", "graph".
std::vector<std::string> builtinSceneNames();
// Throws Error(InvalidInput) listing the known names for an unknown one or a bad option.
Scene builtinScene(const std::string& name, const BuiltinSceneOptions& options = {});

// --- checker-sphere (Fig. 8.6) ---
// A sphere of radius kCheckerSphereRadius around the origin, seen from inside. The colour of a
// point depends on the cube face its direction falls in (dominant axis): blue for ±z, red for ±x,
// green for ±y; each face carries kCheckerSquaresPerFace² squares alternating between the face
// colour and white, laid out in the face's gnomonic (cube) coordinates.
inline constexpr double kCheckerSphereRadius = 10.0;
inline constexpr int kCheckerSquaresPerFace = 8;
// Exact colour seen along a direction from the centre (any non-zero length).
glm::vec3 checkerSphereColor(glm::dvec3 direction);

// --- checker-tunnel (Fig. 8.7) ---
// A square tunnel of 4 m x 4 m cross-section (x, y in [-2, 2]) from z = +10 to z = -50 with
// 1 m checker squares: floor grey/white, ceiling green/white, left wall red/white, right wall
// blue/white; inward normals, open ends.
inline constexpr double kTunnelHalfWidth = 2.0;
inline constexpr double kTunnelZNear = 10.0;
inline constexpr double kTunnelZFar = -50.0;
// Exact colour hit by the ray from the origin along `direction`; nullopt where the ray leaves
// through an open end.
std::optional<glm::vec3> checkerTunnelColor(glm::dvec3 direction);

// --- graph (Fig. 8.9) ---
// kGraphClusters clusters of kGraphNodesPerCluster nodes, 3-15 m around the viewer in all
// directions, nodes as small icospheres, edges as thin triangular prisms, one colour (material)
// per cluster; meshes named "cluster N" plus one "inter-cluster edges" mesh. Deterministic.
inline constexpr int kGraphClusters = 12;
inline constexpr int kGraphNodesPerCluster = 40;

}  // namespace confvis
