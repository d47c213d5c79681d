// checker-tunnel (dissertation Fig. 8.7): a long square tunnel along -z around the viewer with
// 1 m checker squares in world coordinates, so the closed form and the mesh share one rule.
#include <array>
#include <cmath>
#include <limits>

#include "builtin_scene_parts.hpp"

namespace confvis {

namespace {

// A wall lies in the plane p[fixedAxis] = side * half width; its checker squares are indexed by
// the world coordinates p[axisA], p[axisB] (metres), which are also its texture coordinates.
struct TunnelWall {
  const char* name;
  int fixedAxis;
  double side;
  int axisA, axisB;
  glm::vec3 color;
};

const std::array<TunnelWall, 4>& tunnelWalls() {
  static const std::array<TunnelWall, 4> walls = {{
      {"floor", 1, -1.0, 0, 2, {0.5f, 0.5f, 0.5f}},
      {"ceiling", 1, +1.0, 0, 2, {0.0f, 1.0f, 0.0f}},
      {"left wall", 0, -1.0, 2, 1, {1.0f, 0.0f, 0.0f}},
      {"right wall", 0, +1.0, 2, 1, {0.0f, 0.0f, 1.0f}},
  }};
  return walls;
}

glm::vec3 wallColorAt(const TunnelWall& wall, const glm::dvec3& p) {
  return builtin::checkerSquareColor(wall.color, static_cast<long long>(std::floor(p[wall.axisA])),
                                     static_cast<long long>(std::floor(p[wall.axisB])));
}

}  // namespace

std::optional<glm::vec3> checkerTunnelColor(glm::dvec3 direction) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Ray from the origin (inside the box) leaves through the nearer of the x and y slabs.
  const double tx = direction.x != 0.0 ? kTunnelHalfWidth / std::abs(direction.x) : inf;
  const double ty = direction.y != 0.0 ? kTunnelHalfWidth / std::abs(direction.y) : inf;
  const double t = std::min(tx, ty);
  if (t == inf) return std::nullopt;
  const glm::dvec3 hit = t * direction;
  if (hit.z < kTunnelZFar || hit.z > kTunnelZNear) return std::nullopt;  // open ends
  const int axis = tx < ty ? 0 : 1;
  for (const TunnelWall& wall : tunnelWalls())
    if (wall.fixedAxis == axis && (wall.side < 0.0) == (direction[axis] < 0.0))
      return wallColorAt(wall, hit);
  return std::nullopt;  // unreachable: every axis/side pair has a wall
}

namespace builtin {

Scene buildCheckerTunnel(const BuiltinSceneOptions& options) {
  const int perMetre = optionOrDefault(options.subdivision, 1, "subdivision", "checker-tunnel");
  const int texels = texelsPerSquare(options, "checker-tunnel");
  Scene scene;
  const double range[3][2] = {{-kTunnelHalfWidth, kTunnelHalfWidth},
                              {-kTunnelHalfWidth, kTunnelHalfWidth},
                              {kTunnelZFar, kTunnelZNear}};
  for (const TunnelWall& wall : tunnelWalls()) {
    Mesh mesh;
    mesh.name = wall.name;
    // A 2 x 2 tile repeated every 2 m: uv = world coordinate / 2 reproduces the square parity.
    const int texture = addTexture(scene, checkerTexture(wall.color, 2, texels));
    mesh.material = addMaterial(scene, wall.name, glm::vec3(1.0f), texture);
    glm::dvec3 inward(0.0);
    inward[wall.fixedAxis] = -wall.side;
    const double* rangeA = range[wall.axisA];
    const double* rangeB = range[wall.axisB];
    const int countA = static_cast<int>(std::lround((rangeA[1] - rangeA[0]) * perMetre));
    const int countB = static_cast<int>(std::lround((rangeB[1] - rangeB[0]) * perMetre));
    for (int j = 0; j <= countB; ++j) {
      for (int i = 0; i <= countA; ++i) {
        glm::dvec3 p(0.0);
        p[wall.fixedAxis] = wall.side * kTunnelHalfWidth;
        p[wall.axisA] = rangeA[0] + (rangeA[1] - rangeA[0]) * i / countA;
        p[wall.axisB] = rangeB[0] + (rangeB[1] - rangeB[0]) * j / countB;
        mesh.positions.emplace_back(p);
        mesh.normals.emplace_back(inward);
        mesh.uvs.emplace_back(p[wall.axisA] * 0.5, p[wall.axisB] * 0.5);
      }
    }
    addGridQuads(mesh, 0, countA, countB, glm::vec3(inward));
    scene.meshes.push_back(std::move(mesh));
  }
  return scene;
}

}  // namespace builtin
}  // namespace confvis
