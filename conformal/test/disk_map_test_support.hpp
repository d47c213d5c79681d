#pragma once
// Marker choice and Möbius-aligned comparison shared by the disk-map tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/mesh.hpp"

namespace confvis::conformal::test {

// Boundary vertices nearest to azimuths 0°, 120°, 240° (counter-clockwise seen from +z) of a
// mesh around the z axis.
inline std::array<int, 3> azimuthMarkers(const TriMesh& mesh) {
  std::array<int, 3> best{-1, -1, -1};
  std::array<double, 3> bestDist{1e9, 1e9, 1e9};
  for (auto v : mesh.vertices()) {
    if (!mesh.is_boundary(v)) continue;
    const auto& p = mesh.point(v);
    for (int k = 0; k < 3; ++k) {
      const double d = std::abs(std::complex<double>(p[0], p[1]) -
                                std::polar(1.0, 2 * std::numbers::pi * k / 3));
      if (d < bestDist[k]) {
        bestDist[k] = d;
        best[k] = v.idx();
      }
    }
  }
  return best;
}

// Max distance between two disk maps after aligning both at the same three markers.
inline double alignedDistance(std::vector<std::complex<double>> a,
                              std::vector<std::complex<double>> b, const std::array<int, 3>& m) {
  alignDiskMap(a, m[0], m[1], m[2]);
  alignDiskMap(b, m[0], m[1], m[2]);
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace confvis::conformal::test
