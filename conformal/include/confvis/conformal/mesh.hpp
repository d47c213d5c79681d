#pragma once
// The mesh type every conformal algorithm works on: an OpenMesh half-edge triangle mesh with
// double-precision points (curvature to 1e-10 needs doubles end to end).
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <filesystem>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;
using Vec3 = TriMesh::Point;

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct MeshTopology {
  int vertices = 0;
  int edges = 0;
  int faces = 0;
  int boundaryLoops = 0;
  int isolatedVertices = 0;
  int eulerCharacteristic = 0;  // V - E + F
  int components = 0;
  bool isDisk() const {
    return components == 1 && boundaryLoops == 1 && eulerCharacteristic == 1 &&
           isolatedVertices == 0;
  }
  std::string describe() const;  // "V=…, F=…, Euler characteristic …, … boundary loops"
};

MeshTopology analyzeTopology(const TriMesh& mesh);

// Throws Error(InvalidInput) naming `what` unless the mesh is a single topological disk.
void requireDisk(const TriMesh& mesh, const std::string& what);

// Reads OBJ, OFF, PLY (ascii, binary) and STL (ascii, binary) with confvis's own bounded readers
// (limits in the README). Throws FileNotFound / InvalidInput with the path (and line); rejects
// malformed files, meshes with no faces, non-manifold edges or vertices, inconsistently oriented
// faces, non-finite coordinates or zero-length edges, naming them as the file numbers them; welds
// vertices at equal positions and leaves out unused ones (mesh_source.hpp).
TriMesh readMesh(const std::filesystem::path& path);

// Boundary loops as vertex index lists, each following the boundary half-edges.
std::vector<std::vector<int>> boundaryLoops(const TriMesh& mesh);

}  // namespace conformal
}  // namespace confvis
