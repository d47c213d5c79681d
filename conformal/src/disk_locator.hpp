#pragma once
// Point location in a triangulated disk (the aligned disk of a SphereDiskMesh): which triangle
// holds a disk point z, and z's barycentric coordinates there. Used by the bake to invert one
// disk map at the disk points of the other (design note §3 step 6).
//
// A lookup first walks from the caller's previous triangle (neighbouring texels land in the same
// or an adjacent triangle, so this is usually one test), and falls back to a uniform grid. Both
// disks are polygons inscribed in the unit circle, hence convex but not equal: a point of one
// can lie just outside the other (between a boundary chord and the circle). Such a point is
// clamped to the nearest point of the boundary polygon, the PL map's closest extension.
#include <array>
#include <complex>
#include <vector>

namespace confvis::detail {

class DiskLocator {
 public:
  struct Hit {
    int triangle = -1;
    std::array<double, 3> barycentric{};  // non-negative, sum 1
    bool inside = true;                   // false: z was outside and has been clamped
  };

  // Throws Error(InvalidInput) if no triangle has a non-zero area.
  DiskLocator(const std::vector<std::complex<double>>& disk,
              const std::vector<std::array<int, 3>>& triangles);

  // `hint` is the triangle a previous lookup of the same caller returned (or -1); it is updated.
  // Always returns a triangle of non-zero area.
  Hit locate(std::complex<double> z, int& hint) const;

  // Triangle t's barycentric coordinates as affine functions of z = x + iy:
  // (l1, l2) = M (z - p0), l0 = 1 - l1 - l2.
  struct Affine {
    double x0, y0, m11, m12, m21, m22;
    bool valid;  // false for a triangle of (near) zero area, which is never returned
  };
  const Affine& affine(int triangle) const { return affine_[triangle]; }
  // The triangle across the edge opposite `corner` of `triangle`; -1 on the boundary.
  int neighbour(int triangle, int corner) const { return neighbour_[triangle][corner]; }

 private:
  std::array<double, 3> barycentric(int t, std::complex<double> z) const;
  bool walk(std::complex<double> z, int start, Hit& hit) const;
  bool searchGrid(std::complex<double> z, Hit& hit) const;
  Hit clampToBoundary(std::complex<double> z) const;

  const std::vector<std::complex<double>>& disk_;
  const std::vector<std::array<int, 3>>& triangles_;
  std::vector<Affine> affine_;
  std::vector<std::array<int, 3>> neighbour_;  // across the edge opposite corner i; -1: boundary
  std::vector<std::array<int, 2>> boundaryEdges_;  // (triangle, corner opposite the edge)
  // Uniform grid over the disks' bounding box, triangles listed in every cell their box touches.
  int grid_ = 1;
  double minX_ = -1, minY_ = -1, cell_ = 1;
  std::vector<int> cellStart_, cellTriangles_;
};

}  // namespace confvis::detail
