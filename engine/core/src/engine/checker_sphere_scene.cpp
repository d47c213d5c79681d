// checker-sphere (dissertation Fig. 8.6): a "cube sphere" of radius 10 m around the viewer.
// Each cube face is an n x n grid projected to the sphere, so face-colour boundaries follow the
// cube edges exactly, and when n is a multiple of the squares per face every triangle lies in a
// single checker square (central projection maps the grid lines to great circles).
#include <algorithm>
#include <array>
#include <cmath>

#include "builtin_scene_parts.hpp"

namespace confvis {

namespace {

// Face frame: outward axis n and in-face axes u, v with u x v = n. A cube point on the face is
// n + a u + b v with gnomonic coordinates a, b in [-1, 1].
struct CubeFace {
  const char* name;
  glm::dvec3 n, u, v;
  glm::vec3 color;
};

constexpr glm::vec3 kRed{1.0f, 0.0f, 0.0f};
constexpr glm::vec3 kGreen{0.0f, 1.0f, 0.0f};
constexpr glm::vec3 kBlue{0.0f, 0.0f, 1.0f};

const std::array<CubeFace, 6>& cubeFaces() {
  static const std::array<CubeFace, 6> faces = {{
      {"+x (right)", {1, 0, 0}, {0, 0, -1}, {0, 1, 0}, kRed},
      {"-x (left)", {-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, kRed},
      {"+y (top)", {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, kGreen},
      {"-y (bottom)", {0, -1, 0}, {1, 0, 0}, {0, 0, 1}, kGreen},
      {"+z (back)", {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, kBlue},
      {"-z (front)", {0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, kBlue},
  }};
  return faces;
}

// Checker square index along one gnomonic coordinate, clamped so a = 1 stays on the face.
long long squareIndex(double coordinate) {
  const auto i = static_cast<long long>(std::floor((coordinate + 1.0) * 0.5 * kCheckerSquaresPerFace));
  return std::clamp(i, 0LL, static_cast<long long>(kCheckerSquaresPerFace - 1));
}

}  // namespace

glm::vec3 checkerSphereColor(glm::dvec3 direction) {
  const glm::dvec3 m = glm::abs(direction);
  const int axis = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
  const int faceIndex = 2 * axis + (direction[axis] < 0.0 ? 1 : 0);
  const CubeFace& face = cubeFaces()[static_cast<std::size_t>(faceIndex)];
  const double a = glm::dot(direction, face.u) / m[axis];
  const double b = glm::dot(direction, face.v) / m[axis];
  return builtin::checkerSquareColor(face.color, squareIndex(a), squareIndex(b));
}

namespace builtin {

Scene buildCheckerSphere(const BuiltinSceneOptions& options) {
  const int n = optionOrDefault(options.subdivision, 32, "subdivision", "checker-sphere");
  const int texels = texelsPerSquare(options, "checker-sphere");
  Scene scene;
  // Faces of one axis share a texture: the checker rule depends only on (a, b).
  std::array<int, 3> axisTexture{};
  for (int axis = 0; axis < 3; ++axis)
    axisTexture[static_cast<std::size_t>(axis)] = addTexture(
        scene, checkerTexture(cubeFaces()[static_cast<std::size_t>(2 * axis)].color,
                              kCheckerSquaresPerFace, texels));
  for (std::size_t f = 0; f < cubeFaces().size(); ++f) {
    const CubeFace& face = cubeFaces()[f];
    Mesh mesh;
    mesh.name = std::string("cube face ") + face.name;
    mesh.material = addMaterial(scene, mesh.name, glm::vec3(1.0f), axisTexture[f / 2]);
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        // -1 + 2i/n is exact at the face edges, so neighbouring faces share bitwise-equal
        // boundary vertices (watertight).
        const double a = -1.0 + 2.0 * i / n;
        const double b = -1.0 + 2.0 * j / n;
        const glm::dvec3 direction = glm::normalize(face.n + a * face.u + b * face.v);
        mesh.positions.emplace_back(kCheckerSphereRadius * direction);
        mesh.normals.emplace_back(-direction);  // seen from inside
        mesh.uvs.emplace_back((a + 1.0) * 0.5, (b + 1.0) * 0.5);
      }
    }
    addGridQuads(mesh, 0, n, n, glm::vec3(-face.n));
    scene.meshes.push_back(std::move(mesh));
  }
  return scene;
}

}  // namespace builtin
}  // namespace confvis
