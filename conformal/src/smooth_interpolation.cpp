// Per-vertex Möbius blending (smooth_interpolation.hpp, map_interpolation.hpp).
#include "smooth_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace confvis::detail {
namespace {

using Complex = std::complex<double>;

constexpr double kPi = 3.14159265358979323846;
// Corners whose angle changes by more than this (radians) get a power chart (as singularCorners
// in map_accuracy.cpp).
constexpr double kCornerTurn = 0.2;

// a / b without the library's overflow-safe complex division (a call per texel otherwise):
// b is never near 0 or huge here.
inline Complex divide(Complex a, Complex b) {
  return a * std::conj(b) * (1.0 / std::norm(b));
}

Complex chartPoint(const MobiusBlend::Chart& chart, const Vec3d& x) {
  return Complex(dot(x, chart.e1), dot(x, chart.e2)) / (1.0 + dot(x, chart.p));
}

// z^gamma of a point of the wedge 0 <= arg <= wedge (< 2 pi; the branch cut opposite the wedge).
Complex wedgePower(Complex z, double wedge, double gamma) {
  double angle = std::arg(z);
  if (angle < 0.5 * wedge - kPi) angle += 2 * kPi;
  return std::polar(std::pow(std::abs(z), gamma), gamma * angle);
}

// The coordinate the vertex's Möbius map acts on: the stereographic chart, at a singular
// corner opened or closed to the disk's angle.
Complex localPoint(const MobiusBlend::Chart& chart, const Vec3d& x) {
  const Complex w = chartPoint(chart, x);
  if (chart.gamma == 1.0) return w;
  return wedgePower(w * std::conj(chart.turn), chart.sphereWedge, chart.gamma);
}

Complex chartFromLocal(const MobiusBlend::Chart& chart, Complex local) {
  if (chart.gamma == 1.0) return local;
  return wedgePower(local, chart.diskWedge, 1.0 / chart.gamma) * chart.turn;
}

// Vertex `chart`'s Möbius map at direction x, and its inverse at disk point z (a unit vector).
Complex chartToDisk(const MobiusBlend::Chart& chart, const Vec3d& x) {
  const Complex w = localPoint(chart, x);
  return chart.z0 + divide(chart.a * w, 1.0 + chart.c * w);
}

Vec3d chartToSphere(const MobiusBlend::Chart& chart, Complex z) {
  const Complex n = z - chart.z0;
  const Complex w = chartFromLocal(chart, divide(n, chart.a - chart.c * n));
  const double r2 = std::norm(w);
  return (1.0 / (1.0 + r2)) *
         (2 * w.real() * chart.e1 + 2 * w.imag() * chart.e2 + (1.0 - r2) * chart.p);
}

// A triangle is checked for folds where one of its corners' Möbius maps misses a neighbour's
// image by more than this fraction of the edge to it. The blend's Jacobian is the weighted mean
// of the corners' Jacobians plus (M_i - blend) x grad(weight_i), the weights' gradients ~2 / edge:
// it turns over only where the corners' maps disagree by a good fraction of the edge. On cave5
// this screens ~1 % of the triangles (conformal/README.md), and the unscreened rest has no fold
// (MobiusFoldGuard checks every triangle).
constexpr double kFoldScreen = 0.05;
// Points per side of the grid of barycentric points where a screened triangle is checked.
constexpr int kFoldGrid = 8;

// Fits z' = a w / (1 + c w) to the one-ring (w_k, z'_k) by linear least squares of
// a w - c w z' = z' (the equation times 1 + c w). A Möbius map through the vertex has exactly
// these two complex parameters, so a ring that one Möbius map fits is reproduced exactly. Where
// the ring is too small or the fit puts a pole near the ring, the conformal-linear fit (c = 0)
// stands in.
void fitMobius(const std::vector<Complex>& w, const std::vector<Complex>& z, Complex& a,
               Complex& c) {
  Complex m00 = 0, m01 = 0, m11 = 0, r0 = 0, r1 = 0;
  double ww = 0, reach = 0;
  Complex wz = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Complex u = w[k], v = -w[k] * z[k];
    m00 += std::conj(u) * u;
    m01 += std::conj(u) * v;
    m11 += std::conj(v) * v;
    r0 += std::conj(u) * z[k];
    r1 += std::conj(v) * z[k];
    ww += std::norm(w[k]);
    wz += std::conj(w[k]) * z[k];
    reach = std::max(reach, std::abs(w[k]));
  }
  const Complex det = m00 * m11 - m01 * std::conj(m01);
  if (w.size() >= 2 && std::abs(det) > 1e-12 * std::abs(m00 * m11)) {
    a = (r0 * m11 - m01 * r1) / det;
    c = (m00 * r1 - std::conj(m01) * r0) / det;
    if (std::abs(a) > 0 && std::abs(c) * reach < 0.5) return;
  }
  a = ww > 0 ? wz / ww : Complex(0);
  c = 0;
}

}  // namespace

std::array<double, 3> mobiusBlendWeights(const std::array<double, 3>& b) {
  std::array<double, 3> w;
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const double clamped = std::max(b[i], 0.0);
    w[i] = clamped * clamped;
    sum += w[i];
  }
  if (!(sum > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  for (double& x : w) x /= sum;
  return w;
}

MobiusBlend::MobiusBlend(const SphereDiskMesh& mesh, bool unfoldBlend)
    : mesh_(mesh), charts_(mesh.sphere.size()), linear_(mesh.sphere.size(), 0) {
  std::vector<std::vector<int>> ring(mesh.sphere.size());
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      for (int j = 1; j < 3; ++j) ring[t[i]].push_back(t[(i + j) % 3]);
  // Boundary neighbours: the wedge of a boundary vertex runs counter-clockwise from the
  // direction of the next boundary vertex to that of the previous one.
  std::vector<std::array<int, 2>> boundaryNeighbours(mesh.sphere.size(), {-1, -1});
  for (std::size_t k = 0; k < mesh.boundary.size(); ++k) {
    const std::size_t count = mesh.boundary.size();
    boundaryNeighbours[mesh.boundary[k]] = {mesh.boundary[(k + count - 1) % count],
                                            mesh.boundary[(k + 1) % count]};
  }
  std::vector<Complex> w, z;
  for (std::size_t v = 0; v < charts_.size(); ++v) {
    Chart& chart = charts_[v];
    chart.p = mesh.sphere[v];
    const Vec3d axis = std::abs(chart.p.x) < 0.8 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
    chart.e1 = normalized(cross(chart.p, axis));
    // (e1, e2) counter-clockwise seen from the centre, like the triangles: the map to the disk
    // preserves orientation.
    chart.e2 = cross(chart.e1, chart.p);
    chart.z0 = mesh.disk[v];
    std::vector<int>& neighbours = ring[v];
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    const auto [previous, next] = boundaryNeighbours[v];
    if (previous >= 0 && next >= 0 && previous != next) {
      // A corner whose angle differs between the sphere and the disk (a display corner, a cut
      // leaf): the map behaves like a power there, z ~ w^(disk angle / sphere angle).
      const Complex toNext = chartPoint(chart, mesh.sphere[next]);
      double sphereWedge = std::arg(chartPoint(chart, mesh.sphere[previous]) / toNext);
      if (sphereWedge < 1e-6) sphereWedge += 2 * kPi;  // a cut leaf: both neighbours coincide
      double diskWedge = std::arg((mesh.disk[previous] - chart.z0) / (mesh.disk[next] - chart.z0));
      if (diskWedge < 0) diskWedge += 2 * kPi;
      if (std::abs(sphereWedge - diskWedge) > kCornerTurn) {
        chart.gamma = diskWedge / sphereWedge;
        chart.turn = toNext / std::abs(toNext);
        chart.sphereWedge = sphereWedge;
        chart.diskWedge = diskWedge;
      }
    }
    w.clear();
    z.clear();
    for (int k : neighbours) {
      w.push_back(localPoint(chart, mesh.sphere[k]));
      z.push_back(mesh.disk[k] - chart.z0);
    }
    fitMobius(w, z, chart.a, chart.c);
  }
  if (!unfoldBlend) return;
  std::vector<double> misfit(charts_.size(), 0.0);
  for (std::size_t v = 0; v < charts_.size(); ++v)
    for (int k : ring[v]) {
      const double diskEdge = std::abs(mesh.disk[k] - mesh.disk[v]);
      const double sphereEdge = norm(mesh.sphere[k] - mesh.sphere[v]);
      const double diskMiss = std::abs(chartToDisk(charts_[v], mesh.sphere[k]) - mesh.disk[k]);
      const double sphereMiss = norm(chartToSphere(charts_[v], mesh.disk[k]) - mesh.sphere[k]);
      if (diskEdge > 0) misfit[v] = std::max(misfit[v], diskMiss / diskEdge);
      if (sphereEdge > 0) misfit[v] = std::max(misfit[v], sphereMiss / sphereEdge);
    }
  unfold(ring, misfit);
}

std::size_t MobiusBlend::linearVertices() const {
  return static_cast<std::size_t>(std::count(linear_.begin(), linear_.end(), 1));
}

bool MobiusBlend::folds(int t) const {
  const auto& c = mesh_.triangles[t];
  const Vec3d &s0 = mesh_.sphere[c[0]], &s1 = mesh_.sphere[c[1]], &s2 = mesh_.sphere[c[2]];
  const Complex z0 = mesh_.disk[c[0]], z1 = mesh_.disk[c[1]], z2 = mesh_.disk[c[2]];
  // The linear map's orientation either way (derivatives along b0 and b1, b2 = 1 - b0 - b1).
  const double diskTurn = (std::conj(z0 - z2) * (z1 - z2)).imag();
  const double sphereTurn = dot(s2, cross(s0 - s2, s1 - s2));
  // A degenerate triangle is the bake verdict's business (flipped triangles), not the blend's.
  if (!(diskTurn != 0) || !(sphereTurn != 0)) return false;
  auto toDiskAt = [&](const std::array<double, 3>& b) {
    return toDisk(t, b, normalized(b[0] * s0 + b[1] * s1 + b[2] * s2));
  };
  auto toSphereAt = [&](const std::array<double, 3>& l) {
    return toSphere(t, l, l[0] * z0 + l[1] * z1 + l[2] * z2);
  };
  constexpr double h = 1e-5;
  for (int i = 0; i < kFoldGrid; ++i)
    for (int j = 0; i + j < kFoldGrid; ++j) {
      const double b0 = (i + 1.0 / 3) / kFoldGrid, b1 = (j + 1.0 / 3) / kFoldGrid;
      const std::array<double, 3> b{b0, b1, 1 - b0 - b1}, along0{b0 + h, b1, 1 - b0 - b1 - h},
          along1{b0, b1 + h, 1 - b0 - b1 - h};
      const Complex z = toDiskAt(b);
      const double diskDet = (std::conj(toDiskAt(along0) - z) * (toDiskAt(along1) - z)).imag();
      if (!(diskDet * diskTurn > 0)) return true;
      const Vec3d x = toSphereAt(b);
      const double sphereDet = dot(x, cross(toSphereAt(along0) - x, toSphereAt(along1) - x));
      if (!(sphereDet * sphereTurn > 0)) return true;
    }
  return false;
}

void MobiusBlend::unfold(const std::vector<std::vector<int>>& rings,
                         const std::vector<double>& misfit) {
  std::vector<int> check;
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& c = mesh_.triangles[t];
    if (std::max({misfit[c[0]], misfit[c[1]], misfit[c[2]]}) > kFoldScreen)
      check.push_back(static_cast<int>(t));
  }
  std::vector<std::vector<int>> around;  // triangles around each vertex, once needed
  while (!check.empty()) {
    std::vector<int> flagged;
    auto flag = [&](int v) {
      if (linear_[v]) return;
      linear_[v] = 1;
      flagged.push_back(v);
    };
    // The corners of a folding triangle and their neighbours: every triangle around its corners
    // becomes the linear map, so the blends mix linear and Möbius maps one ring further out,
    // away from the misfit (mixed next to a singular corner, the map kinks hard enough for the
    // baked texels' finite differences to turn over).
    for (int t : check)
      if (folds(t))
        for (int v : mesh_.triangles[t]) {
          flag(v);
          for (int k : rings[v]) flag(k);
        }
    check.clear();
    if (flagged.empty()) break;
    if (around.empty()) {
      around.resize(charts_.size());
      for (std::size_t t = 0; t < mesh_.triangles.size(); ++t)
        for (int v : mesh_.triangles[t]) around[v].push_back(static_cast<int>(t));
    }
    // The triangles around newly linear corners blend differently now: check them again.
    for (int v : flagged)
      for (int t : around[v]) {
        const auto& c = mesh_.triangles[t];
        if (!(linear_[c[0]] && linear_[c[1]] && linear_[c[2]])) check.push_back(t);
      }
    std::sort(check.begin(), check.end());
    check.erase(std::unique(check.begin(), check.end()), check.end());
  }
}

// Per texel of a bake: written in real arithmetic with one division per corner (the library's
// complex operators check for infinities and NaN).
std::complex<double> MobiusBlend::toDisk(int t, const std::array<double, 3>& b,
                                         const Vec3d& x) const {
  const std::array<double, 3> weight = mobiusBlendWeights(b);
  const auto& corners = mesh_.triangles[t];
  double zx = 0, zy = 0;
  // The triangle's linear map, for every corner that blends it: computed once, when first needed.
  std::optional<Complex> linear;
  for (int i = 0; i < 3; ++i) {
    if (weight[i] == 0) continue;
    if (linear_[corners[i]]) {
      if (!linear)
        linear = b[0] * mesh_.disk[corners[0]] + b[1] * mesh_.disk[corners[1]] +
                 b[2] * mesh_.disk[corners[2]];
      zx += weight[i] * linear->real();
      zy += weight[i] * linear->imag();
      continue;
    }
    const Chart& chart = charts_[corners[i]];
    // z0 + a w / (1 + c w) with w = W / s, W = (x . e1) + i (x . e2), s = 1 + x . p:
    // z0 + a W / (s + c W).
    double wx, wy, s;
    if (chart.gamma == 1.0) {
      wx = dot(x, chart.e1);
      wy = dot(x, chart.e2);
      s = 1.0 + dot(x, chart.p);
    } else {
      const Complex w = localPoint(chart, x);
      wx = w.real();
      wy = w.imag();
      s = 1.0;
    }
    const double nx = chart.a.real() * wx - chart.a.imag() * wy;
    const double ny = chart.a.real() * wy + chart.a.imag() * wx;
    const double dx = s + chart.c.real() * wx - chart.c.imag() * wy;
    const double dy = chart.c.real() * wy + chart.c.imag() * wx;
    const double scale = weight[i] / (dx * dx + dy * dy);
    zx += weight[i] * chart.z0.real() + scale * (nx * dx + ny * dy);
    zy += weight[i] * chart.z0.imag() + scale * (ny * dx - nx * dy);
  }
  return {zx, zy};
}

Vec3d MobiusBlend::toSphere(int t, const std::array<double, 3>& l, std::complex<double> z) const {
  const std::array<double, 3> weight = mobiusBlendWeights(l);
  const auto& corners = mesh_.triangles[t];
  Vec3d sum{0.0};
  std::optional<Vec3d> linear;  // as in toDisk: once, when first needed
  for (int i = 0; i < 3; ++i) {
    if (weight[i] == 0) continue;
    if (linear_[corners[i]]) {  // a unit vector, like the Möbius maps' terms
      if (!linear)
        linear = normalized(l[0] * mesh_.sphere[corners[0]] + l[1] * mesh_.sphere[corners[1]] +
                            l[2] * mesh_.sphere[corners[2]]);
      sum += weight[i] * *linear;
      continue;
    }
    const Chart& chart = charts_[corners[i]];
    // The inverse of z0 + a w / (1 + c w): w = N / D, N = z - z0, D = a - c N.
    const double nx = z.real() - chart.z0.real(), ny = z.imag() - chart.z0.imag();
    const double dx = chart.a.real() - (chart.c.real() * nx - chart.c.imag() * ny);
    const double dy = chart.a.imag() - (chart.c.real() * ny + chart.c.imag() * nx);
    if (chart.gamma != 1.0) {
      const Complex w = chartFromLocal(chart, divide({nx, ny}, {dx, dy}));
      const double r2 = std::norm(w);
      sum += (weight[i] / (1.0 + r2)) *
             (2 * w.real() * chart.e1 + 2 * w.imag() * chart.e2 + (1.0 - r2) * chart.p);
      continue;
    }
    // The inverse stereographic chart of w = N / D, a unit vector:
    // (2 Re(N conj D) e1 + 2 Im(N conj D) e2 + (|D|^2 - |N|^2) p) / (|D|^2 + |N|^2).
    const double re = nx * dx + ny * dy, im = ny * dx - nx * dy;
    const double n2 = nx * nx + ny * ny, d2 = dx * dx + dy * dy;
    sum += (weight[i] / (d2 + n2)) * (2 * re * chart.e1 + 2 * im * chart.e2 + (d2 - n2) * chart.p);
  }
  return sum;
}

}  // namespace confvis::detail
