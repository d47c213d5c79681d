#pragma once
// Writes a mesh with per-vertex disk coordinates as OBJ: input vertices in input order, one
// `vt` per vertex, faces as `f v/vt`. Written atomically.
#include <complex>
#include <filesystem>
#include <vector>

#include "confvis/conformal/mesh.hpp"

namespace confvis::conformal {

void writeObjWithDiskCoordinates(const std::filesystem::path& path, const TriMesh& mesh,
                                 const std::vector<std::complex<double>>& uv);

}  // namespace confvis::conformal
