#include "confvis/conformal/mesh_generators.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "confvis/base/error.hpp"

namespace confvis::conformal {
namespace {

// Grid vertices (i, j) for i, j in [0, n]; `skip(i, j)` removes quad (i, j).
template <typename Skip>
TriMesh gridMesh(int n, double jitter, std::uint64_t seed, Skip skip) {
  if (n < 1) throw Error(ErrorCode::InvalidInput, "grid resolution must be at least 1");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const double h = 2.0 / n;
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> vh((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = -1 + i * h, y = -1 + j * h;
      const bool bx = i == 0 || i == n, by = j == 0 || j == n;
      const double dx = jitter * h * 0.5 * uni(rng), dy = jitter * h * 0.5 * uni(rng);
      if (!bx) x += dx;  // boundary vertices slide only along the boundary, corners stay
      if (!by) y += dy;
      vh[j * (n + 1) + i] = mesh.add_vertex(Vec3(x, y, 0));
    }
  std::bernoulli_distribution coin(0.5);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool flipDiagonal = jitter > 0 ? coin(rng) : ((i + j) % 2 == 0);
      if (skip(i, j)) continue;
      auto a = vh[j * (n + 1) + i], b = vh[j * (n + 1) + i + 1];
      auto c = vh[(j + 1) * (n + 1) + i + 1], d = vh[(j + 1) * (n + 1) + i];
      if (flipDiagonal) {
        mesh.add_face(a, b, d);
        mesh.add_face(b, c, d);
      } else {
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
      }
    }
  mesh.garbage_collection();
  return mesh;
}

}  // namespace

TriMesh makeGridDisk(int n, double jitter, std::uint64_t seed) {
  return gridMesh(n, jitter, seed, [](int, int) { return false; });
}

TriMesh makeRoundDisk(int n, double jitter, std::uint64_t seed) {
  TriMesh mesh = makeGridDisk(n, jitter, seed);
  for (auto v : mesh.vertices()) {
    auto& p = mesh.point(v);
    const double x = p[0], y = p[1];
    p = Vec3(x * std::sqrt(1 - y * y / 2), y * std::sqrt(1 - x * x / 2), 0);
  }
  return mesh;
}

TriMesh makeHemisphere(int n, double jitter, std::uint64_t seed) {
  TriMesh mesh = makeRoundDisk(n, jitter, seed);
  for (auto v : mesh.vertices()) {
    auto& p = mesh.point(v);
    const double r = std::min(1.0, std::hypot(p[0], p[1]));
    const double polar = r * std::numbers::pi / 2, azimuth = std::atan2(p[1], p[0]);
    p = Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
             std::cos(polar));
  }
  return mesh;
}

TriMesh makeLopsidedDisk(int n, double jitter, std::uint64_t seed) {
  TriMesh mesh = makeGridDisk(n, jitter, seed);
  for (auto v : mesh.vertices()) {
    auto& p = mesh.point(v);
    const double x = p[0], y = p[1];
    const double X = 1.7 * x + 0.35 * x * y + 0.2 * y * y;
    const double Y = 0.8 * y + 0.25 * std::sin(2.0 * x) + 0.1 * x * x;
    const double Z = 0.45 * std::exp(-2 * ((x - 0.4) * (x - 0.4) + (y + 0.3) * (y + 0.3))) +
                     0.15 * x * y;
    p = Vec3(X, Y, Z);
  }
  return mesh;
}

TriMesh makeIcosphere(int levels) {
  TriMesh mesh;
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0},   {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t},   {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1},   {-t, 0, -1}, {-t, 0, 1}};
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  std::vector<Vec3> points;
  for (auto& b : base) points.push_back(Vec3(b[0], b[1], b[2]).normalized());
  std::vector<std::array<int, 3>> tris;
  for (auto& f : faces) tris.push_back({f[0], f[1], f[2]});
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(points.size()));
      if (inserted) points.push_back((points[a] + points[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> next;
    for (auto& f : tris) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris.swap(next);
  }
  std::vector<TriMesh::VertexHandle> vh;
  for (auto& p : points) vh.push_back(mesh.add_vertex(p));
  for (auto& f : tris) mesh.add_face(vh[f[0]], vh[f[1]], vh[f[2]]);
  return mesh;
}

TriMesh makeDiskWithTwoHoles(int n) {
  if (n < 7) throw Error(ErrorCode::InvalidInput, "disk with two holes needs n >= 7");
  const int a = n / 4, b = (3 * n) / 4 - 1, mid = n / 2;
  return gridMesh(n, 0.0, 1, [&](int i, int j) { return j == mid && (i == a || i == b); });
}

}  // namespace confvis::conformal
