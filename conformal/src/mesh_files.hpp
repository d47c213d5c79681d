#pragma once
// Our own readers of the mesh files `confvis flow` takes (OBJ, OFF, PLY ascii/binary, STL
// ascii/binary), private to confvis_conformal. OpenMesh's readers hang, grow without bound or
// crash on small malformed files (a PLY "element face -inf", an OFF face of valence -1) and
// accept NaN vertices; these check every count, valence and size against the file before
// allocating anything of that size, and name the file and line of the first problem.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace confvis::conformal::detail {

// Documented limits (README): beyond them a file is refused, whatever its size.
inline constexpr std::size_t kMaxMeshVertices = std::size_t{1} << 24;
inline constexpr std::size_t kMaxMeshFaces = std::size_t{1} << 25;
inline constexpr std::size_t kMaxFaceValence = 1024;

struct PolygonSoup {
  std::vector<std::array<double, 3>> points;
  std::vector<int> corners;         // vertex indices, face after face
  std::vector<std::size_t> starts;  // first corner of each face; corners.size() closes the last
};

// By extension (.obj, .off, .ply, .stl, any case). Throws Error(InvalidInput) naming the file
// (and line where there is one) for anything malformed, Error(FileNotFound) if it cannot be read.
PolygonSoup readPolygonFile(const std::filesystem::path& path);

}  // namespace confvis::conformal::detail
