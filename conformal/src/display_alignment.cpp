// The forward-and-up Möbius alignment of a display map (display_alignment.hpp).
#include "display_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mobius.hpp"

namespace confvis::detail {

using Complex = std::complex<double>;

SphereLocation locateDirection(const SphereDiskMesh& mesh, const Vec3d& direction) {
  // Inside the chord triangle (a, b, c) exactly when the triple products det(d, b, c),
  // det(d, c, a), det(d, a, b) share det(a, b, c)'s sign (sphere_raster.hpp); normalised, they
  // are the barycentric coordinates the bake uses. The first triangle wins: on a shared edge or
  // vertex every holder gives the same disk point.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3d& a = mesh.sphere[mesh.triangles[t][0]];
    const Vec3d& b = mesh.sphere[mesh.triangles[t][1]];
    const Vec3d& c = mesh.sphere[mesh.triangles[t][2]];
    const double det = dot(a, cross(b, c));
    if (det == 0) continue;
    const double sign = det > 0 ? 1.0 : -1.0;
    const std::array<double, 3> w{sign * dot(direction, cross(b, c)),
                                  sign * dot(direction, cross(c, a)),
                                  sign * dot(direction, cross(a, b))};
    const double sum = w[0] + w[1] + w[2];
    if (!(sum > 0) || std::min({w[0], w[1], w[2]}) < -1e-12 * sum) continue;
    SphereLocation at;
    at.triangle = static_cast<int>(t);
    for (int i = 0; i < 3; ++i) at.barycentric[i] = std::max(0.0, w[i]) / sum;
    return at;
  }
  return {};
}

Complex diskPoint(const SphereDiskMesh& mesh, const SphereLocation& at) {
  Complex z = 0;
  for (int i = 0; i < 3; ++i) z += at.barycentric[i] * mesh.disk[mesh.triangles[at.triangle][i]];
  return z;
}

Vec3d upAt(const Vec3d& direction) {
  const Vec3d d = normalized(direction);
  const Vec3d y{0, 1, 0};
  if (std::abs(d.y) < 0.99) return normalized(y - dot(y, d) * d);
  const Vec3d toward = d.y < 0 ? Vec3d{0, 0, -1} : Vec3d{0, 0, 1};
  return normalized(toward - dot(toward, d) * d);
}

namespace {

// Inside the mesh and off its rim (a point on the rim cannot be sent to the disk's centre).
bool interior(const SphereDiskMesh& mesh, const SphereLocation& at) {
  return at.triangle >= 0 && std::abs(diskPoint(mesh, at)) < 1 - 1e-9;
}

double longestEdgeAngle(const SphereDiskMesh& mesh, int triangle) {
  const auto& t = mesh.triangles[triangle];
  return std::max({angleBetween(mesh.sphere[t[0]], mesh.sphere[t[1]]),
                   angleBetween(mesh.sphere[t[1]], mesh.sphere[t[2]]),
                   angleBetween(mesh.sphere[t[2]], mesh.sphere[t[0]])});
}

// The display's centre of directions: the chord-area weighted mean of its triangles' centroids.
Vec3d centreOfDirections(const SphereDiskMesh& mesh) {
  Vec3d sum{};
  for (const auto& t : mesh.triangles) {
    const Vec3d& a = mesh.sphere[t[0]];
    const Vec3d& b = mesh.sphere[t[1]];
    const Vec3d& c = mesh.sphere[t[2]];
    sum = sum + (norm(cross(b - a, c - a)) / 3) * (a + b + c);
  }
  return norm(sum) > 1e-12 ? normalized(sum) : Vec3d{0, 0, -1};
}

Vec3d along(const Vec3d& anchor, const Vec3d& up, double angle) {
  return normalized(std::cos(angle) * anchor + std::sin(angle) * up);
}

// Moves mesh's disk so that `anchor` goes to 0 and the chord from the image of anchor - step*up
// to that of anchor + step*up (a symmetric difference: second-order accurate) points along +i.
void alignMesh(SphereDiskMesh& mesh, const Vec3d& anchor, double step) {
  const Vec3d up = upAt(anchor);
  const Complex a = diskPoint(mesh, locateDirection(mesh, anchor));
  const conformal::Mobius centred = conformal::Mobius::diskAutomorphism(a, 0);
  const Complex above = centred(diskPoint(mesh, locateDirection(mesh, along(anchor, up, step))));
  const Complex below = centred(diskPoint(mesh, locateDirection(mesh, along(anchor, up, -step))));
  const double turn = std::numbers::pi / 2 - std::arg(above - below);
  const conformal::Mobius m = conformal::Mobius::diskAutomorphism(a, turn);
  for (Complex& z : mesh.disk) z = m(z);
}

// The direction T_ray gives a disk point of the target: located in the source disk (clamped to
// the nearest triangle where it pokes out between a boundary chord and the circle).
Vec3d sourceDirectionAt(const SphereDiskMesh& source, Complex z) {
  double bestOutside = 1e300;
  Vec3d best{};
  for (const auto& t : source.triangles) {
    const Complex a = source.disk[t[0]], b = source.disk[t[1]], c = source.disk[t[2]];
    const double area = std::imag(std::conj(b - a) * (c - a));
    if (area == 0) continue;
    const double l1 = std::imag(std::conj(c - b) * (z - b)) / area;
    const double l2 = std::imag(std::conj(a - c) * (z - c)) / area;
    const double l0 = 1 - l1 - l2;
    const double outside = std::max({0.0, -l0, -l1, -l2});
    if (outside < bestOutside) {
      bestOutside = outside;
      best = std::max(0.0, l1) * source.sphere[t[0]] + std::max(0.0, l2) * source.sphere[t[1]] +
             std::max(0.0, l0) * source.sphere[t[2]];
    }
  }
  return normalized(best);
}

nlohmann::json toJson(const Vec3d& v) { return {v.x, v.y, v.z}; }

}  // namespace

nlohmann::json alignAtForward(DisplayMap& map, const Vec3d& forward, const std::string& name) {
  const Vec3d sourceAnchor = normalized(forward);
  Vec3d targetAnchor = sourceAnchor;
  bool straightAhead = true;
  if (!interior(map.target, locateDirection(map.target, targetAnchor))) {
    straightAhead = false;
    targetAnchor = centreOfDirections(map.target);
    if (!interior(map.target, locateDirection(map.target, targetAnchor)))
      throw Error(ErrorCode::InvalidInput,
                  name + ": the display covers neither the forward direction nor its own centre "
                         "of directions as seen from the reference point, so the map has no "
                         "point to centre on; move the reference point in front of the walls");
  }
  if (!interior(map.source, locateDirection(map.source, sourceAnchor)))
    throw Error(ErrorCode::InvalidInput,
                name + ": the forward direction lies on the rim of the source field (the cut "
                       "through the uncovered directions); use a hemisphere source about it");

  // One step for both disks, about a triangle of either mesh at its anchor: the chord through
  // the anchor then spans the triangles around it. Halved until both ends lie inside.
  double step = std::max(
      longestEdgeAngle(map.source, locateDirection(map.source, sourceAnchor).triangle),
      longestEdgeAngle(map.target, locateDirection(map.target, targetAnchor).triangle));
  auto fits = [&](const SphereDiskMesh& mesh, const Vec3d& anchor) {
    const Vec3d up = upAt(anchor);
    return interior(mesh, locateDirection(mesh, along(anchor, up, step))) &&
           interior(mesh, locateDirection(mesh, along(anchor, up, -step)));
  };
  for (int k = 0; k < 30 && !(fits(map.source, sourceAnchor) && fits(map.target, targetAnchor));
       ++k)
    step *= 0.5;
  alignMesh(map.source, sourceAnchor, step);
  alignMesh(map.target, targetAnchor, step);

  nlohmann::json stats = {{"rule", straightAhead ? "straight ahead" : "display centre"},
                          {"virtual_anchor", toJson(sourceAnchor)},
                          {"display_anchor", toJson(targetAnchor)},
                          {"up_step_degrees", step * 180 / std::numbers::pi}};
  // Sphere sources: how far each cut leaf (a marker) lands from the display corner it stands for.
  if (map.source.sphere != map.target.sphere || map.source.disk != map.target.disk) {
    double worst = 0;
    int measured = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3d leaf = map.source.sphere[map.sourceMarkers[k]];
      const Vec3d corner = map.target.sphere[map.targetMarkers[k]];
      if (angleBetween(leaf, corner) > 1e-9) continue;  // hemisphere rim points: azimuth only
      const Vec3d image = sourceDirectionAt(map.source, map.target.disk[map.targetMarkers[k]]);
      worst = std::max(worst, angleBetween(image, leaf));
      ++measured;
    }
    if (measured > 0) stats["leaf_offset_degrees"] = worst * 180 / std::numbers::pi;
  }
  return stats;
}

}  // namespace confvis::detail
