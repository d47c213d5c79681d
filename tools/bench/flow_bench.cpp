// Ricci flow benchmark (run by hand, never in CI): Riemann disk maps of asymmetric disk meshes
// for every scheme and route (background geometry), against one sparse Cholesky factorisation
// (symbolic analysis + numeric factorisation) of the same mesh's cotangent Laplacian measured in
// the same run — the flow's cost as a multiple of that single solve is the headline figure. On
// the hemisphere mesh it also prints the distance to the stereographic projection.
//
//   confvis_bench_flow [--sizes 10k,100k,1m] [--schemes yamabe,inversive,...|all]
//                      [--geometry euclidean,spherical,hyperbolic|all]
//                      [--flips auto|on|off] [--guess on|off] [--repeat N] [--jitter J] [--seed S]
//                      [--mesh lopsided|hemisphere|round] [--breakdown]
#include <Eigen/SparseCholesky>

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/mesh_generators.hpp"

using namespace confvis::conformal;
using confvis::SteadyClock;
using confvis::secondsSince;

namespace {


// CPU time of the whole process (all threads): steadier than wall time on a shared machine,
// where other jobs take the cores away at random.
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Timing {
  double seconds = 1e30, cpuSeconds = 1e30;  // each the best of the repeats
};

// Peak resident memory in MiB: getrusage's lifetime maximum, and VmHWM, which Linux lets us
// reset (clear_refs) so that each run gets its own peak.
void resetPeakMemory() { std::ofstream("/proc/self/clear_refs") << "5"; }
double peakMemoryMiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// The cotangent Laplacian of the mesh with vertex 0 pinned, as the flow's system is.
Eigen::SparseMatrix<double> pinnedCotangentLaplacian(const TriMesh& mesh) {
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
  return L;
}

// One sparse Cholesky: Eigen's simplicial LDLᵀ, symbolic analysis (AMD ordering) + numeric
// factorisation — the same factorisation the flow uses.
void timeCholesky(const Eigen::SparseMatrix<double>& L, Timing& best) {
  const auto start = SteadyClock::now();
  const double cpuStart = processCpuSeconds();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  solver.analyzePattern(L);
  solver.factorize(L);
  best.seconds = std::min(best.seconds, secondsSince(start));
  best.cpuSeconds = std::min(best.cpuSeconds, processCpuSeconds() - cpuStart);
  if (solver.info() != Eigen::Success) std::fprintf(stderr, "baseline factorisation failed\n");
}

// "10k" → 10000, "1m" → 1000000, "1500" → 1500.
int parseCount(std::string s) {
  double scale = 1;
  if (!s.empty() && (s.back() == 'k' || s.back() == 'K')) scale = 1e3, s.pop_back();
  else if (!s.empty() && (s.back() == 'm' || s.back() == 'M')) scale = 1e6, s.pop_back();
  return static_cast<int>(std::stod(s) * scale);
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// Max distance of the map to the hemisphere's stereographic projection, both aligned at the
// boundary vertices nearest to azimuths 0°, 120°, 240° (as the DiskMap.Hemisphere* tests do).
double stereographicError(const TriMesh& mesh, std::vector<std::complex<double>> uv) {
  std::array<int, 3> marker{};
  std::array<double, 3> nearest{1e9, 1e9, 1e9};
  std::vector<std::complex<double>> stereo;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    stereo.emplace_back(p[0] / (1 + p[2]), p[1] / (1 + p[2]));
    if (!mesh.is_boundary(v)) continue;
    for (int k = 0; k < 3; ++k) {
      const double d = std::abs(std::complex<double>(p[0], p[1]) - std::polar(1.0, 2 * std::numbers::pi * k / 3));
      if (d < nearest[k]) nearest[k] = d, marker[k] = v.idx();
    }
  }
  alignDiskMap(uv, marker[0], marker[1], marker[2]);
  alignDiskMap(stereo, marker[0], marker[1], marker[2]);
  double error = 0;
  for (std::size_t i = 0; i < uv.size(); ++i) error = std::max(error, std::abs(uv[i] - stereo[i]));
  return error;
}

[[noreturn]] void usage(int code) {
  std::printf(
      "usage: confvis_bench_flow [--sizes 10k,100k,1m | --with-1m] [--schemes yamabe,...|all]\n"
      "                          [--geometry euclidean,spherical,hyperbolic|all]\n"
      "                          [--flips auto|on|off] [--guess on|off] [--repeat N]\n"
      "                          [--jitter J] [--seed S]\n"
      "                          [--mesh lopsided|hemisphere|round] [--breakdown]\n"
      "Disk maps of disk meshes (default lopsided) of about the given vertex counts (default\n"
      "10k,100k) by each route (default euclidean); seconds are the best of N runs (default 3),\n"
      "interleaved with the baseline's; 'CPU x Cholesky' is the same ratio in process CPU time\n"
      "(all threads), steadier on a loaded machine; on --mesh hemisphere, 'stereo' is the max\n"
      "distance to the stereographic projection after aligning both at three boundary markers;\n"
      "--guess: the Euclidean route's flattening guess (DiskMapOptions::flatteningGuess, on by\n"
      "default); --breakdown prints where the flow's time went and its error history to stderr.\n");
  std::exit(code);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{10000, 100000};
  std::vector<Scheme> schemes(kAllSchemes.begin(), kAllSchemes.end());
  std::vector<Geometry> routes{Geometry::Euclidean};
  FlipPolicy flips = FlipPolicy::Auto;
  bool guess = DiskMapOptions{}.flatteningGuess;
  int repeat = 3;
  double jitter = 0.2;
  std::uint64_t seed = 42;
  bool breakdown = false;
  std::string shape = "lopsided";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") usage(0);
    if (arg == "--breakdown") {
      breakdown = true;
      continue;
    }
    if (arg == "--with-1m") {  // the older spelling of --sizes 10k,100k,1m
      sizes = {10000, 100000, 1000000};
      continue;
    }
    if (i + 1 >= argc) usage(2);
    const std::string value = argv[++i];
    if (arg == "--sizes") {
      sizes.clear();
      for (const auto& s : splitList(value)) sizes.push_back(parseCount(s));
    } else if (arg == "--schemes") {
      if (value != "all") {
        schemes.clear();
        for (const auto& s : splitList(value)) schemes.push_back(parseScheme(s));
      }
    } else if (arg == "--geometry") {
      routes.assign(kAllGeometries.begin(), kAllGeometries.end());
      if (value != "all") {
        routes.clear();
        for (const auto& g : splitList(value)) routes.push_back(parseGeometry(g));
      }
    } else if (arg == "--flips") {
      flips = value == "on" ? FlipPolicy::On : value == "off" ? FlipPolicy::Off : FlipPolicy::Auto;
    } else if (arg == "--guess") {
      if (value != "on" && value != "off") usage(2);
      guess = value == "on";
    } else if (arg == "--repeat") {
      repeat = std::max(1, std::atoi(value.c_str()));
    } else if (arg == "--mesh") {
      shape = value;
      if (shape != "lopsided" && shape != "hemisphere" && shape != "round") usage(2);
    } else if (arg == "--jitter") {
      jitter = std::stod(value);
    } else if (arg == "--seed") {
      seed = std::strtoull(value.c_str(), nullptr, 10);
    } else {
      usage(2);
    }
  }
  struct Config {
    Geometry route;
    Scheme scheme;
  };
  std::vector<Config> configs;
  for (Geometry route : routes)
    for (Scheme scheme : schemes) configs.push_back({route, scheme});
  std::printf("| vertices | route | scheme | iterations | factorisations | flips | seconds | "
              "x Cholesky | CPU x Cholesky | peak MiB | max abs(K̄-K) | σ-ratio p50 | p99 | "
              "flipped | stereo |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int count : sizes) {
    const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(count))));
    const TriMesh mesh = shape == "hemisphere" ? makeHemisphere(side, jitter, seed)
                         : shape == "round"    ? makeRoundDisk(side, jitter, seed)
                                               : makeLopsidedDisk(side, jitter, seed);
    const auto laplacian = pinnedCotangentLaplacian(mesh);
    // Repeats interleave the baseline with the flows so both see the same machine load; each
    // figure is the best of its repeats.
    Timing cholesky;
    struct Result {
      Timing timing;
      double peak = 0;
      DiskMap map;
      std::string failure;
    };
    std::vector<Result> results(configs.size());
    for (int rep = 0; rep < repeat; ++rep) {
      timeCholesky(laplacian, cholesky);
      for (std::size_t k = 0; k < configs.size(); ++k) {
        DiskMapOptions options;
        options.geometry = configs[k].route;
        options.scheme = configs[k].scheme;
        options.flips = flips;
        options.flatteningGuess = guess;
        Result& result = results[k];
        if (!result.failure.empty()) continue;
        try {
          resetPeakMemory();
          const auto start = SteadyClock::now();
          const double cpuStart = processCpuSeconds();
          DiskMap map = computeDiskMap(mesh, options);
          const double seconds = secondsSince(start);
          result.timing.cpuSeconds =
              std::min(result.timing.cpuSeconds, processCpuSeconds() - cpuStart);
          result.peak = std::max(result.peak, peakMemoryMiB());
          if (seconds < result.timing.seconds) {
            result.timing.seconds = seconds;
            result.map = std::move(map);
          }
        } catch (const std::exception& e) {
          result.failure = e.what();
        }
      }
    }
    std::printf("| %zu | *one cotangent-Laplacian LDLT* | | | | | %.4f | 1.0 | 1.0 (%.4f s) | | | | | | |\n",
                mesh.n_vertices(), cholesky.seconds, cholesky.cpuSeconds);
    for (std::size_t k = 0; k < configs.size(); ++k) {
      const Result& result = results[k];
      const char* name = toString(configs[k].scheme);
      const char* route = toString(configs[k].route);
      if (!result.failure.empty()) {
        std::printf("| %zu | %s | %s | failed: %s |\n", mesh.n_vertices(), route, name,
                    result.failure.c_str());
        continue;
      }
      const DiskMap& map = result.map;
      const auto stats = measureDistortion(mesh, map.uv);
      char stereo[32] = "";
      if (shape == "hemisphere")
        std::snprintf(stereo, sizeof stereo, "%.2e", stereographicError(mesh, map.uv));
      std::printf("| %zu | %s | %s | %d | %d | %d | %.4f | %.2f | %.2f | %.0f | %.1e | %.4f | %.4f | "
                  "%d | %s |\n",
                  mesh.n_vertices(), route, name, map.flow.iterations, map.flow.factorizations,
                  map.flow.flips, result.timing.seconds, result.timing.seconds / cholesky.seconds,
                  result.timing.cpuSeconds / cholesky.cpuSeconds, result.peak,
                  map.flow.maxCurvatureError, stats.ratioP50, stats.ratioP99, stats.flippedFaces,
                  stereo);
      if (breakdown) {
        const auto& t = map.flow.seconds;
        std::fprintf(stderr,
                     "  %s: evaluation %.4f assembly %.4f analysis %.4f factorisation %.4f "
                     "solve %.4f (%d CG steps) flips %.4f, rest %.4f; %d evaluations; errors",
                     name, t.evaluation, t.assembly, t.analysis, t.factorization, t.solve,
                     map.flow.cgIterations, t.flips,
                     result.timing.seconds - t.evaluation - t.assembly - t.analysis - t.factorization -
                         t.solve - t.flips,
                     map.flow.evaluations);
        for (double e : map.flow.errorHistory) std::fprintf(stderr, " %.1e", e);
        std::fprintf(stderr, "\n");
      }
    }
    std::fflush(stdout);
  }
}
