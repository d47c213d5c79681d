#include "confvis/conformal/obj_output.hpp"

#include <cstdio>
#include <fstream>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"

namespace confvis::conformal {

void writeObjWithDiskCoordinates(const std::filesystem::path& path, const TriMesh& mesh,
                                 const std::vector<std::complex<double>>& uv) {
  if (uv.size() != mesh.n_vertices())
    throw Error(ErrorCode::Internal, "one disk coordinate per vertex expected");
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << "# confvis disk map: vt = unit-disk coordinates of each vertex\n";
    char line[128];
    for (auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
      out << line;
    }
    for (const auto& z : uv) {
      std::snprintf(line, sizeof line, "vt %.17g %.17g\n", z.real(), z.imag());
      out << line;
    }
    for (auto f : mesh.faces()) {
      out << 'f';
      for (auto v : f.vertices()) out << ' ' << v.idx() + 1 << '/' << v.idx() + 1;
      out << '\n';
    }
    out.close();
    if (!out) throw Error(ErrorCode::IoFailure, "cannot write '" + path.string() + "'");
  });
}

}  // namespace confvis::conformal
