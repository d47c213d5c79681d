// Scene files: OBJ + MTL + texture, .gltf with an embedded buffer, .glb, and the error cases.
// Every fixture is written by the test into its own temporary directory.
#include "confvis/engine/scene_loader.hpp"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "confvis/base/error.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace fs = std::filesystem;
using namespace confvis;

namespace {

class SceneLoader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("confvis_scene_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
            std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& contents) const {
    std::ofstream(dir_ / name, std::ios::binary) << contents;
    return dir_ / name;
  }

  fs::path dir_;
};

// Expects `load` to throw an Error of `code` whose message names `file`.
template <typename Load>
void expectErrorNaming(Load load, ErrorCode code, const std::string& file) {
  try {
    load();
    FAIL() << "expected an Error naming " << file;
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), code) << error.what();
    EXPECT_NE(std::string(error.what()).find(file), std::string::npos) << error.what();
  }
}

glm::vec3 colorOfMesh(const Scene& scene, const std::string& meshName) {
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    if (scene.meshes[m].name == meshName) return scene.baseColorAt(m, 0, {1.0f / 3, 1.0f / 3});
  ADD_FAILURE() << "no mesh named " << meshName;
  return glm::vec3(-1.0f);
}

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= static_cast<std::uint8_t>(bytes[i + 2]);
    const std::size_t present = std::min<std::size_t>(3, bytes.size() - i);
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= present ? table[(chunk >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// One triangle (1,0,0), (0,1,0), (0,0,0) with unsigned-short indices, under a parent node
// translated by (1, 2, 3) and a child scaled by 2; material colour (0.2, 0.4, 0.6).
struct TriangleGltf {
  std::string buffer;
  nlohmann::json json;
};

TriangleGltf triangleGltf() {
  TriangleGltf gltf;
  const float positions[9] = {1, 0, 0, 0, 1, 0, 0, 0, 0};
  const std::uint16_t indices[4] = {0, 1, 2, 0};  // last one pads to 4 bytes
  gltf.buffer.assign(reinterpret_cast<const char*>(positions), sizeof positions);
  gltf.buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
  gltf.json = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"translation", {1, 2, 3}}, {"children", {1}}}, {{"scale", {2, 2, 2}}, {"mesh", 0}}}},
      {"meshes", {{{"name", "tri"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}}}}},
      {"buffers", {{{"byteLength", gltf.buffer.size()}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                       {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                      {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                     {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
  };
  return gltf;
}

void expectTransformedTriangle(const Scene& scene) {
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.triangles.size(), 1u);
  const glm::uvec3 t = mesh.triangles[0];
  EXPECT_EQ(mesh.positions[t.x], glm::vec3(3, 2, 3));  // (1,0,0) * 2 + (1,2,3)
  EXPECT_EQ(mesh.positions[t.y], glm::vec3(1, 4, 3));
  EXPECT_EQ(mesh.positions[t.z], glm::vec3(1, 2, 3));
  EXPECT_EQ(mesh.normals[t.x], glm::vec3(0, 0, 1));  // generated flat normal
  const glm::vec4 color = scene.baseColorAt(0, 0, {0.2f, 0.2f});
  EXPECT_FLOAT_EQ(color.g, 0.4f);
  EXPECT_FLOAT_EQ(color.b, 0.6f);
}

}  // namespace

TEST_F(SceneLoader, ObjWithMtlColourAndTexture) {
  // 2 x 2 PNG, row 0 (top): red, green; row 1 (bottom): blue, white. 0/255 decode exactly.
  const unsigned char pixels[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  ASSERT_NE(stbi_write_png((dir_ / "tex.png").c_str(), 2, 2, 3, pixels, 6), 0);
  write("scene.mtl",
        "newmtl plain\nKd 1 0.5 0.25\n"
        "newmtl textured\nKd 1 1 1\nmap_Kd tex.png\n");
  // OBJ texture v = 0 is the image bottom: vt 0.25 0.25 is the bottom-left (blue) texel and
  // vt 0.75 0.75 the top-right (green) one.
  const fs::path obj = write("scene.obj",
                             "mtllib scene.mtl\n"
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                             "vt 0.25 0.25\nvt 0.75 0.75\nvn 0 0 1\n"
                             "g a\nusemtl plain\nf 1//1 2//1 3//1\n"
                             "g b\nusemtl textured\nf 1/1/1 2/1/1 3/1/1\n"
                             "g c\nusemtl textured\nf 1/2 2/2 3/2\n");
  const Scene scene = loadScene(obj);
  EXPECT_EQ(scene.triangleCount(), 3u);
  EXPECT_EQ(colorOfMesh(scene, "plain"), glm::vec3(1.0f, 0.5f, 0.25f));
  ASSERT_EQ(scene.textures.size(), 1u);
  const auto& textured = scene.meshes;
  std::vector<glm::vec3> texturedColors;
  for (std::size_t m = 0; m < textured.size(); ++m)
    if (textured[m].name == "textured")
      for (std::size_t t = 0; t < textured[m].triangles.size(); ++t)
        texturedColors.push_back(scene.baseColorAt(m, t, {0.2f, 0.3f}));
  ASSERT_EQ(texturedColors.size(), 2u);
  EXPECT_EQ(texturedColors[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(texturedColors[1], glm::vec3(0, 1, 0));
  // Face c has no normals: flat ones are generated.
  for (const Mesh& mesh : scene.meshes)
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST_F(SceneLoader, ObjMissingMtlOrTextureWarnsAndFallsBack) {
  write("broken.mtl", "newmtl red\nKd 1 0 0\nmap_Kd nowhere.png\n");
  const fs::path missingTexture =
      write("a.obj", "mtllib broken.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  const Scene a = loadScene(missingTexture);
  EXPECT_EQ(colorOfMesh(a, "red"), glm::vec3(1, 0, 0));
  const fs::path missingMtl =
      write("b.obj", "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  const Scene b = loadScene(missingMtl);
  EXPECT_EQ(b.baseColorAt(0, 0, {0.3f, 0.3f}), glm::vec4(1.0f));
}

TEST_F(SceneLoader, GltfEmbeddedBufferNodeTransformsApplied) {
  TriangleGltf gltf = triangleGltf();
  gltf.json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(gltf.buffer);
  expectTransformedTriangle(loadScene(write("tri.gltf", gltf.json.dump())));
}

TEST_F(SceneLoader, GlbWithBinaryChunk) {
  TriangleGltf gltf = triangleGltf();
  std::string json = gltf.json.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string bin = gltf.buffer;
  bin.append((4 - bin.size() % 4) % 4, '\0');
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = u32(0x46546C67) + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
                          u32(static_cast<std::uint32_t>(json.size())) + u32(0x4E4F534A) + json +
                          u32(static_cast<std::uint32_t>(bin.size())) + u32(0x004E4942) + bin;
  expectTransformedTriangle(loadScene(write("tri.glb", glb)));
}

TEST_F(SceneLoader, GltfBaseColorTextureDecodedFromSrgb) {
  // 1 x 2 PNG: row 0 (uv v = 0 in glTF) sRGB 188 (linear ~0.5), row 1 black.
  const unsigned char pixels[6] = {188, 188, 188, 0, 0, 0};
  std::string png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
      },
      &png, 1, 2, 3, pixels, 3);
  TriangleGltf gltf = triangleGltf();
  const float uvs[6] = {0.5f, 0.25f, 0.5f, 0.25f, 0.5f, 0.25f};  // centre of row 0
  gltf.buffer.append(reinterpret_cast<const char*>(uvs), sizeof uvs);
  gltf.json["buffers"][0] = {{"byteLength", gltf.buffer.size()},
                             {"uri", "data:application/octet-stream;base64," + base64(gltf.buffer)}};
  gltf.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 24}});
  gltf.json["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
  gltf.json["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
  gltf.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  const Scene scene = loadScene(write("textured.gltf", gltf.json.dump()));
  ASSERT_EQ(scene.textures.size(), 1u);
  const glm::vec4 color = scene.baseColorAt(0, 0, {0.2f, 0.2f});
  // factor (0.2, 0.4, 0.6) times sRGB 188 decoded to linear 0.5029.
  EXPECT_NEAR(color.r, 0.2f * 0.5029f, 1e-3f);
  EXPECT_NEAR(color.b, 0.6f * 0.5029f, 1e-3f);
}

TEST_F(SceneLoader, ErrorsNameTheFile) {
  expectErrorNaming([&] { loadScene(dir_ / "absent.obj"); }, ErrorCode::FileNotFound, "absent.obj");
  expectErrorNaming([&] { loadScene(dir_ / "absent.glb"); }, ErrorCode::FileNotFound, "absent.glb");
  const fs::path stl = write("model.stl", "solid x\nendsolid x\n");
  expectErrorNaming([&] { loadScene(stl); }, ErrorCode::InvalidInput, "model.stl");
  const fs::path badJson = write("bad.gltf", "{ this is not json");
  expectErrorNaming([&] { loadScene(badJson); }, ErrorCode::InvalidInput, "bad.gltf");
  const fs::path badGlb = write("bad.glb", "glTF but not really");
  expectErrorNaming([&] { loadScene(badGlb); }, ErrorCode::InvalidInput, "bad.glb");
  const fs::path badIndex = write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expectErrorNaming([&] { loadScene(badIndex); }, ErrorCode::InvalidInput, "bad_index.obj");
  const fs::path pointsOnly = write("points.obj", "v 0 0 0\nv 1 0 0\n");
  expectErrorNaming([&] { loadScene(pointsOnly); }, ErrorCode::InvalidInput, "points.obj");
  TriangleGltf gltf = triangleGltf();  // a buffer the accessors overrun
  gltf.json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(gltf.buffer.substr(0, 12));
  gltf.json["buffers"][0]["byteLength"] = 12;
  const fs::path shortBuffer = write("short.gltf", gltf.json.dump());
  expectErrorNaming([&] { loadScene(shortBuffer); }, ErrorCode::InvalidInput, "short.gltf");
}

TEST_F(SceneLoader, NameOrFile) {
  EXPECT_EQ(sceneByNameOrFile("checker-tunnel").name, "checker-tunnel");
  expectErrorNaming([] { sceneByNameOrFile("no-such-scene"); }, ErrorCode::FileNotFound,
                    "no-such-scene");
  try {
    sceneByNameOrFile("no-such-scene");
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("checker-sphere"), std::string::npos);
  }
  TriangleGltf gltf = triangleGltf();
  gltf.json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(gltf.buffer);
  const fs::path file = write("tri.gltf", gltf.json.dump());
  EXPECT_EQ(sceneByNameOrFile(file.string()).triangleCount(), 1u);
}
