#pragma once
// Synthetic DisplayMaps for the bake tests: spherical caps with their exact conformal disk map,
// so maps between them have closed forms (identity, rotations, Möbius maps of the sphere).
#include <array>
#include <cmath>
#include <complex>
#include <functional>

#include <gtest/gtest.h>

#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/mesh_generators.hpp"

namespace confvis::test {

// Rotation by `angle` about the unit axis `u` (Rodrigues).
inline Vec3d rotate(const Vec3d& p, const Vec3d& u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * p + s * cross(u, p) + (1 - c) * dot(u, p) * u;
}

// The cap of directions within `capAngle` (radians, < pi) of +z, meshed from the round grid disk
// (radius r -> polar angle r * capAngle), then moved by `place` (default: the cap faces the
// front, -z). Triangles counter-clockwise seen from the centre, as in DisplayMap. Disk
// coordinates: the stereographic projection from the pole opposite the cap's centre, conjugated
// so the orientation matches, scaled to put the rim on the unit circle:
//   z = conj(tan(theta / 2) e^{i phi}) / tan(capAngle / 2), a conformal map of the cap.
inline SphereDiskMesh makeCapMesh(int n, double capAngle,
                                  const std::function<Vec3d(const Vec3d&)>& place = {}) {
  const conformal::TriMesh disk = conformal::makeRoundDisk(n);
  SphereDiskMesh mesh;
  const double rimScale = 1.0 / std::tan(capAngle / 2);
  for (auto v : disk.vertices()) {
    const auto& p = disk.point(v);
    const double r = std::min(1.0, std::hypot(p[0], p[1]));
    const double theta = r * capAngle, phi = std::atan2(p[1], p[0]);
    Vec3d s{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    mesh.disk.push_back(std::conj(std::polar(std::tan(theta / 2) * rimScale, phi)));
    if (r == 1.0) mesh.disk.back() /= std::abs(mesh.disk.back());  // exactly on the circle
    s = place ? place(s) : Vec3d{s.x, -s.y, -s.z};  // default: half-turn about x, +z -> -z
    mesh.sphere.push_back(normalized(s));
  }
  for (auto f : disk.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : f.vertices()) t[k++] = v.idx();
    mesh.triangles.push_back({t[0], t[2], t[1]});  // CCW from outside -> CCW from the centre
  }
  return mesh;
}

// Is d inside the cone over some triangle of the mesh (brute force, for coverage checks)?
// Returns the triangle or -1.
inline int containingTriangle(const SphereDiskMesh& mesh, const Vec3d& d, double tolerance = 0) {
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const Vec3d& a = mesh.sphere[mesh.triangles[t][0]];
    const Vec3d& b = mesh.sphere[mesh.triangles[t][1]];
    const Vec3d& c = mesh.sphere[mesh.triangles[t][2]];
    const double s = dot(a, cross(b, c)) > 0 ? 1.0 : -1.0;
    if (s * dot(d, cross(b, c)) >= -tolerance && s * dot(d, cross(c, a)) >= -tolerance &&
        s * dot(d, cross(a, b)) >= -tolerance)
      return t;
  }
  return -1;
}

}  // namespace confvis::test

namespace confvis::test {

// Per triangle, the singular-value ratio of the affine map from the chord triangle to its disk
// triangle: how far the mesh's own disk map is from conformal. A baked map composes two of these.
inline std::vector<double> diskMapRatios(const SphereDiskMesh& mesh) {
  std::vector<double> ratios;
  for (const auto& t : mesh.triangles) {
    const Vec3d e1 = mesh.sphere[t[1]] - mesh.sphere[t[0]], e2 = mesh.sphere[t[2]] - mesh.sphere[t[0]];
    const Vec3d ux = normalized(e1), uy = normalized(cross(cross(e1, e2), e1));
    const double p11 = dot(e1, ux), p12 = dot(e2, ux), p21 = dot(e1, uy), p22 = dot(e2, uy);
    const std::complex<double> q1 = mesh.disk[t[1]] - mesh.disk[t[0]], q2 = mesh.disk[t[2]] - mesh.disk[t[0]];
    const double det = p11 * p22 - p12 * p21;
    // J = Q P^-1, then the ratio from J's conformal and anti-conformal parts.
    const double j11 = (q1.real() * p22 - q2.real() * p21) / det, j12 = (q2.real() * p11 - q1.real() * p12) / det;
    const double j21 = (q1.imag() * p22 - q2.imag() * p21) / det, j22 = (q2.imag() * p11 - q1.imag() * p12) / det;
    const double conformal = std::hypot(j11 + j22, j21 - j12), anti = std::hypot(j11 - j22, j21 + j12);
    ratios.push_back((conformal + anti) / std::abs(conformal - anti));
  }
  return ratios;
}

}  // namespace confvis::test

namespace confvis::test {

// Expects call() to throw one confvis::Error with `code` whose message contains `fragment`.
template <class Call>
void expectError(Call&& call, ErrorCode code, const std::string& fragment) {
  try {
    call();
    ADD_FAILURE() << "no error; expected one mentioning '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

}  // namespace confvis::test
