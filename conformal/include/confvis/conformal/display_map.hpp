#pragma once
// The conformal map of a display before baking (design note §3 steps 1-5): the source and target
// templates projected to the unit sphere around the reference point, each with its aligned
// Riemann map to the unit disk. Both disks share three boundary markers sent to 1, i, -1, so
// T_ray = phi_S^-1 o phi_D and T_geom = phi_D^-1 o phi_S can be evaluated by point location in
// the other disk. The bake (bake.hpp) turns this into a RetargetMap.
#include <array>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/base/vec3.hpp"

namespace confvis {

// A triangulated topological disk on the unit sphere with a per-vertex disk coordinate.
struct SphereDiskMesh {
  std::vector<glm::dvec3> sphere;                  // unit directions from the reference point
  std::vector<std::complex<double>> disk;     // aligned disk coordinates, |z| <= 1, same size
  // Counter-clockwise as seen from the reference point (inside the sphere), like a viewer sees
  // the walls; both meshes use this orientation, so T_ray preserves orientation.
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> boundary;                  // boundary loop, vertex indices, in disk order
                                              // (counter-clockwise in the disk)
  // Per triangle: 1 where the triangle lies on a lit part of a wall, 0 on a bezel (covered but
  // unlit: the bake gives alpha 0 there). Empty means every triangle is lit.
  std::vector<std::uint8_t> lit;
};

struct DisplayMap {
  SphereDiskMesh source;  // S: the virtual field of view shown (sphere cut open, or hemisphere)
  SphereDiskMesh target;  // D: the directions covered by the display's lit walls
  std::array<int, 3> sourceMarkers{};  // vertex indices in source, sent to 1, i, -1
  std::array<int, 3> targetMarkers{};  // the corresponding vertices in target
  // Seconds per stage ("template", "flow", "alignment") and mesh sizes, for bake.json.
  nlohmann::json stats = nlohmann::json::object();
};

struct DisplayConfig;

struct DisplayMapOptions {
  double edgeLength = 0.0;          // metres; <= 0 takes the config's edge_length
  bool showProgress = false;
};

// Templates, refinement, projection to the sphere, both Riemann maps and the Möbius alignment
// for a validated display config, with config.reference as the reference point.
// Throws Error(InvalidInput) naming the culprit for displays it cannot map (visible region not a
// disk, ...), Error(Unreachable) if a flow fails.
DisplayMap computeDisplayMap(const DisplayConfig& config, const DisplayMapOptions& options = {});

}  // namespace confvis
