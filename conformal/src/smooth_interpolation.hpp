#pragma once
// Per-vertex Möbius blending of a SphereDiskMesh's discrete map (map_interpolation.hpp): the
// smooth interpolation used by the bake (bake_smooth.cpp) and by DisplayMapEvaluator.
#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "confvis/base/vec3.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/conformal/display_map.hpp"

namespace confvis::detail {

class MobiusBlend {
 public:
  // Keeps a reference to `mesh`, which must outlive it. `unfold` false keeps every vertex's
  // Möbius map even where the blend folds (tests: the folds the guard removes).
  explicit MobiusBlend(const SphereDiskMesh& mesh, bool unfold = true);

  // The disk point of unit direction x, which lies in triangle t with chord barycentric
  // coordinates b (clamped to >= 0 here).
  std::complex<double> toDisk(int t, const std::array<double, 3>& b, const Vec3d& x) const;
  // The (unnormalised) direction of disk point z, which lies in triangle t with disk barycentric
  // coordinates l (clamped to >= 0 here).
  Vec3d toSphere(int t, const std::array<double, 3>& l, std::complex<double> z) const;

  // Vertex j's map: z = z0 + a w / (1 + c w), w the stereographic chart at the vertex,
  // w = ((x . e1) + i (x . e2)) / (1 + x . p).
  // At a boundary corner whose angle differs between sphere and disk, w is first turned by
  // conj(turn) and raised to gamma = diskWedge / sphereWedge (the map's local power law).
  struct Chart {
    Vec3d p{0.0}, e1{0.0}, e2{0.0};
    std::complex<double> z0, a, c;
    double gamma = 1.0, sphereWedge = 0.0, diskWedge = 0.0;
    std::complex<double> turn = 1.0;
  };
  const Chart& chart(int vertex) const { return charts_[vertex]; }

  // Vertices blended with the triangle's linear map instead of their Möbius map: the corners of
  // triangles where the blend folded (its Jacobian changed sign), found when the blend is built.
  // The linear map of a corner is that of the triangle being evaluated, which agrees with its
  // neighbour's on their shared edge, so the blend stays continuous; a triangle with three such
  // corners is the linear map, which keeps the disk triangle's orientation.
  bool blendsLinearly(int vertex) const { return linear_[vertex] != 0; }
  std::size_t linearVertices() const;

  // Whether the blend of triangle t turns over, either way (sphere -> disk or disk -> sphere),
  // at a grid of points inside it.
  bool folds(int t) const;

 private:
  // Sets linear_ for the corners of folding triangles, checking those whose corners' Möbius maps
  // miss their neighbours by more than kFoldScreen (misfit, per vertex), until none folds.
  void unfold(const std::vector<std::vector<int>>& rings, const std::vector<double>& misfit);

  const SphereDiskMesh& mesh_;
  std::vector<Chart> charts_;
  std::vector<std::uint8_t> linear_;
};

class DiskLocator;

// One direction map of the bake (bake.cpp's bakeDirectionMap) through the Möbius blends:
// rasterise `domain` on the sphere; per texel, the domain blend gives the disk point, the
// codomain disk locates it, the codomain blend gives the direction. Same alpha and `covered`.
void bakeDirectionMapSmooth(const SphereDiskMesh& domain, const SphereDiskMesh& codomain,
                            const MobiusBlend& domainBlend, const MobiusBlend& codomainBlend,
                            const DiskLocator& codomainDisk, int threads, CubeMap& out,
                            std::vector<std::uint8_t>& covered, Progress* progress);

// The blending weights of barycentric coordinates b: b_j^2 / sum b^2 (negative b clamped to 0).
std::array<double, 3> mobiusBlendWeights(const std::array<double, 3>& b);

}  // namespace confvis::detail
