// The hyperbolic disk-map route (dissertation §6.2, iterated boundary curvature): hyperbolic
// flow with zero target curvature inside; on the boundary the curvature of a polygon inscribed
// in a hyperbolic circle. For boundary edges l_j inscribed in a circle of radius R, the
// isosceles triangle (centre, v_j, v_j+1) has the central angle θ_j, sin(θ_j/2) =
// sinh(l_j/2)/sinh R, and base angles β_j, cos β_j = tanh(l_j/2)/tanh R (right triangles with
// hypotenuse R); R closes the polygon, Σθ_j = 2π, and the curvature at v_i is
// π − β_{i−1} − β_i. The edge lengths are the flow's result, so the targets are recomputed from
// them until they stop changing; the metric is then the hyperbolic disk of radius R, which the
// Poincaré model shows as a Euclidean disk, scaled onto the unit disk.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "confvis/base/error.hpp"
#include "disk_map_layout.hpp"
#include "disk_map_routes.hpp"

namespace confvis::conformal::detail {
namespace {

using Point = Eigen::Vector3d;  // (x, y, t) on the hyperboloid t² − x² − y² = 1, t > 0
constexpr double pi = std::numbers::pi;

// The mesh is scaled to the area of a hyperbolic disk of radius 1 to start with.
const double kInitialArea = 2 * pi * (std::cosh(1.0) - 1);

// Radius of the hyperbolic circle through a closed polygon with these side lengths.
double circumradius(const std::vector<double>& sides) {
  double longest = 0;
  for (double l : sides) longest = std::max(longest, l);
  auto excess = [&](double R) {  // Σθ_j - 2π, decreasing in R
    const double s = std::sinh(R);
    double sum = -2 * pi;
    for (double l : sides) sum += 2 * std::asin(std::min(1.0, std::sinh(0.5 * l) / s));
    return sum;
  };
  double lo = 0.5 * longest, hi = std::max(1.0, longest);
  if (!(excess(lo) > 0))
    throw Error(ErrorCode::Unreachable,
                "hyperbolic disk map: one boundary edge is as long as the rest of the boundary");
  while (excess(hi) > 0) hi *= 2;
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Boundary target curvature of the polygon inscribed in a circle with the metric's boundary
// edge lengths.
void inscribedTargets(const BoundaryCycle& cycle, const CirclePackingMetric& metric,
                      const IntrinsicTriangulation& tri, std::vector<double>& target) {
  const std::size_t n = cycle.edges.size();
  std::vector<double> sides(n), base(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int e = cycle.edges[k], a = tri.edgeVertices[e][0], b = tri.edgeVertices[e][1];
    const EdgeLength l = edgeLength(metric.geometry, metric.u[a], metric.u[b], metric.eta[e],
                                    metric.epsilon[a], metric.epsilon[b]);
    if (!l.valid) throw Error(ErrorCode::Internal, "hyperbolic disk map: invalid boundary edge");
    sides[k] = l.length;
  }
  const double tanhR = std::tanh(circumradius(sides));
  for (std::size_t k = 0; k < n; ++k) base[k] = std::acos(std::tanh(0.5 * sides[k]) / tanhR);
  for (std::size_t k = 0; k < n; ++k)
    target[cycle.vertices[k]] = pi - base[(k + n - 1) % n] - base[k];
}

double minkowski(const Point& a, const Point& b) { return a.x() * b.x() + a.y() * b.y() - a.z() * b.z(); }

// Develops the hyperbolic metric onto the hyperboloid, faces counter-clockwise seen from above.
std::vector<Point> layOutOnHyperboloid(const IntrinsicTriangulation& tri,
                                       const std::vector<double>& lengths) {
  auto placeFirstEdge = [&](std::array<Point, 3>& corner) {
    const double l = lengths[tri.faceEdges[0][2]];
    corner[0] = Point(0, 0, 1);
    corner[1] = Point(std::sinh(l), 0, std::cosh(l));
  };
  // As on the sphere: from c2 along the geodesic towards c1 turned clockwise by the angle at c2.
  auto placeThird = [&](int f, int c0, std::array<Point, 3>& corner) {
    const int c1 = (c0 + 1) % 3, c2 = (c0 + 2) % 3;
    const auto& fe = tri.faceEdges[f];
    const double base = lengths[fe[c0]], toC2 = lengths[fe[c1]], toC1 = lengths[fe[c2]];
    const double angle = curvedCornerAngle(Geometry::Hyperbolic, toC1, base, toC2);
    const Point& p2 = corner[c2];
    Point tangent = corner[c1] + minkowski(corner[c1], p2) * p2;
    tangent /= std::sqrt(minkowski(tangent, tangent));
    // The Lorentzian cross product: the tangent turned counter-clockwise (it is at the origin,
    // and the turn varies continuously over the hyperboloid).
    Point normal = p2.cross(tangent);
    normal.z() = -normal.z();
    const Point direction = std::cos(angle) * tangent - std::sin(angle) * normal;
    Point p0 = std::cosh(toC2) * p2 + std::sinh(toC2) * direction;
    p0.z() = std::sqrt(1 + p0.x() * p0.x() + p0.y() * p0.y());  // back onto the hyperboloid
    corner[c0] = p0;
  };
  return vertexPositions(tri, developFaces<Point>(tri, {}, placeFirstEdge, placeThird));
}

// Anderson acceleration of the fixed-point iteration x ← T(x) on the boundary targets: the
// plain iteration contracts by only ~0.57 per update (measured on hemispheres: 19 updates from
// 6e-5 to 1e-10), like a boundary mode of wavenumber 2 would for Koebe-type iterations; mixing
// the last five updates takes 9.
class BoundaryAcceleration {
 public:
  explicit BoundaryAcceleration(std::size_t size) : size_(size) {}

  // `target` = x, `next` = T(x) on the boundary vertices; sets target to the next iterate.
  void update(const std::vector<int>& vertices, std::vector<double>& target,
              const std::vector<double>& next) {
    Eigen::VectorXd x(size_), g(size_);
    for (std::size_t k = 0; k < size_; ++k) x[k] = target[vertices[k]], g[k] = next[vertices[k]];
    const Eigen::VectorXd f = g - x;
    if (lastF_.size() > 0) {
      if (dF_.size() == kMemory) dF_.erase(dF_.begin()), dG_.erase(dG_.begin());
      dF_.push_back(f - lastF_);
      dG_.push_back(g - lastG_);
    }
    lastF_ = f;
    lastG_ = g;
    Eigen::VectorXd mixed = g;
    if (!dF_.empty()) {
      Eigen::MatrixXd F(size_, dF_.size()), G(size_, dG_.size());
      for (std::size_t j = 0; j < dF_.size(); ++j) F.col(j) = dF_[j], G.col(j) = dG_[j];
      const Eigen::VectorXd gamma = F.colPivHouseholderQr().solve(f);
      if (gamma.allFinite()) mixed -= G * gamma;
    }
    for (std::size_t k = 0; k < size_; ++k) target[vertices[k]] = mixed[k];
  }

 private:
  static constexpr std::size_t kMemory = 5;
  std::size_t size_;
  Eigen::VectorXd lastF_, lastG_;
  std::vector<Eigen::VectorXd> dF_, dG_;
};

}  // namespace

DiskMap hyperbolicDiskMap(const std::vector<Vec3d>& points, const IntrinsicTriangulation& whole,
                          const DiskMapOptions& options) {
  DiskMap result;
  result.geometry = Geometry::Hyperbolic;
  IntrinsicTriangulation tri = whole;  // flips change it
  CirclePackingMetric metric = initialMetric(tri, lengthsScaledToArea(tri, points, kInitialArea),
                                             options.scheme, Geometry::Hyperbolic);
  const BoundaryCycle cycle = boundaryCycle(tri);
  std::vector<double> target(tri.vertexCount, 0.0), next = target;
  inscribedTargets(cycle, metric, tri, target);
  BoundaryAcceleration acceleration(cycle.vertices.size());
  RicciFlowOptions flowOptions = diskMapFlowOptions(options);
  // The flows stop at half the tolerance: the other half is left for the last change of the
  // boundary targets, so that the error against the final ones can meet the tolerance.
  flowOptions.tolerance = 0.5 * options.tolerance;
  // Inside the Newton loop: once the flow has (nearly) reached the current targets, replace
  // them by those of the current boundary (accelerated). The last updates are plain, so that on
  // convergence the targets are exactly the inscribed polygon's.
  flowOptions.updateTarget = [&](const IntrinsicTriangulation& t, const CirclePackingMetric& m,
                                 const std::vector<double>& curvature,
                                 std::vector<double>& flowTarget) {
    double reached = 0, change = 0;
    for (std::size_t v = 0; v < curvature.size(); ++v)
      reached = std::max(reached, std::abs(curvature[v] - flowTarget[v]));
    inscribedTargets(cycle, m, t, next);
    for (int v : cycle.vertices) change = std::max(change, std::abs(next[v] - flowTarget[v]));
    if (change == 0 || reached > 0.1 * change) return false;
    if (change > 4 * options.tolerance) {
      acceleration.update(cycle.vertices, flowTarget, next);
    } else {
      for (int v : cycle.vertices) flowTarget[v] = next[v];
    }
    target = flowTarget;
    ++result.boundaryUpdates;
    return true;
  };
  // The error reported is the true one: the final metric's curvature against the targets of
  // its own boundary (zero inside, the inscribed polygon's on the boundary).
  double error = 0;
  for (int flows = 1;; ++flows) {
    accumulateFlowReport(result.flow, runRicciFlow(tri, metric, target, flowOptions));
    inscribedTargets(cycle, metric, tri, next);
    const std::vector<double> curvature = vertexCurvature(tri, metric);
    error = 0;
    for (int v = 0; v < tri.vertexCount; ++v)
      error = std::max(error, std::abs(curvature[v] - next[v]));
    if (error <= options.tolerance) break;
    if (flows >= 10) {
      std::ostringstream s;
      s << "hyperbolic disk map: max curvature error " << error
        << " against the boundary's inscribed polygon after " << result.boundaryUpdates
        << " boundary updates (tolerance " << options.tolerance << ")";
      throw Error(ErrorCode::Unreachable, s.str());
    }
    target.swap(next);
  }
  result.flow.maxCurvatureError = error;
  result.usedFlips = result.flow.flipsStartedAt >= 0;
  const std::vector<Point> p = layOutOnHyperboloid(tri, metricEdgeLengths(tri, metric));

  // Poincaré disk z = (x + iy)/(1 + t); the boundary's circle by an algebraic least-squares fit
  // |z|² + a x + b y + c = 0 (exact for points on a circle).
  std::vector<std::complex<double>> z(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) z[v] = std::complex<double>(p[v].x(), p[v].y()) / (1 + p[v].z());
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (int v : cycle.vertices) {
    const Eigen::Vector3d row(z[v].real(), z[v].imag(), 1);
    normal += row * row.transpose();
    rhs -= row * std::norm(z[v]);
  }
  const Eigen::Vector3d abc = normal.ldlt().solve(rhs);
  const std::complex<double> centre(-0.5 * abc[0], -0.5 * abc[1]);
  const double radius = std::sqrt(std::norm(centre) - abc[2]);
  if (!(radius > 0)) throw Error(ErrorCode::Internal, "hyperbolic disk map: degenerate boundary circle");
  result.uv.resize(tri.vertexCount);
  for (int v = 0; v < tri.vertexCount; ++v) result.uv[v] = (z[v] - centre) / radius;
  return result;
}

}  // namespace confvis::conformal::detail
