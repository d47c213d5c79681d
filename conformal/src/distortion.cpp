#include "confvis/conformal/distortion.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis::conformal {

namespace {
double cornerAngle(const std::array<double, 2>& a, const std::array<double, 2>& b,
                   const std::array<double, 2>& c) {  // angle at a
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}
}  // namespace

DistortionStats measureDistortion(const TriMesh& mesh, const std::vector<std::complex<double>>& uv,
                                  int histogramBins) {
  if (uv.size() != mesh.n_vertices())
    throw Error(ErrorCode::Internal, "measureDistortion: one uv per vertex expected");
  DistortionStats s;
  s.logAngleRatioHistogram.assign(histogramBins, 0);
  std::vector<double> ratios;
  ratios.reserve(mesh.n_faces());
  double logSum = 0, logSum2 = 0;
  int corners = 0;
  for (auto f : mesh.faces()) {
    std::array<int, 3> v{};
    int k = 0;
    for (auto vh : f.vertices()) v[k++] = vh.idx();
    // The 3D triangle in its own orthonormal frame (x along the first edge).
    const Vec3 p0 = mesh.point(TriMesh::VertexHandle(v[0]));
    const Vec3 e1 = mesh.point(TriMesh::VertexHandle(v[1])) - p0;
    const Vec3 e2 = mesh.point(TriMesh::VertexHandle(v[2])) - p0;
    const Vec3 x = e1.normalized();
    const Vec3 n = (e1 % e2).normalized();
    const Vec3 y = n % x;
    const std::array<std::array<double, 2>, 3> P{{{0, 0}, {e1 | x, 0}, {e2 | x, e2 | y}}};
    std::array<std::array<double, 2>, 3> Q;
    for (int c = 0; c < 3; ++c) Q[c] = {uv[v[c]].real(), uv[v[c]].imag()};
    // J = [q1-q0, q2-q0] [p1-p0, p2-p0]^-1
    const double pa = P[1][0], pb = P[2][0], pc = P[1][1], pd = P[2][1];
    const double detP = pa * pd - pb * pc;
    const double qa = Q[1][0] - Q[0][0], qb = Q[2][0] - Q[0][0];
    const double qc = Q[1][1] - Q[0][1], qd = Q[2][1] - Q[0][1];
    const double detQ = qa * qd - qb * qc;
    if (!(detQ > 0)) {
      ++s.flippedFaces;
      continue;
    }
    if (!(detP > 0)) {  // zero area in space (scans have them): no orientation or ratio to measure
      ++s.degenerateFaces;
      continue;
    }
    const double j11 = (qa * pd - qb * pc) / detP, j12 = (-qa * pb + qb * pa) / detP;
    const double j21 = (qc * pd - qd * pc) / detP, j22 = (-qc * pb + qd * pa) / detP;
    // Singular values of a 2×2 matrix from its conformal and anti-conformal parts.
    const double conf = std::hypot(j11 + j22, j21 - j12) / 2;
    const double anti = std::hypot(j11 - j22, j21 + j12) / 2;
    ratios.push_back((conf + anti) / (conf - anti));
    for (int c = 0; c < 3; ++c) {
      const double a3 = cornerAngle(P[c], P[(c + 1) % 3], P[(c + 2) % 3]);
      const double a2 = cornerAngle(Q[c], Q[(c + 1) % 3], Q[(c + 2) % 3]);
      const double l = std::log(a2 / a3);
      logSum += l;
      logSum2 += l * l;
      ++corners;
      int bin = static_cast<int>((l - s.histogramMin) / (s.histogramMax - s.histogramMin) *
                                 histogramBins);
      ++s.logAngleRatioHistogram[std::clamp(bin, 0, histogramBins - 1)];
    }
  }
  s.faces = static_cast<int>(mesh.n_faces());
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    double sum = 0;
    for (double r : ratios) sum += r;
    s.ratioMean = sum / ratios.size();
    s.ratioP50 = ratios[ratios.size() / 2];
    s.ratioP99 = ratios[std::min(ratios.size() - 1, ratios.size() * 99 / 100)];
    s.ratioMax = ratios.back();
  }
  if (corners > 0) {
    const double mean = logSum / corners;
    s.logAngleRatioStd = std::sqrt(std::max(0.0, logSum2 / corners - mean * mean));
  }
  for (auto v : mesh.vertices())
    if (mesh.is_boundary(v))
      s.boundaryRoundness = std::max(s.boundaryRoundness, std::abs(std::abs(uv[v.idx()]) - 1.0));
  return s;
}

nlohmann::json toJson(const DistortionStats& s) {
  return {{"faces", s.faces},
          {"singular_value_ratio",
           {{"mean", s.ratioMean}, {"p50", s.ratioP50}, {"p99", s.ratioP99}, {"max", s.ratioMax}}},
          {"flipped_faces", s.flippedFaces},
          {"degenerate_faces", s.degenerateFaces},
          {"boundary_roundness", s.boundaryRoundness},
          {"log_angle_ratio",
           {{"std", s.logAngleRatioStd},
            {"histogram_min", s.histogramMin},
            {"histogram_max", s.histogramMax},
            {"histogram", s.logAngleRatioHistogram}}}};
}

}  // namespace confvis::conformal
