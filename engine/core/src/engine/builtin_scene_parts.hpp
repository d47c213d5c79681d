#pragma once
// Internal pieces shared by the built-in scene builders (one source file per scene).
#include <glm/glm.hpp>

#include <string>

#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis::builtin {

inline constexpr glm::vec3 kWhite{1.0f, 1.0f, 1.0f};
inline constexpr int kDefaultTexelsPerSquare = 16;

// The checker rule every checker scene uses, in the texture and in the closed form alike:
// square (i, j) has `color` where i + j is even and white where it is odd.
glm::vec3 checkerSquareColor(glm::vec3 color, long long i, long long j);

// squares x squares checker squares of texelsPerSquare² texels each; square (0, 0) at row 0.
Texture checkerTexture(glm::vec3 color, int squares, int texelsPerSquare);

int addTexture(Scene& scene, Texture texture);
int addMaterial(Scene& scene, const std::string& name, glm::vec3 color, int texture = -1);

// Appends the two triangles of quad (a, b, c, d) (corners in order around it) so that their
// winding is counter-clockwise seen from the side `facing` points to.
void addQuad(Mesh& mesh, unsigned a, unsigned b, unsigned c, unsigned d, glm::vec3 facing);

// Triangulates a grid of (countA + 1) x (countB + 1) vertices appended row by row (index
// j * (countA + 1) + i, starting at mesh.positions index `first`), facing `facing`.
void addGridQuads(Mesh& mesh, unsigned first, int countA, int countB, glm::vec3 facing);

// Reads an option that must be non-negative; 0 selects `fallback`.
int optionOrDefault(int value, int fallback, const char* what, const std::string& scene);
// BuiltinSceneOptions::texelsPerSquare checked, with kDefaultTexelsPerSquare for 0.
int texelsPerSquare(const BuiltinSceneOptions& options, const std::string& scene);

Scene buildCheckerSphere(const BuiltinSceneOptions& options);
Scene buildCheckerTunnel(const BuiltinSceneOptions& options);
Scene buildGraph(const BuiltinSceneOptions& options);

}  // namespace confvis::builtin
