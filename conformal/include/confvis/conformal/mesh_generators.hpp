#pragma once
// Synthetic meshes with known topology and, where useful, known conformal maps: used by the
// tests (closed forms) and by tools/bench (large asymmetric disks).
#include <cstdint>

#include "confvis/base/export.hpp"
#include "confvis/conformal/mesh.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

// An n×n-quad grid on [-1,1]², each quad split along a diagonal chosen at random, vertices
// jittered by `jitter` × the spacing (boundary vertices only along the boundary).
TriMesh makeGridDisk(int n, double jitter = 0.0, std::uint64_t seed = 1);

// The grid disk mapped onto the round unit disk (elliptical square-to-disk map, not conformal):
// boundary vertices lie exactly on the unit circle, z = 0.
TriMesh makeRoundDisk(int n, double jitter = 0.0, std::uint64_t seed = 1);

// The round disk lifted onto the upper unit hemisphere (z ≥ 0) by polar angle = r·π/2 — a
// non-conformal parametrisation, so the Riemann map still has work to do. Boundary = equator.
TriMesh makeHemisphere(int n, double jitter = 0.0, std::uint64_t seed = 1);

// A lopsided, curved disk: the grid disk bent by a smooth non-conformal deformation and lifted
// into 3D (asymmetric in every axis), for robustness tests and benchmarks.
TriMesh makeLopsidedDisk(int n, double jitter = 0.25, std::uint64_t seed = 1);

// A closed genus-0 mesh: the icosahedron subdivided `levels` times, on the unit sphere.
TriMesh makeIcosphere(int levels);

// A grid disk with two square holes: Euler characteristic -1 (a pair of pants).
TriMesh makeDiskWithTwoHoles(int n);

}  // namespace conformal
}  // namespace confvis
