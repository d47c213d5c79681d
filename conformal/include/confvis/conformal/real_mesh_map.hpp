#pragma once
// computeDiskMap for a mesh read from a file (scans, exports), where slivers and zero-area
// faces are common: the same routes, made to start and checked face by face on the file's own
// triangles, so a map that folds a face over is never returned, and errors name the file's faces.
#include <complex>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/mesh_source.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

struct RealMeshMap {
  DiskMap map;
  // Faces of (numerically) zero area whose vertex off the longest edge was moved off it in
  // space, so that the flow can start (by 1e-4 rad of the face's angles: the map of a
  // neighbourhood that small is unchanged to the flow's accuracy); the output keeps the input's
  // positions.
  int mollifiedFaces = 0;
  // Interior vertices moved in the disk so that no face folds over (a sliver laid out across its
  // long edge: with flips the flow's triangulation is not the input's, and the spherical and
  // hyperbolic routes' final projections bend straight edges), and the largest move in units of
  // the moved vertex's shortest edge in the disk.
  int untangledVertices = 0;
  double largestUntangleShift = 0;
};

// Triangles of `mesh` whose image under `uv` (one point per vertex) is not counter-clockwise
// with positive area: folded over, or collapsed to a segment or a point.
std::vector<int> foldedTriangles(const TriMesh& mesh, const std::vector<std::complex<double>>& uv);

// Moves interior vertices of folded triangles, each to a point of the kernel of its ring of
// triangles near where it was, until no triangle folds; returns the vertices moved (-1 if some
// fold could not be undone this way) and the largest move relative to the vertex's shortest edge.
int untangleFolds(const TriMesh& mesh, std::vector<std::complex<double>>& uv, double& largestShift);

// Moves, in a copy of `mesh`, the vertex off the longest edge of every triangle whose triangle
// inequality holds with less slack than a flow needs to start (zero-area faces: a vertex on its
// neighbour's edge, T-junctions closed by a flat face), along the surface's normal side, so that
// the face's angles differ from 0 and π by 1e-4 rad; returns the number of faces moved.
int mollifyDegenerateFaces(TriMesh& mesh);

// computeDiskMap on the mollified mesh, then untangled and checked: if a fold remains after a
// flow with flips under options.flips Auto, computed again with flips off. Throws Error(Unreachable) naming
// the file's folded faces (and their largest angle in space: slivers are the usual cause) if no
// attempt is fold-free; other errors of the routes come with the file's name and each attempt.
RealMeshMap computeRealMeshDiskMap(const TriMesh& mesh, const MeshSource& source,
                                   const DiskMapOptions& options);

}  // namespace conformal
}  // namespace confvis
