// Scene files from attackers and from real tools (issue: hostile input), each finding against
// its own minimal file in tests/data/hostile/. Before the fixes these read foreign memory,
// crashed, hung, or loaded with exit 0 and wrong content.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/display_import.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/engine/scene_units.hpp"

using namespace confvis;
namespace fs = std::filesystem;

namespace {

fs::path hostile(const std::string& name) {
  return fs::path(CONFVIS_SOURCE_DIR) / "tests" / "data" / "hostile" / name;
}

// The Error a load raises: InvalidInput, naming the file.
std::string loadError(const std::string& name) {
  try {
    loadScene(hostile(name));
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << name << " loaded without an error";
  return "";
}

double secondsOf(const std::function<void()>& call) {
  const auto start = std::chrono::steady_clock::now();
  call();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

// bufferView.byteOffset = 2^64 - 16: offset + length wrapped past the old bounds check.
TEST(HostileGltf, BufferViewOffsetNearTwoToTheSixtyFourIsRefused) {
  EXPECT_NE(loadError("offset-wrap.gltf").find("buffer view 0 reaches past the end of its buffer"),
            std::string::npos);
}

TEST(HostileGltf, AccessorOffsetNearTwoToTheSixtyFourIsRefused) {
  EXPECT_NE(loadError("accessor-offset-wrap.gltf").find("accessor reaches past the end"),
            std::string::npos);
}

// An image in a buffer view that starts 1 TiB into a 36-byte buffer: tinygltf passed the
// pointer on unchecked (segmentation fault).
TEST(HostileGltf, ImageBufferViewPastItsBufferIsRefused) {
  EXPECT_NE(loadError("image-view-past-buffer.gltf").find("reaches past the end of its buffer"),
            std::string::npos);
}

// 24 levels, each node listing its child twice: 2^24 instances of one triangle from 1 KB.
TEST(HostileGltf, NodeDagInstancingIsBounded) {
  std::string message;
  const double seconds = secondsOf([&] { message = loadError("node-dag.gltf"); });
  EXPECT_NE(message.find("node instances"), std::string::npos) << message;
  EXPECT_LT(seconds, 5.0);
}

TEST(HostileGltf, DeepJsonNestingIsRefusedBeforeTinygltfRecurses) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_deep_gltf_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "deep.gltf";
  std::ofstream(file) << "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " << std::string(100000, '[')
                      << std::string(100000, ']') << "}";
  try {
    loadScene(file);
    ADD_FAILURE() << "loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 64"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("deep.gltf"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(HostileGltf, DracoCompressionIsNamedNotReadAsACorruptAccessor) {
  const std::string message = loadError("draco.gltf");
  EXPECT_NE(message.find("Draco"), std::string::npos) << message;
  EXPECT_EQ(message.find("accessor"), std::string::npos) << message;
}

TEST(HostileGltf, UnknownRequiredExtensionIsNamed) {
  EXPECT_NE(loadError("unknown-required-extension.gltf").find("EXT_meshopt_compression"),
            std::string::npos);
}

// "%zz.png" decoded to a name tinygltf read as a directory: std::bad_alloc without a file name.
// Now the image is skipped with a warning, as any missing texture is, and the geometry loads.
TEST(HostileGltf, MalformedImageUriLeavesTheTextureOutNotTheProcess) {
  const Scene scene = loadScene(hostile("bad-image-uri.gltf"));
  EXPECT_EQ(scene.triangleCount(), 1u);
  EXPECT_TRUE(scene.textures.empty());
}

// (0, 0, 0) normals normalised to NaN and failed only when the image was written.
TEST(HostileGltf, ZeroLengthNormalsAreReplacedByFaceNormals) {
  const Scene scene = loadScene(hostile("zero-normals.gltf"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  for (const glm::vec3& n : scene.meshes[0].normals) {
    EXPECT_NEAR(n.x, 0.0f, 1e-6f);
    EXPECT_NEAR(n.y, 0.0f, 1e-6f);
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // counter-clockwise seen from +z
  }
}

// offset (0.5, 0.25), rotation 90 degrees, scale (2, 3): uv' = T R S uv with the README's
// matrices, so (0,0) -> (0.5, 0.25), (1,0) -> (0.5, 2.25), (0,1) -> (-2.5, 0.25).
TEST(HostileGltf, TextureTransformIsApplied) {
  const Scene scene = loadScene(hostile("texture-transform.gltf"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const auto& uvs = scene.meshes[0].uvs;
  ASSERT_EQ(uvs.size(), 3u);
  const glm::vec2 expected[3] = {{0.5f, 0.25f}, {0.5f, 2.25f}, {-2.5f, 0.25f}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(uvs[static_cast<std::size_t>(i)].x, expected[i].x, 1e-5f) << i;
    EXPECT_NEAR(uvs[static_cast<std::size_t>(i)].y, expected[i].y, 1e-5f) << i;
  }
}

// Found by fuzz_gltf (heap-buffer-overflow): one TEXCOORD_0 value for three positions was read
// past its end while flat normals were made.
TEST(HostileGltf, AttributeWithFewerValuesThanPositionsIsRefused) {
  EXPECT_NE(loadError("short-texcoord.gltf").find("TEXCOORD_0 has 1 values for 3 positions"),
            std::string::npos);
}

// "v 0 1,5 -2" was read by tinyobjloader as a vertex somewhere and rendered with exit 0.
TEST(HostileObj, UnparsableVertexLineIsRefusedNamingTheLine) {
  const std::string message = loadError("bad-vertex.obj");
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
  EXPECT_NE(message.find("1,5"), std::string::npos) << message;
}

TEST(HostileObj, TrailingCommentsAndColoursOnVertexLinesAreFine) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_obj_comment_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "c.obj") << "v 0 0 -2 # origin\nv 1 0 -2 1 0 0\nv 0 1 -2 0.5 0.5 0.5 1\n"
                                  "vt 0.5 # u only\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n";
  EXPECT_EQ(loadScene(dir / "c.obj").triangleCount(), 1u);
  fs::remove_all(dir);
}

// Found by fuzz_obj_scene: an `mtllib` name longer than the file system allows made
// is_regular_file throw std::filesystem::filesystem_error (ENAMETOOLONG) out of the loader.
TEST(HostileObj, OverlongMaterialLibraryNameIsAMissingLibrary) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_obj_mtllib_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "m.obj") << "mtllib " << std::string(300, 'm') << ".mtl\n"
                                  "v 0 0 -2\nv 1 0 -2\nv 0 1 -2\nf 1 2 3\n";
  EXPECT_EQ(loadScene(dir / "m.obj").triangleCount(), 1u);
  fs::remove_all(dir);
}

// Saved as UTF-16 by a Windows editor: "contains no triangles".
TEST(HostileObj, Utf16FileIsRead) {
  const Scene scene = loadScene(hostile("utf16.obj"));
  EXPECT_EQ(scene.triangleCount(), 1u);
  EXPECT_FLOAT_EQ(scene.bounds().max.x, 1.0f);
}

// A Windows exporter: CR LF, "usemtl red paint", "map_Kd .\textures\red.png". The material lost
// its name match (white) and the texture was "missing".
TEST(HostileObj, WindowsExportKeepsMaterialWithSpacesAndFindsBackslashTexture) {
  const Scene scene = loadScene(hostile("windows.obj"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "red paint");
  EXPECT_EQ(scene.meshes[0].material, 0);
  EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1, 0, 0, 1));
  ASSERT_EQ(scene.materials[0].baseColorTexture, 0);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].width, 2);
  EXPECT_NEAR(scene.textures[0].rgba[0], 1.0f, 1e-6f);  // red, linear
  EXPECT_NEAR(scene.textures[0].rgba[1], 0.0f, 1e-6f);
}

// Found by fuzz_pvx and fuzz_sgct_xml (their crash inputs, kept as they were found): a machine
// or window name with invalid UTF-8 from XML made the config hash's JSON dump throw an uncaught
// nlohmann type_error ("unexpected error", exit 3).
TEST(HostileImport, InvalidUtf8NamesFromXmlAreRefusedNamingTheFile) {
  for (const char* name : {"invalid-utf8-name.pvx", "invalid-utf8-name.xml"}) {
    try {
      (void)importDisplayConfig(hostile(name));
      ADD_FAILURE() << name << " was imported";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("not valid UTF-8"), std::string::npos) << e.what();
    }
  }
}

// A scene in millimetres on a 3 m display: a hint naming both sizes and the factor; none for a
// scene of the display's own size, and --scene-scale 0.001 makes it fit.
TEST(SceneUnits, MillimetreModelGetsAHintAndScalesToMetres) {
  const DisplayConfig display =
      loadDisplayConfig(fs::path(CONFVIS_SOURCE_DIR) / "configs" / "cave5.json");
  Scene scene;
  scene.name = "part.obj";
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}};  // 2 m, in millimetres
  mesh.triangles = {{0, 1, 2}};
  scene.meshes.push_back(mesh);
  const auto hint = sceneUnitsHint(scene, display);
  ASSERT_TRUE(hint.has_value());
  EXPECT_NE(hint->find("part.obj"), std::string::npos) << *hint;
  EXPECT_NE(hint->find("--scene-scale 0.001"), std::string::npos) << *hint;
  scaleScene(scene, 0.001);
  EXPECT_FLOAT_EQ(scene.bounds().max.x, 2.0f);
  EXPECT_FALSE(sceneUnitsHint(scene, display).has_value());
  EXPECT_THROW(scaleScene(scene, 1e300), Error);  // overflows float: refused, not inf
}
