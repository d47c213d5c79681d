#include "confvis/conformal/obj_output.hpp"

#include <cstdio>
#include <fstream>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"

namespace confvis::conformal {

void writeObjWithDiskCoordinates(const std::filesystem::path& path, const TriMesh& mesh,
                                 const std::vector<std::complex<double>>& uv) {
  std::vector<Vec3d> positions;
  positions.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    positions.push_back({p[0], p[1], p[2]});
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.n_faces());
  for (auto f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : f.vertices())
      if (k < 3) t[k++] = v.idx();
    triangles.push_back(t);
  }
  writeObjWithDiskCoordinates(path, positions, triangles, uv);
}

void writeObjWithDiskCoordinates(const std::filesystem::path& path,
                                 const std::vector<Vec3d>& positions,
                                 const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<std::complex<double>>& uv) {
  if (uv.size() != positions.size())
    throw Error(ErrorCode::Internal, "one disk coordinate per vertex expected");
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << "# confvis disk map: vt = unit-disk coordinates of each vertex\n";
    char line[128];
    for (const Vec3d& p : positions) {
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
      out << line;
    }
    for (const auto& z : uv) {
      std::snprintf(line, sizeof line, "vt %.17g %.17g\n", z.real(), z.imag());
      out << line;
    }
    for (const auto& t : triangles)
      out << 'f' << ' ' << t[0] + 1 << '/' << t[0] + 1 << ' ' << t[1] + 1 << '/' << t[1] + 1 << ' '
          << t[2] + 1 << '/' << t[2] + 1 << '\n';
    out.close();
    if (!out) throw Error(ErrorCode::IoFailure, "cannot write '" + path.string() + "'");
  });
}

}  // namespace confvis::conformal
