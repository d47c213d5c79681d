#pragma once
// Point location on a triangle mesh of the unit sphere: which chord triangle the ray from the
// centre along a direction d meets, and where (barycentric coordinates from the triple products,
// the piecewise-linear map's own coordinates, as in sphere_raster.hpp). Triangles are listed in
// the cells of a cube-map grid (binSphereTriangles' boxes); a query tests the triangles of its
// cell. Used to evaluate a DisplayMap exactly (map_accuracy.cpp), without baking it.
#include <array>
#include <vector>

#include "confvis/base/vec3.hpp"

namespace confvis::detail {

class SphereLocator {
 public:
  struct Hit {
    int triangle = -1;                    // -1: no triangle covers d
    std::array<double, 3> barycentric{};  // sum 1; non-negative up to rounding
  };

  SphereLocator(const std::vector<Vec3d>& sphere, const std::vector<std::array<int, 3>>& triangles);

  Hit locate(const Vec3d& d) const;

 private:
  const std::vector<Vec3d>& sphere_;
  const std::vector<std::array<int, 3>>& triangles_;
  std::vector<std::array<Vec3d, 3>> edges_;  // edges_[t][i] . d = det(d, corner i+1, corner i+2)
  std::vector<double> sign_;                 // sign of det(a, b, c); 0: degenerate
  int n_ = 1;                                // cells per cube-face side
  std::vector<int> cellStart_, cellTriangles_;
};

}  // namespace confvis::detail
