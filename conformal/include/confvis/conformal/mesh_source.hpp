#pragma once
// Where a mesh read from a file came from: which of the file's vertices and faces each mesh
// vertex and triangle is, so that errors about the mesh name places as the file numbers them
// (not the indices of the cleaned-up copy the algorithms work on).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/conformal/mesh.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct MeshSource {
  std::filesystem::path path;
  std::string format;        // "OBJ", "OFF", "PLY" or "STL"
  int firstNumber = 1;       // the file's numbering: from 1 (OBJ; STL facets) or 0 (OFF, PLY)
  std::vector<int> fileVertex;  // per mesh vertex: its index in the file's vertex list (from 0)
  std::vector<int> fileFace;    // per mesh triangle: the file's face (polygon) it was fanned from
  int weldedVertices = 0;       // file vertices merged into an earlier one at the same position
  int unreferencedVertices = 0; // file vertices no face uses, left out of the mesh
  std::vector<std::array<double, 3>> filePoints;

  // "vertex 12 (0.1, 0.2, 0.3)" and "face 7", numbered as the file numbers them.
  std::string fileVertexName(int fileIndex) const;
  std::string vertexName(int meshVertex) const { return fileVertexName(fileVertex.at(meshVertex)); }
  std::string faceName(int meshTriangle) const;
  // "faces and vertices numbered from 1 as in the OBJ file"
  std::string numbering() const;
};

// readMesh that also says where each vertex and triangle came from. Vertices at bitwise-equal
// positions (exporters split them at texture seams) are welded when the welded mesh is manifold
// and consistently oriented; vertices no face uses are left out. Before any of that, and before
// OpenMesh sees the faces, an edge of more than two faces, a vertex joining separate fans of
// faces (a bowtie), or faces listed against their neighbours' orientation are refused with
// Error(InvalidInput) naming the file's faces and vertices.
TriMesh readMesh(const std::filesystem::path& path, MeshSource& source);

// requireDisk naming the file's places: each separate piece by a face in it, each extra
// boundary loop (a hole) by vertices on it, as well as the counts.
void requireDisk(const TriMesh& mesh, const MeshSource& source);

}  // namespace conformal
}  // namespace confvis
