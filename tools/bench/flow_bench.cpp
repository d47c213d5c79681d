// Ricci flow benchmark (run by hand, never in CI): Riemann disk maps of asymmetric disk meshes
// for every scheme, against one sparse Cholesky factorisation of the same mesh's cotangent
// Laplacian measured in the same run — the flow's cost as a multiple of that single solve.
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/mesh_generators.hpp"

using namespace confvis::conformal;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Peak resident memory since the last reset, in MiB (Linux: VmHWM, reset via clear_refs).
void resetPeakMemory() { std::ofstream("/proc/self/clear_refs") << "5"; }
double peakMemoryMiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

// One LDLᵀ (symbolic + numeric) of the cotangent Laplacian, pinned like the flow's system.
double choleskySeconds(const TriMesh& mesh) {
  const auto tri = buildTriangulation(mesh);
  std::vector<Eigen::Triplet<double>> t;
  for (int f = 0; f < tri.faceCount(); ++f) {
    const auto& fv = tri.faceVertices[f];
    for (int c = 0; c < 3; ++c) {
      const auto& p = mesh.point(TriMesh::VertexHandle(fv[c]));
      const auto a = mesh.point(TriMesh::VertexHandle(fv[(c + 1) % 3])) - p;
      const auto b = mesh.point(TriMesh::VertexHandle(fv[(c + 2) % 3])) - p;
      const double w = 0.5 * (a | b) / (a % b).norm();
      const int i = fv[(c + 1) % 3], j = fv[(c + 2) % 3];
      if (i == 0 || j == 0) continue;
      t.emplace_back(std::max(i, j) - 1, std::min(i, j) - 1, -w);
      t.emplace_back(i - 1, i - 1, w);
      t.emplace_back(j - 1, j - 1, w);
    }
  }
  Eigen::SparseMatrix<double> L(tri.vertexCount - 1, tri.vertexCount - 1);
  L.setFromTriplets(t.begin(), t.end());
  double best = 1e30;
  for (int rep = 0; rep < 3; ++rep) {
    const auto start = Clock::now();
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver(L);
    best = std::min(best, secondsSince(start));
    if (solver.info() != Eigen::Success) std::fprintf(stderr, "baseline factorisation failed\n");
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sides{100, 316};  // ≈10k and ≈100k vertices
  if (argc > 1 && std::string(argv[1]) == "--with-1m") sides.push_back(1000);
  std::printf("| vertices | scheme | iterations | flips | seconds | x Cholesky | peak MiB | max |K̄-K| | "
              "σ-ratio p50 | p99 | flipped |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int side : sides) {
    const TriMesh mesh = makeLopsidedDisk(side, 0.2, 42);
    const double cholesky = choleskySeconds(mesh);
    std::printf("| %zu | *one cotangent-Laplacian LDLT* | | | %.3f | 1.0 | | | | | |\n",
                mesh.n_vertices(), cholesky);
    for (Scheme scheme : kAllSchemes) {
      DiskMapOptions options;
      options.scheme = scheme;
      resetPeakMemory();
      const auto start = Clock::now();
      try {
        const DiskMap map = computeDiskMap(mesh, options);
        const double seconds = secondsSince(start);
        const double peak = peakMemoryMiB();
        const auto stats = measureDistortion(mesh, map.uv);
        std::printf("| %zu | %s | %d | %d | %.3f | %.1f | %.0f | %.1e | %.4f | %.4f | %d |\n",
                    mesh.n_vertices(), toString(scheme), map.flow.iterations, map.flow.flips,
                    seconds, seconds / cholesky, peak, map.flow.maxCurvatureError, stats.ratioP50,
                    stats.ratioP99, stats.flippedFaces);
      } catch (const std::exception& e) {
        std::printf("| %zu | %s | failed: %s |\n", mesh.n_vertices(), toString(scheme), e.what());
      }
      std::fflush(stdout);
    }
  }
}
