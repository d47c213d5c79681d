#pragma once
// Internal: the spherical and hyperbolic disk-map routes (disk_map_spherical.cpp,
// disk_map_hyperbolic.cpp) and what they share with the Euclidean one (disk_map.cpp).
#include <vector>

#include "confvis/conformal/disk_map.hpp"

namespace confvis::conformal::detail {

// `whole`: the unflipped triangulation of the disk, vertices numbered as `points`.
DiskMap sphericalDiskMap(const std::vector<Vec3d>& points, const IntrinsicTriangulation& whole,
                         const DiskMapOptions& options);
DiskMap hyperbolicDiskMap(const std::vector<Vec3d>& points, const IntrinsicTriangulation& whole,
                          const DiskMapOptions& options);

// The flow options a disk map runs with.
RicciFlowOptions diskMapFlowOptions(const DiskMapOptions& options);

// The mesh's edge lengths scaled so that its total area is `area` (the curved routes need the
// mesh at the size of the model surface they end up on).
std::vector<double> lengthsScaledToArea(const IntrinsicTriangulation& tri,
                                        const std::vector<Vec3d>& points, double area);

// The boundary as a counter-clockwise cycle: vertices[k] → vertices[k+1] along edges[k].
struct BoundaryCycle {
  std::vector<int> vertices, edges;
};
BoundaryCycle boundaryCycle(const IntrinsicTriangulation& tri);

// Adds the counts and times of `flow` to `total` (a route that runs several flows).
void accumulateFlowReport(RicciFlowReport& total, const RicciFlowReport& flow);

// Corner angle of a spherical or hyperbolic triangle opposite side `opposite` (cornerAngles).
double curvedCornerAngle(Geometry geometry, double opposite, double adjacent1, double adjacent2);

}  // namespace confvis::conformal::detail
