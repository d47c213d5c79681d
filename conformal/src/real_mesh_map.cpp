#include "confvis/conformal/real_mesh_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "confvis/base/error.hpp"

namespace confvis::conformal {
namespace {

using Complex = std::complex<double>;

std::array<int, 3> cornersOf(const TriMesh& mesh, int face) {
  std::array<int, 3> v{};
  int k = 0;
  for (auto vh : mesh.fv_range(TriMesh::FaceHandle(face)))
    if (k < 3) v[k++] = vh.idx();
  return v;
}

Vec3 point(const TriMesh& mesh, int v) { return mesh.point(TriMesh::VertexHandle(v)); }

// The largest corner angle of a triangle in space, in degrees.
double largestAngleDegrees(const TriMesh& mesh, int face) {
  const auto v = cornersOf(mesh, face);
  double largest = 0;
  for (int c = 0; c < 3; ++c) {
    const Vec3 a = point(mesh, v[(c + 1) % 3]) - point(mesh, v[c]);
    const Vec3 b = point(mesh, v[(c + 2) % 3]) - point(mesh, v[c]);
    largest = std::max(largest, std::atan2((a % b).norm(), a | b));
  }
  return largest * 180 / std::numbers::pi;
}

std::string describeFolds(const TriMesh& mesh, const MeshSource& source,
                          const std::vector<int>& folded) {
  std::ostringstream s;
  s.precision(6);
  s << folded.size() << " face" << (folded.size() == 1 ? "" : "s") << ": ";
  for (std::size_t i = 0; i < std::min<std::size_t>(folded.size(), 5); ++i)
    s << (i > 0 ? ", " : "") << source.faceName(folded[i]) << " (largest angle "
      << largestAngleDegrees(mesh, folded[i]) << "°)";
  if (folded.size() > 5) s << " and " << folded.size() - 5 << " more";
  return s.str();
}

double cross(Complex a, Complex b) { return a.real() * b.imag() - a.imag() * b.real(); }

// Moves uv[v] into the kernel of its ring: left of every opposite edge p→q of its triangles
// (v, p, q) by a margin, by cyclic projections onto the violated half-planes from where it is.
bool moveIntoKernel(const TriMesh& mesh, int v, std::vector<Complex>& uv, double& shift) {
  struct HalfPlane {
    Complex p, normal;  // inside: (x - p)·normal >= margin
    double margin;
  };
  std::vector<HalfPlane> planes;
  double shortest = std::numeric_limits<double>::infinity();
  for (auto fh : mesh.vf_range(TriMesh::VertexHandle(v))) {
    auto c = cornersOf(mesh, fh.idx());
    while (c[0] != v) std::rotate(c.begin(), c.begin() + 1, c.end());
    const Complex p = uv[c[1]], q = uv[c[2]];
    const Complex along = q - p;
    const double length = std::abs(along);
    if (!(length > 0)) return false;
    planes.push_back({p, Complex(-along.imag(), along.real()) / length, 1e-6 * length});
    shortest = std::min({shortest, std::abs(p - uv[v]), length});
  }
  const Complex start = uv[v];
  Complex x = start;
  for (int sweep = 0; sweep < 1000; ++sweep) {
    bool inside = true;
    for (const HalfPlane& h : planes) {
      const double d = (x - h.p).real() * h.normal.real() + (x - h.p).imag() * h.normal.imag();
      if (d < h.margin) {
        x += (2 * h.margin - d) * h.normal;
        inside = false;
      }
    }
    if (inside) {
      uv[v] = x;
      shift = std::max(shift, std::abs(x - start) / shortest);
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<int> foldedTriangles(const TriMesh& mesh, const std::vector<Complex>& uv) {
  std::vector<int> folded;
  for (int f = 0; f < static_cast<int>(mesh.n_faces()); ++f) {
    const auto v = cornersOf(mesh, f);
    if (!(cross(uv.at(v[1]) - uv.at(v[0]), uv.at(v[2]) - uv.at(v[0])) > 0)) folded.push_back(f);
  }
  return folded;
}

int untangleFolds(const TriMesh& mesh, std::vector<Complex>& uv, double& largestShift) {
  std::vector<char> moved(mesh.n_vertices(), 0);
  for (int round = 0; round < 10; ++round) {
    const std::vector<int> folded = foldedTriangles(mesh, uv);
    if (folded.empty()) return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
    for (int f : folded) {
      // The interior corner whose move is smallest: the one nearest the line through the others.
      const auto c = cornersOf(mesh, f);
      int best = -1;
      double bestDistance = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) {
        if (mesh.is_boundary(TriMesh::VertexHandle(c[k]))) continue;
        const Complex a = uv[c[(k + 1) % 3]], b = uv[c[(k + 2) % 3]];
        const double d = std::abs(cross(b - a, uv[c[k]] - a)) / std::max(std::abs(b - a), 1e-300);
        if (d < bestDistance) bestDistance = d, best = c[k];
      }
      if (best < 0 || !moveIntoKernel(mesh, best, uv, largestShift)) return -1;
      moved[best] = 1;
    }
  }
  return foldedTriangles(mesh, uv).empty()
             ? static_cast<int>(std::count(moved.begin(), moved.end(), 1))
             : -1;
}

int mollifyDegenerateFaces(TriMesh& mesh) {
  constexpr double kAngle = 1e-4;  // rad: what the moved vertex's face keeps off 0 and π
  int moved = 0;
  for (int f = 0; f < static_cast<int>(mesh.n_faces()); ++f) {
    const auto v = cornersOf(mesh, f);
    // The longest edge, opposite corner k.
    int k = 0;
    double longest = 0;
    for (int c = 0; c < 3; ++c) {
      const double l = (point(mesh, v[(c + 1) % 3]) - point(mesh, v[(c + 2) % 3])).norm();
      if (l > longest) longest = l, k = c;
    }
    const Vec3 a = point(mesh, v[(k + 1) % 3]), b = point(mesh, v[(k + 2) % 3]), m = point(mesh, v[k]);
    const double am = (m - a).norm(), mb = (b - m).norm();
    // Triangle-inequality slack below what a cap of angle π - kAngle/8 has.
    if ((am + mb - longest) > 1e-10 * longest) continue;
    // The side the face's neighbours face: their normals, summed.
    Vec3 normal(0, 0, 0);
    for (auto g : mesh.ff_range(TriMesh::FaceHandle(f))) normal += mesh.calc_face_normal(g);
    const Vec3 edge = b - a;
    // For the face (m, a, b) counter-clockwise about `normal`, m lies left of a→b: along n × e.
    Vec3 side = normal % edge;
    if (!(side.norm() > 0)) continue;  // no neighbour to take a side from: left to the flow
    side.normalize();
    const double height = kAngle / (1 / std::max(am, 1e-300) + 1 / std::max(mb, 1e-300));
    mesh.set_point(TriMesh::VertexHandle(v[k]), m + side * height);
    ++moved;
  }
  return moved;
}

RealMeshMap computeRealMeshDiskMap(const TriMesh& mesh, const MeshSource& source,
                                   const DiskMapOptions& options) {
  RealMeshMap result;
  TriMesh mollified = mesh;
  result.mollifiedFaces = mollifyDegenerateFaces(mollified);
  std::vector<std::string> failures;
  const auto name = [](FlipPolicy flips) {
    return std::string(flips == FlipPolicy::On ? "flips on" : flips == FlipPolicy::Off ? "flips off" : "flips auto");
  };
  // With flips the flow's triangulation is not the input's, so a map that folds an input face
  // the untangling cannot undo is tried once more without them (auto only).
  for (FlipPolicy flips = options.flips;;) {
    DiskMapOptions o = options;
    o.flips = flips;
    try {
      result.map = computeDiskMap(mollified, o);
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Unreachable && e.code() != ErrorCode::InvalidInput) throw;
      failures.push_back(name(flips) + ": " + e.what());
      break;
    }
    const std::vector<int> folded = foldedTriangles(mesh, result.map.uv);
    double shift = 0;
    const int untangled = untangleFolds(mesh, result.map.uv, shift);
    if (untangled >= 0) {
      result.untangledVertices = untangled;
      result.largestUntangleShift = shift;
      return result;
    }
    failures.push_back(name(flips) + ": converged, but the map folds over " +
                       describeFolds(mesh, source, folded) +
                       " and moving their vertices does not undo it");
    if (flips != FlipPolicy::Auto || !result.map.usedFlips) break;
    flips = FlipPolicy::Off;
  }
  std::string message = "mesh '" + source.path.string() + "': no fold-free disk map (" +
                        source.numbering() + ")";
  for (const std::string& f : failures) message += "; " + f;
  throw Error(ErrorCode::Unreachable, message);
}

}  // namespace confvis::conformal
