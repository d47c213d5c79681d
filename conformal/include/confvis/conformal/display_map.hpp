#pragma once
// The conformal map of a display before baking (design note §3 steps 1-5): the source and target
// templates projected to the unit sphere around the reference point, each with its aligned
// Riemann map to the unit disk. Both disks are aligned by a disk automorphism at the forward
// direction (the hemisphere axis, else -z): the source's forward direction and the display point
// straight ahead of the reference point (the display's centre of directions where it covers no
// such point) go to 0, "up" (+y) to +i, so T_ray = phi_S^-1 o phi_D sends the straight-ahead
// point to the forward direction and keeps up up there; T_ray and T_geom = phi_D^-1 o phi_S are
// evaluated by point location in the other disk. The bake (bake.hpp) turns this into a
// RetargetMap.
#include <array>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/display_template.hpp"

namespace confvis CONFVIS_API {

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

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct DisplayMap {
  SphereDiskMesh source;  // S: the virtual field of view shown (sphere cut open, or hemisphere)
  SphereDiskMesh target;  // D: the directions covered by the display's lit walls
  // Three corresponding boundary vertices (cut leaves and the display corners they stand for;
  // for a hemisphere source, rim points at those corners' azimuths). Not pinned by the
  // alignment; stats["anchor"]["leaf_offset_degrees"] says how far apart T_ray puts them.
  std::array<int, 3> sourceMarkers{};
  std::array<int, 3> targetMarkers{};
  // Seconds per stage ("template", "flow", "alignment"), the alignment's anchors ("anchor") and
  // mesh sizes, for bake.json.
  nlohmann::json stats = nlohmann::json::object();
};

struct DisplayConfig;

// Spherical (default): no removed face, so a symmetric display gets an exactly symmetric map,
// and far closer to the true Riemann map; Euclidean-route fallback where its flow stalls.
// Euclidean: the faster preset (cave5 at 20 cm, shared 2-core machine: 50 against 75 ms CPU for
// the whole re-bake), but its removed face bends the map around the display's centre (0.7 px
// median mirror asymmetry on cave3, 59 px on flat-wall).
// Hyperbolic: iterated boundary curvature (disk_map.hpp); measured against the other two in
// conformal/README.md ("Map accuracy"), Euclidean fallback like the spherical route.
enum class DisplayMapRoute { Spherical, Euclidean, Hyperbolic };

struct DisplayMapOptions {
  double edgeLength = 0.0;          // metres; <= 0 takes the config's edge_length
  DisplayMapRoute route = DisplayMapRoute::Spherical;
  TemplateGrading grading;  // uniform edges unless radiusDegrees > 0 (display_template.hpp)
  bool showProgress = false;
};

// Templates, refinement, projection to the sphere, both Riemann maps and the Möbius alignment
// at the forward direction for a validated display config, with config.reference as the reference point.
// Throws Error(InvalidInput) naming the culprit for displays it cannot map (visible region not a
// disk, ...), Error(Unreachable) if a flow fails.
DisplayMap computeDisplayMap(const DisplayConfig& config, const DisplayMapOptions& options = {});

}  // namespace confvis
