// The circle packing metric on a triangulation: initialisation (Appendix B, Step 1), lengths,
// angles, curvature and the curvature Jacobian.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "confvis/base/error.hpp"
#include "metric_evaluation.hpp"
#include "ricci_flow_parallel.hpp"

namespace confvis::conformal {
namespace detail {

bool euclideanAngles(const std::array<double, 3>& l, std::array<double, 3>& angles) {
  const double a = l[0], b = l[1], c = l[2];
  const double pa = b + c - a, pb = c + a - b, pc = a + b - c;
  if (!(pa > 0 && pb > 0 && pc > 0)) return false;  // also rejects NaN
  const double area4 = std::sqrt((a + b + c) * pa * pb * pc);  // 4 × area (Heron)
  if (!(area4 > 0) || !std::isfinite(area4)) return false;
  // Half-angle tangents: tan(θ_a/2) = pb·pc / 4A. Accurate for slivers too, where the cosine
  // law loses half the digits (acos near ±1); atan is also cheaper than acos.
  angles[0] = 2 * std::atan(pb * pc / area4);
  angles[1] = 2 * std::atan(pc * pa / area4);
  angles[2] = std::numbers::pi - angles[0] - angles[1];  // exact to rounding, one atan less
  return true;
}

void evaluateMetric(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                    const std::vector<double>& u, MetricEvaluation& out) {
  out.geometry = metric.geometry;
  const int edgeCount = tri.edgeCount(), faceCount = tri.faceCount();
  out.edges.resize(edgeCount);
  // First invalid edge / face per part of the parallel loops; the smallest index wins.
  std::array<int, 8> firstInvalid;
  auto smallestInvalid = [&](int parts) {
    int first = -1;
    for (int p = 0; p < parts; ++p)
      if (firstInvalid[p] >= 0 && (first < 0 || firstInvalid[p] < first)) first = firstInvalid[p];
    return first;
  };
  firstInvalid.fill(-1);
  int parts;
  if (metric.geometry == Geometry::Euclidean) {
    // (4.1.2) in E²: l² = 2η x_i x_j + ε_i x_i² + ε_j x_j² with x = e^u, one exp per vertex.
    out.scale.resize(u.size());
    parallelFor(static_cast<int>(u.size()), [&](int begin, int end, int) {
      for (int v = begin; v < end; ++v) out.scale[v] = std::exp(u[v]);
    });
    const double* x = out.scale.data();
    const int* eps = metric.epsilon.data();
    parts = parallelFor(edgeCount, [&](int begin, int end, int part) {
      for (int e = begin; e < end; ++e) {
        const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
        const double cross = metric.eta[e] * x[a] * x[b];
        const double sa = eps[a] * x[a] * x[a], sb = eps[b] * x[b] * x[b];
        const double l2 = 2 * cross + sa + sb;
        EdgeLength& el = out.edges[e];
        el.valid = l2 > 0 && std::isfinite(l2);
        if (!el.valid) {
          if (firstInvalid[part] < 0) firstInvalid[part] = e;
          continue;
        }
        el.length = std::sqrt(l2);
        const double inverse = 1 / el.length;
        el.dLength_dui = (cross + sa) * inverse;
        el.dLength_duj = (cross + sb) * inverse;
      }
    });
  } else {
    parts = parallelFor(edgeCount, [&](int begin, int end, int part) {
      for (int e = begin; e < end; ++e) {
        const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
        out.edges[e] = edgeLength(metric.geometry, u[a], u[b], metric.eta[e],
                                  metric.epsilon[a], metric.epsilon[b]);
        if (!out.edges[e].valid && firstInvalid[part] < 0) firstInvalid[part] = e;
      }
    });
  }
  out.invalidEdge = smallestInvalid(parts);
  out.invalidFace = -1;
  if (out.invalidEdge >= 0) return;
  // Triangle inequalities first, from the lengths alone: a line-search trial that degenerates
  // a triangle (a third of all trials with flips, measured) then costs no angles.
  firstInvalid.fill(-1);
  parts = parallelFor(faceCount, [&](int begin, int end, int part) {
    for (int f = begin; f < end; ++f) {
      const auto& fe = tri.faceEdges[f];
      const double a = out.edges[fe[0]].length, b = out.edges[fe[1]].length,
                   c = out.edges[fe[2]].length;
      if (!(b + c > a && c + a > b && a + b > c)) {
        firstInvalid[part] = f;
        break;
      }
    }
  });
  out.invalidFace = smallestInvalid(parts);
  if (out.invalidFace >= 0) return;
  out.angles.resize(faceCount);
  firstInvalid.fill(-1);
  parts = parallelFor(faceCount, [&](int begin, int end, int part) {
    for (int f = begin; f < end; ++f)
      if (!faceAngles(tri, out, f) && firstInvalid[part] < 0) firstInvalid[part] = f;
  });
  out.invalidFace = smallestInvalid(parts);
  if (out.invalidFace < 0) refreshCurvature(tri, out);
}

bool faceAngles(const IntrinsicTriangulation& tri, MetricEvaluation& eval, int f) {
  const auto& fe = tri.faceEdges[f];
  const std::array<double, 3> l{eval.edges[fe[0]].length, eval.edges[fe[1]].length,
                                eval.edges[fe[2]].length};
  return eval.geometry == Geometry::Euclidean ? euclideanAngles(l, eval.angles[f])
                                              : cornerAngles(eval.geometry, l, eval.angles[f]);
}

void refreshCurvature(const IntrinsicTriangulation& tri, MetricEvaluation& eval) {
  eval.curvature.resize(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v)
    eval.curvature[v] = tri.vertexOnBoundary[v] ? std::numbers::pi : 2 * std::numbers::pi;
  for (int f = 0; f < tri.faceCount(); ++f)
    for (int c = 0; c < 3; ++c) eval.curvature[tri.faceVertices[f][c]] -= eval.angles[f][c];
}

bool updateAroundEdge(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                      int e, MetricEvaluation& eval) {
  const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
  eval.edges[e] = edgeLength(metric.geometry, metric.u[a], metric.u[b], metric.eta[e],
                             metric.epsilon[a], metric.epsilon[b]);
  if (!eval.edges[e].valid) return false;
  for (int f : tri.edgeFaces[e])
    if (f >= 0 && !faceAngles(tri, eval, f)) return false;
  return true;
}

void faceAngleJacobian(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int f,
                       std::array<std::array<double, 3>, 3>& J) {
  const auto& fe = tri.faceEdges[f];
  const auto& fv = tri.faceVertices[f];
  const std::array<double, 3> l{eval.edges[fe[0]].length, eval.edges[fe[1]].length,
                                eval.edges[fe[2]].length};
  std::array<std::array<double, 3>, 3> dThetaDl;
  if (eval.geometry == Geometry::Euclidean) {
    // Derivative cosine law without trigonometry: with 4A = 4 × area,
    // ∂θ_i/∂l_i = 2 l_i / 4A and ∂θ_i/∂l_j = -(l_i² + l_j² - l_k²) / (l_j · 4A).
    const double pa = l[1] + l[2] - l[0], pb = l[2] + l[0] - l[1], pc = l[0] + l[1] - l[2];
    const double inverseArea4 = 1 / std::sqrt((l[0] + l[1] + l[2]) * pa * pb * pc);
    const std::array<double, 3> sq{l[0] * l[0], l[1] * l[1], l[2] * l[2]};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      dThetaDl[i][i] = 2 * l[i] * inverseArea4;
      dThetaDl[i][j] = -(sq[i] + sq[j] - sq[k]) / l[j] * inverseArea4;
      dThetaDl[i][k] = -(sq[i] + sq[k] - sq[j]) / l[k] * inverseArea4;
    }
  } else {
    angleLengthDerivatives(eval.geometry, l, eval.angles[f], dThetaDl);
  }
  // dLdu[c][b]: derivative of the length opposite corner c w.r.t. u at corner b.
  std::array<std::array<double, 3>, 3> dLdu{};
  for (int c = 0; c < 3; ++c) {
    const EdgeLength& el = eval.edges[fe[c]];
    const int b1 = (c + 1) % 3, b2 = (c + 2) % 3;
    const bool aligned = tri.edgeVertices[fe[c]][0] == fv[b1];
    dLdu[c][b1] = aligned ? el.dLength_dui : el.dLength_duj;
    dLdu[c][b2] = aligned ? el.dLength_duj : el.dLength_dui;
  }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double s = 0;
      for (int c = 0; c < 3; ++c) s += dThetaDl[a][c] * dLdu[c][b];
      J[a][b] = s;
    }
}

double degenerationStep(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                        const std::vector<double>& uStart, const std::vector<double>& uTrial,
                        const MetricEvaluation& start, const MetricEvaluation& trial) {
  if (trial.invalidEdge >= 0 || !start.valid()) return 0;
  // Relative triangle-inequality margin of face f at the point `alpha` of the way.
  auto margin = [&](int f, double alpha) {
    std::array<double, 3> l;
    for (int c = 0; c < 3; ++c) {
      const int e = tri.faceEdges[f][c];
      const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
      const EdgeLength el = edgeLength(
          metric.geometry, uStart[a] + alpha * (uTrial[a] - uStart[a]),
          uStart[b] + alpha * (uTrial[b] - uStart[b]), metric.eta[e], metric.epsilon[a],
          metric.epsilon[b]);
      if (!el.valid) return -1.0;
      l[c] = el.length;
    }
    return std::min({l[1] + l[2] - l[0], l[2] + l[0] - l[1], l[0] + l[1] - l[2]}) /
           (l[0] + l[1] + l[2]);
  };
  double step = 1;
  for (int f = 0; f < tri.faceCount(); ++f) {
    const auto& fe = tri.faceEdges[f];
    const double a = trial.edges[fe[0]].length, b = trial.edges[fe[1]].length,
                 c = trial.edges[fe[2]].length;
    if (b + c > a && c + a > b && a + b > c) continue;
    // The margin is not linear in the step: bisect for where this face degenerates, within
    // the part of the way no other face has been found to degenerate in.
    if (margin(f, step) > 0) continue;
    double lo = 0, hi = step;
    for (int k = 0; k < 40 && hi - lo > 1e-4 * hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      (margin(f, mid) > 0 ? lo : hi) = mid;
    }
    step = lo;
  }
  return step < 1 ? step : 0;
}

double faceAngleDerivative(const IntrinsicTriangulation& tri, const MetricEvaluation& eval, int f,
                           int a, int b) {
  if (eval.geometry != Geometry::Euclidean || a == b) {
    std::array<std::array<double, 3>, 3> J;
    faceAngleJacobian(tri, eval, f, J);
    return J[a][b];
  }
  // u_b moves the two edges at corner b: the one opposite a and the one opposite c.
  const int c = 3 - a - b;
  const auto& fe = tri.faceEdges[f];
  const double la = eval.edges[fe[a]].length, lb = eval.edges[fe[b]].length,
               lc = eval.edges[fe[c]].length;
  const double area4 =
      std::sqrt((la + lb + lc) * (lb + lc - la) * (lc + la - lb) * (la + lb - lc));
  auto dLength = [&](int edgeCorner) {  // ∂l/∂u_b of the edge opposite edgeCorner
    const EdgeLength& el = eval.edges[fe[edgeCorner]];
    return tri.edgeVertices[fe[edgeCorner]][0] == tri.faceVertices[f][b] ? el.dLength_dui
                                                                          : el.dLength_duj;
  };
  return (2 * la * dLength(a) - (la * la + lc * lc - lb * lb) / lc * dLength(c)) / area4;
}

bool flippedEdgeLength(const IntrinsicTriangulation& tri, const MetricEvaluation& eval,
                       Geometry geometry, int e, double& length) {
  const int f0 = tri.edgeFaces[e][0], f1 = tri.edgeFaces[e][1];
  const int c0 = tri.cornerOpposite(f0, e), c1 = tri.cornerOpposite(f1, e);
  // f0 = (p, q, r), f1 = (s, r, q): angles at q and r, summed over both triangles.
  const double angleQ = eval.angles[f0][(c0 + 1) % 3] + eval.angles[f1][(c1 + 2) % 3];
  const double angleR = eval.angles[f0][(c0 + 2) % 3] + eval.angles[f1][(c1 + 1) % 3];
  constexpr double margin = 1e-9;  // strictly convex quads only: flat ones round badly
  if (!(angleQ < std::numbers::pi - margin && angleR < std::numbers::pi - margin)) return false;
  const double a = eval.edges[tri.faceEdges[f0][(c0 + 2) % 3]].length;  // pq
  const double b = eval.edges[tri.faceEdges[f1][(c1 + 1) % 3]].length;  // qs
  switch (geometry) {
    case Geometry::Euclidean:
      length = std::sqrt(a * a + b * b - 2 * a * b * std::cos(angleQ));
      break;
    // The cosine laws in haversine form, as edgeLength: acosh / acos of a value near 1 would
    // lose half the digits of a short diagonal. cosh d − 1 = 2 sinh²((a−b)/2) +
    // 2 sinh a sinh b sin²(A/2); 1 − cos d = 2 sin²((a−b)/2) + 2 sin a sin b sin²(A/2).
    case Geometry::Hyperbolic: {
      const double h = std::sinh(0.5 * (a - b)), s = std::sin(0.5 * angleQ);
      length = 2 * std::asinh(std::sqrt(h * h + std::sinh(a) * std::sinh(b) * s * s));
      break;
    }
    case Geometry::Spherical: {
      const double h = std::sin(0.5 * (a - b)), s = std::sin(0.5 * angleQ);
      length = 2 * std::asin(std::min(1.0, std::sqrt(h * h + std::sin(a) * std::sin(b) * s * s)));
      break;
    }
  }
  return std::isfinite(length) && length > 0;
}

}  // namespace detail

std::vector<int> defaultMixedEpsilon(int vertexCount) {
  std::vector<int> eps(vertexCount);
  // Inversive-distance and Yamabe vertices interleaved. Mixing in virtual-radius (ε = -1)
  // vertices is supported through an explicit ε, but measured fragile: with (i mod 3) - 1 the
  // flow stalled on 3 of 5 test meshes even with flips, so it is not the default.
  for (int v = 0; v < vertexCount; ++v) eps[v] = v % 2 == 0 ? 1 : 0;
  return eps;
}

namespace {

int schemeEpsilon(Scheme s) {
  switch (s) {
    case Scheme::Yamabe: return 0;
    case Scheme::VirtualRadius: return -1;
    default: return 1;
  }
}

// Initial radii (Appendix B, Step 1), in the units of the background geometry.
std::vector<double> initialRadii(const IntrinsicTriangulation& tri,
                                 const std::vector<double>& lengths, Scheme scheme,
                                 const std::vector<int>& epsilon) {
  const int n = tri.vertexCount;
  std::vector<double> minLength(n, std::numeric_limits<double>::infinity());
  std::vector<double> sumLength(n, 0.0);
  std::vector<int> degree(n, 0);
  for (int e = 0; e < tri.edgeCount(); ++e)
    for (int v : tri.edgeVertices[e]) {
      minLength[v] = std::min(minLength[v], lengths[e]);
      sumLength[v] += lengths[e];
      ++degree[v];
    }
  std::vector<double> radii(n, 1.0);
  switch (scheme) {
    case Scheme::Tangential: {
      // Average over incident corners of the incircle tangent length (l_ij + l_ik - l_jk) / 2:
      // exact for the incircle packing of each triangle, a compromise across triangles.
      std::vector<double> sum(n, 0.0);
      std::vector<int> count(n, 0);
      for (int f = 0; f < tri.faceCount(); ++f)
        for (int c = 0; c < 3; ++c) {
          const double opposite = lengths[tri.faceEdges[f][c]];
          const double adj1 = lengths[tri.faceEdges[f][(c + 1) % 3]];
          const double adj2 = lengths[tri.faceEdges[f][(c + 2) % 3]];
          sum[tri.faceVertices[f][c]] += 0.5 * (adj1 + adj2 - opposite);
          ++count[tri.faceVertices[f][c]];
        }
      for (int v = 0; v < n; ++v) radii[v] = count[v] ? sum[v] / count[v] : 1.0;
      break;
    }
    case Scheme::Thurston:
      // Intersection angles in [0, π/2] need γ_i² + γ_j² ≤ l² ≤ (γ_i + γ_j)²: radii between
      // l/2 and l/√2 for uniform meshes. The window's lower end, 0.5 × the mean incident
      // length, converges fastest (10k vertices: 6 Newton steps, 23 with 0.6×; sweep mean 5, 9).
      for (int v = 0; v < n; ++v) radii[v] = degree[v] ? 0.5 * sumLength[v] / degree[v] : 1.0;
      break;
    case Scheme::InversiveDistance:
      for (int v = 0; v < n; ++v) radii[v] = minLength[v] / 3;  // separated circles
      break;
    case Scheme::Yamabe:
      // Appendix B takes γ = 1; radii follow the mesh scale instead (see VirtualRadius).
      for (int v = 0; v < n; ++v) radii[v] = degree[v] ? sumLength[v] / degree[v] : 1.0;
      break;
    case Scheme::VirtualRadius:
      // Appendix B's γ = 1 makes (4.1.2) with ε = -1 a cancellation of O(1) terms into l²
      // (catastrophic on a mesh with centimetre edges). Radii of the mean incident length, the
      // next guess, stalled the flow on every mesh of the robustness sweep; a third of the
      // shortest incident edge, as for inversive distance, converges (measured).
      for (int v = 0; v < n; ++v) radii[v] = minLength[v] / 3;
      break;
    case Scheme::Mixed:
      for (int v = 0; v < n; ++v)
        radii[v] = epsilon[v] > 0 ? minLength[v] / 3 : (degree[v] ? sumLength[v] / degree[v] : 1.0);
      break;
  }
  return radii;
}

}  // namespace

CirclePackingMetric initialMetric(const IntrinsicTriangulation& tri,
                                  const std::vector<double>& lengths, Scheme scheme,
                                  Geometry geometry, const std::vector<int>& mixedEpsilon) {
  if (static_cast<int>(lengths.size()) != tri.edgeCount())
    throw Error(ErrorCode::Internal, "initialMetric: one length per edge expected");
  for (int e = 0; e < tri.edgeCount(); ++e)
    if (!(lengths[e] > 0) || !std::isfinite(lengths[e]))
      throw Error(ErrorCode::InvalidInput, "edge " + std::to_string(e) + " (vertices " +
                                               std::to_string(tri.edgeVertices[e][0]) + "-" +
                                               std::to_string(tri.edgeVertices[e][1]) +
                                               ") has a non-positive length");
  if (geometry == Geometry::Spherical)
    for (int e = 0; e < tri.edgeCount(); ++e)
      if (lengths[e] >= std::numbers::pi)
        throw Error(ErrorCode::InvalidInput,
                    "spherical edge " + std::to_string(e) + " is longer than π: scale the mesh");
  CirclePackingMetric m;
  m.geometry = geometry;
  m.scheme = scheme;
  if (scheme == Scheme::Mixed) {
    m.epsilon = mixedEpsilon.empty() ? defaultMixedEpsilon(tri.vertexCount) : mixedEpsilon;
    if (static_cast<int>(m.epsilon.size()) != tri.vertexCount)
      throw Error(ErrorCode::InvalidInput, "mixed scheme: one ε per vertex expected");
    for (int e : m.epsilon)
      if (e < -1 || e > 1) throw Error(ErrorCode::InvalidInput, "mixed scheme: ε must be -1, 0 or 1");
  } else {
    m.epsilon.assign(tri.vertexCount, schemeEpsilon(scheme));
  }
  const std::vector<double> radii = initialRadii(tri, lengths, scheme, m.epsilon);
  m.u.resize(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) {
    double r = radii[v];
    // Radii must stay inside the domain of (4.1.1) and keep denominators of (4.1.2) positive.
    if (geometry == Geometry::Spherical) r = std::min(r, m.epsilon[v] < 0 ? 1.0 : 3.0);
    m.u[v] = conformalFactorFromRadius(geometry, r);
  }
  m.eta.resize(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
    double eta = etaForLength(geometry, lengths[e], m.u[a], m.u[b], m.epsilon[a], m.epsilon[b]);
    if (scheme == Scheme::Tangential) eta = 1.0;
    if (scheme == Scheme::Thurston) eta = std::clamp(eta, 0.0, 1.0);
    m.eta[e] = eta;
  }
  return m;
}

std::vector<double> metricEdgeLengths(const IntrinsicTriangulation& tri,
                                      const CirclePackingMetric& metric) {
  std::vector<double> lengths(tri.edgeCount());
  for (int e = 0; e < tri.edgeCount(); ++e) {
    const int a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
    const EdgeLength l = edgeLength(metric.geometry, metric.u[a], metric.u[b], metric.eta[e],
                                    metric.epsilon[a], metric.epsilon[b]);
    if (!l.valid)
      throw Error(ErrorCode::InvalidInput,
                  "edge " + std::to_string(e) + " has no valid length in this metric");
    lengths[e] = l.length;
  }
  return lengths;
}

std::vector<double> vertexCurvature(const IntrinsicTriangulation& tri,
                                    const CirclePackingMetric& metric) {
  detail::MetricEvaluation eval;
  detail::evaluateMetric(tri, metric, metric.u, eval);
  if (!eval.valid())
    throw Error(ErrorCode::InvalidInput,
                eval.invalidEdge >= 0
                    ? "edge " + std::to_string(eval.invalidEdge) + " has no valid length"
                    : "face " + std::to_string(eval.invalidFace) + " violates the triangle inequality");
  return eval.curvature;
}

Eigen::SparseMatrix<double> curvatureJacobian(const IntrinsicTriangulation& tri,
                                              const CirclePackingMetric& metric) {
  detail::MetricEvaluation eval;
  detail::evaluateMetric(tri, metric, metric.u, eval);
  if (!eval.valid()) throw Error(ErrorCode::InvalidInput, "curvatureJacobian: invalid metric");
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(9 * tri.faceCount());
  std::array<std::array<double, 3>, 3> J;
  for (int f = 0; f < tri.faceCount(); ++f) {
    detail::faceAngleJacobian(tri, eval, f, J);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)  // K = 2π - Σθ
        triplets.emplace_back(tri.faceVertices[f][a], tri.faceVertices[f][b], -J[a][b]);
  }
  Eigen::SparseMatrix<double> H(tri.vertexCount, tri.vertexCount);
  H.setFromTriplets(triplets.begin(), triplets.end());
  return H;
}

void checkTargetCurvature(const IntrinsicTriangulation& tri, Geometry geometry,
                          const std::vector<double>& target) {
  if (static_cast<int>(target.size()) != tri.vertexCount)
    throw Error(ErrorCode::InvalidInput, "target curvature: one value per vertex expected (got " +
                                             std::to_string(target.size()) + " for " +
                                             std::to_string(tri.vertexCount) + " vertices)");
  double sum = 0;
  for (int v = 0; v < tri.vertexCount; ++v) {
    const double bound = tri.vertexOnBoundary[v] ? std::numbers::pi : 2 * std::numbers::pi;
    if (!std::isfinite(target[v]) || target[v] >= bound) {
      std::ostringstream s;
      s << "target curvature " << target[v] << " at vertex " << v
        << " is not below " << (tri.vertexOnBoundary[v] ? "π (boundary)" : "2π (interior)")
        << ": no metric has a non-positive angle sum";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    sum += target[v];
  }
  const double expected = 2 * std::numbers::pi * tri.eulerCharacteristic();
  const double slack = 1e-9 * std::max(1.0, std::abs(expected)) + 1e-12 * tri.vertexCount;
  std::ostringstream s;
  s.precision(12);
  s << "target curvature sums to " << sum << " but Gauss-Bonnet for this mesh (Euler "
    << "characteristic " << tri.eulerCharacteristic() << ") ";
  if (geometry == Geometry::Euclidean && std::abs(sum - expected) > slack) {
    s << "requires exactly 2πχ = " << expected;
    throw Error(ErrorCode::Unreachable, s.str());
  }
  if (geometry == Geometry::Hyperbolic && !(sum > expected + slack)) {
    s << "requires more than 2πχ = " << expected << " in hyperbolic geometry (the excess is the area)";
    throw Error(ErrorCode::Unreachable, s.str());
  }
  if (geometry == Geometry::Spherical && !(sum < expected - slack)) {
    s << "requires less than 2πχ = " << expected << " in spherical geometry (the deficit is the area)";
    throw Error(ErrorCode::Unreachable, s.str());
  }
}

}  // namespace confvis::conformal
