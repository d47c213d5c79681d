// The Scene type and the built-in scenes: textures, colour lookup, and the mesh versions of the
// checker scenes against their closed forms.
#include "confvis/engine/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "confvis/base/error.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "scene_test_support.hpp"

using namespace confvis;

namespace {

const glm::vec3 kBlue(0, 0, 1), kRed(1, 0, 0), kGreen(0, 1, 0), kWhite(1, 1, 1);

void expectColorNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& where) {
  EXPECT_NEAR(actual.r, expected.r, tolerance) << where;
  EXPECT_NEAR(actual.g, expected.g, tolerance) << where;
  EXPECT_NEAR(actual.b, expected.b, tolerance) << where;
}

std::string describe(glm::dvec3 d) {
  return "direction (" + std::to_string(d.x) + ", " + std::to_string(d.y) + ", " +
         std::to_string(d.z) + ")";
}

// Distance of x to the nearest integer.
double offInteger(double x) { return std::abs(x - std::round(x)); }

}  // namespace

TEST(SceneTexture, BilinearSamplingWrapsAround) {
  Texture texture{2, 1, {0, 0, 0, 1, /**/ 1, 1, 1, 1}};
  EXPECT_FLOAT_EQ(texture.sample({0.25f, 0.5f}).r, 0.0f);   // texel 0 centre
  EXPECT_FLOAT_EQ(texture.sample({0.75f, 0.5f}).r, 1.0f);   // texel 1 centre
  EXPECT_FLOAT_EQ(texture.sample({0.5f, 0.5f}).r, 0.5f);    // between them
  EXPECT_FLOAT_EQ(texture.sample({0.0f, 0.5f}).r, 0.5f);    // wraps to texel 1
  EXPECT_FLOAT_EQ(texture.sample({-1.75f, 3.5f}).r, 0.0f);  // repeat in u and v
}

TEST(SceneTexture, InteriorFastPathEqualsTheBilinearFormula) {
  Texture texture{3, 2, {}};
  for (int i = 0; i < 3 * 2 * 4; ++i) texture.rgba.push_back(static_cast<float>(i * i % 7));
  // uv (0.5, 0.5): x = 1.0, y = 0.5 in texel-centre units: halfway between rows 0 and 1.
  const glm::vec4 expected = 0.5f * (texture.texel(1, 0) + texture.texel(1, 1));
  const glm::vec4 got = texture.sample({0.5f, 0.5f});
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], expected[c], 1e-5f);
  // Off-centre: x = 0.25 + ..., compare with the wrapped path one period away.
  const glm::vec4 inside = texture.sample({0.4f, 0.6f}), wrapped = texture.sample({1.4f, 1.6f});
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(inside[c], wrapped[c], 1e-4f);
}

TEST(SceneColor, FactorTimesTextureAndWhiteDefault) {
  Scene scene;
  scene.textures.push_back(Texture{1, 1, {0.5f, 0.5f, 0.5f, 1.0f}});
  scene.materials.push_back(Material{"m", {1.0f, 0.5f, 0.0f, 1.0f}, 0});
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
  mesh.triangles = {{0, 1, 2}};
  mesh.material = 0;
  scene.meshes.push_back(mesh);
  mesh.material = -1;
  scene.meshes.push_back(mesh);
  validateScene(scene);
  EXPECT_EQ(scene.baseColorAt(0, 0, {0.3f, 0.3f}), glm::vec4(0.5f, 0.25f, 0.0f, 1.0f));
  EXPECT_EQ(scene.baseColorAt(1, 0, {0.3f, 0.3f}), glm::vec4(1.0f));
  EXPECT_EQ(scene.triangleCount(), 2u);
  EXPECT_EQ(scene.bounds().max, glm::vec3(1, 1, 0));
}

TEST(SceneValidation, RejectsBadIndicesAndEmptyScenes) {
  Scene scene;
  scene.name = "broken";
  EXPECT_THROW(validateScene(scene), Error);
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 3}};
  scene.meshes.push_back(mesh);
  try {
    validateScene(scene);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(error.what()).find("broken"), std::string::npos) << error.what();
  }
}

TEST(SceneBuiltin, UnknownNameListsKnownScenes) {
  try {
    builtinScene("checker-cube");
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.code(), ErrorCode::InvalidInput);
    EXPECT_NE(message.find("checker-cube"), std::string::npos) << message;
    for (const std::string& name : builtinSceneNames())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_THROW(builtinScene("graph", {.subdivision = -1}), Error);
}

TEST(SceneCheckerSphere, ClosedFormColoursByCubeFace) {
  expectColorNear(checkerSphereColor({0, 0, -1}), kBlue, 0, "front");
  expectColorNear(checkerSphereColor({0, 0, 1}), kBlue, 0, "back");
  expectColorNear(checkerSphereColor({1, 0, 0}), kRed, 0, "right");
  expectColorNear(checkerSphereColor({-1, 0, 0}), kRed, 0, "left");
  expectColorNear(checkerSphereColor({0, 1, 0}), kGreen, 0, "top");
  expectColorNear(checkerSphereColor({0, -1, 0}), kGreen, 0, "bottom");
  // Length does not matter.
  expectColorNear(checkerSphereColor({0, 0, -7}), kBlue, 0, "scaled");
  // Crossing the checker edge at the front face's centre line alternates face colour / white,
  // and so does the next edge a square (2/8 in gnomonic coordinates) further.
  const glm::vec3 left = checkerSphereColor({-0.01, 0.1, -1});
  const glm::vec3 right = checkerSphereColor({0.01, 0.1, -1});
  EXPECT_NE(left, right);
  EXPECT_TRUE((left == kBlue && right == kWhite) || (left == kWhite && right == kBlue));
  EXPECT_EQ(checkerSphereColor({0.26, 0.1, -1}), left);
}

TEST(SceneCheckerSphere, VerticesOnSphereWithInwardNormals) {
  const Scene scene = builtinScene("checker-sphere", {.subdivision = 8, .texelsPerSquare = 4});
  EXPECT_EQ(scene.meshes.size(), 6u);
  EXPECT_EQ(scene.triangleCount(), 6u * 8 * 8 * 2);
  const double r = kCheckerSphereRadius;
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p(mesh.positions[i]);
      ASSERT_NEAR(glm::length(p), r, 1e-6 * r);
      ASSERT_GT(glm::dot(glm::dvec3(mesh.normals[i]), -p / glm::length(p)), 0.999999);
    }
    for (const glm::uvec3& t : mesh.triangles) {  // winding agrees with the normals
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      ASSERT_LT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0f);
    }
  }
}

TEST(SceneCheckerSphere, TexturedMeshMatchesClosedForm) {
  const Scene scene = builtinScene("checker-sphere", {.subdivision = 8, .texelsPerSquare = 16});
  // Square centres and points 0.3 square off centre on every face; gnomonic coordinates are
  // symmetric under sign changes, so one set of (a, b) serves every face frame.
  const double square = 2.0 / kCheckerSquaresPerFace;
  int checked = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      for (int i = 0; i < kCheckerSquaresPerFace; ++i) {
        for (int j = 0; j < kCheckerSquaresPerFace; ++j) {
          for (const glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(0.3, -0.2)}) {
            glm::dvec3 d(0.0);
            d[axis] = sign;
            d[(axis + 1) % 3] = -1.0 + (i + 0.5 + offset.x) * square;
            d[(axis + 2) % 3] = -1.0 + (j + 0.5 + offset.y) * square;
            const auto hit = test::castRay(scene, glm::dvec3(0.0), d);
            ASSERT_TRUE(hit) << describe(d);
            const glm::vec3 color = scene.baseColorAt(hit->mesh, hit->triangle, hit->barycentrics);
            expectColorNear(color, checkerSphereColor(d), 1e-4f, describe(d));
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 6 * 64 * 2);
}

TEST(SceneCheckerTunnel, ClosedFormWallsAndOpenEnds) {
  EXPECT_FALSE(checkerTunnelColor({0, 0, -1}));  // straight out of the far end
  EXPECT_FALSE(checkerTunnelColor({0, 0, 1}));
  EXPECT_FALSE(checkerTunnelColor({0.01, 0.01, -1}));  // hits z = -200 > 50 m away
  // Floor at (0.5, -2, -2.5): squares (0, -3) -> odd -> white; (0.5, -2, -1.5): grey.
  EXPECT_EQ(*checkerTunnelColor({0.5, -2, -2.5}), kWhite);
  EXPECT_EQ(*checkerTunnelColor({0.5, -2, -1.5}), glm::vec3(0.5f));
  EXPECT_EQ(checkerTunnelColor({-2, 0.5, -1.5})->r, 1.0f);   // left wall red/white
  EXPECT_EQ(checkerTunnelColor({2, 0.5, -1.5})->b, 1.0f);    // right wall blue/white
  EXPECT_EQ(checkerTunnelColor({0.5, 2, -1.5})->g, 1.0f);    // ceiling green/white
}

TEST(SceneCheckerTunnel, MeshMatchesClosedFormAtHitPoints) {
  const Scene scene = builtinScene("checker-tunnel", {.subdivision = 1, .texelsPerSquare = 8});
  EXPECT_EQ(scene.meshes.size(), 4u);
  for (const Mesh& mesh : scene.meshes)  // inward normals: pointing at the tunnel axis
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      ASSERT_LT(glm::dot(glm::vec2(mesh.normals[i]), glm::vec2(mesh.positions[i])), 0.0f);
  int compared = 0, open = 0;
  for (int k = 0; k < 600; ++k) {
    // A deterministic spread of directions (golden-angle spiral over the sphere).
    const double z = 1.0 - (k + 0.5) / 300.0;
    const double phi = k * 2.399963229728653;
    const double r = std::sqrt(1.0 - z * z);
    const glm::dvec3 d(r * std::cos(phi), r * std::sin(phi), z);
    const auto expected = checkerTunnelColor(d);
    const auto hit = test::castRay(scene, glm::dvec3(0.0), d);
    ASSERT_EQ(expected.has_value(), hit.has_value()) << describe(d);
    if (!hit) {
      ++open;
      continue;
    }
    bool nearEdge = false;  // bilinear filtering blends across square edges
    for (int c = 0; c < 3; ++c)
      if ((c == 2 || std::abs(hit->point[c]) < kTunnelHalfWidth - 1e-6) &&
          offInteger(hit->point[c]) < 0.1)
        nearEdge = true;
    if (nearEdge) continue;
    const glm::vec3 color = scene.baseColorAt(hit->mesh, hit->triangle, hit->barycentrics);
    expectColorNear(color, *expected, 1e-5f, describe(d));
    ++compared;
  }
  EXPECT_GT(compared, 300);
  EXPECT_GT(open, 0);
}

TEST(SceneGraph, DeterministicClusteredAroundViewer) {
  const auto checksum = [](const Scene& scene) {
    std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a over the raw vertex and index data
    for (const Mesh& mesh : scene.meshes) {
      const auto mix = [&hash](const void* data, std::size_t bytes) {
        for (std::size_t i = 0; i < bytes; ++i)
          hash = (hash ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ULL;
      };
      mix(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
      mix(mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3));
    }
    return hash;
  };
  const Scene first = builtinScene("graph");
  const Scene second = builtinScene("graph");
  EXPECT_EQ(first.triangleCount(), second.triangleCount());
  EXPECT_EQ(checksum(first), checksum(second));
  EXPECT_GE(first.triangleCount(), 20000u);
  EXPECT_LE(first.triangleCount(), 60000u);
  int clusters = 0;
  for (const Mesh& mesh : first.meshes) clusters += mesh.name.rfind("cluster ", 0) == 0 ? 1 : 0;
  EXPECT_GE(clusters, 12);
  EXPECT_GE(first.materials.size(), 12u);
  for (const Mesh& mesh : first.meshes)
    for (const glm::vec3& p : mesh.positions) {
      ASSERT_GT(glm::length(p), 2.8f);
      ASSERT_LT(glm::length(p), 15.2f);
    }
  const Scene coarse = builtinScene("graph", {.subdivision = 1});  // bare icosahedron nodes
  EXPECT_LT(coarse.triangleCount(), first.triangleCount());
  EXPECT_EQ(coarse.meshes.size(), first.meshes.size());
}
