// confvis's own mesh readers (mesh_files.hpp) behind readMesh: every format round-trips what
// OpenMesh writes, and the small malformed files that hung or crashed OpenMesh's readers, or
// passed with garbage, are refused quickly, naming the file and the culprit.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh.hpp"
#include "confvis/conformal/mesh_generators.hpp"

using namespace confvis;
using namespace confvis::conformal;
namespace fs = std::filesystem;

namespace {

fs::path hostile(const std::string& name) {
  return fs::path(CONFVIS_SOURCE_DIR) / "tests" / "data" / "hostile" / name;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_meshfiles_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

fs::path writeFile(const std::string& name, const std::string& bytes) {
  const fs::path file = scratch(name);
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

// The message of the InvalidInput a read raises, which must name the file; and the seconds.
std::string readError(const fs::path& file, double* seconds = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  try {
    readMesh(file);
    ADD_FAILURE() << file << " was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    message = e.what();
    EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
  }
  if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return message;
}

void expectSameMesh(const TriMesh& read, const TriMesh& written, bool sameOrder) {
  ASSERT_EQ(read.n_vertices(), written.n_vertices());
  ASSERT_EQ(read.n_faces(), written.n_faces());
  EXPECT_TRUE(analyzeTopology(read).isDisk());
  if (!sameOrder) return;
  for (auto v : written.vertices())
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(read.point(TriMesh::VertexHandle(v.idx()))[i], written.point(v)[i], 1e-6);
}

std::string binaryPlyHeader(const char* format, int vertices, int faces) {
  return std::string("ply\nformat ") + format + " 1.0\ncomment confvis test\nelement vertex " +
         std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

template <class T>
void put(std::string& out, T value, bool bigEndian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

// A unit square as two triangles, binary PLY with an extra colour property.
std::string binaryPlySquare(bool bigEndian) {
  std::string out = binaryPlyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian", 4, 2);
  const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& p : points) {
    for (float c : p) put(out, c, bigEndian);
    out += '\x7f';
  }
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& face : faces) {
    out += '\x03';
    for (int corner : face) put(out, corner, bigEndian);
  }
  return out;
}

}  // namespace

TEST(MeshFiles, EveryFormatReadsBackWhatOpenMeshWrites) {
  const TriMesh hemisphere = makeHemisphere(6, 0.2, 3);
  for (const char* extension : {".obj", ".off", ".ply", ".stl"})
    for (bool binary : {false, true}) {
      if (binary && (std::string(extension) == ".obj" || std::string(extension) == ".off")) continue;
      const fs::path file = scratch(std::string(binary ? "binary" : "ascii") + extension);
      const OpenMesh::IO::Options options(binary ? OpenMesh::IO::Options::Binary
                                                 : OpenMesh::IO::Options::Default);
      ASSERT_TRUE(OpenMesh::IO::write_mesh(hemisphere, file.string(), options, 10));
      // STL stores each facet's corners: vertices are merged by position, in first-use order.
      expectSameMesh(readMesh(file), hemisphere, std::string(extension) != ".stl");
    }
}

TEST(MeshFiles, BinaryPlyOfBothByteOrdersAndPolygonsAreRead) {
  for (bool bigEndian : {false, true}) {
    const TriMesh mesh = readMesh(writeFile(bigEndian ? "be.ply" : "le.ply", binaryPlySquare(bigEndian)));
    EXPECT_EQ(mesh.n_vertices(), 4u);
    EXPECT_EQ(mesh.n_faces(), 2u);
    EXPECT_EQ(mesh.point(TriMesh::VertexHandle(2)), Vec3(1, 1, 0));
  }
  // A quad and a negative (relative) OBJ index: fanned into two triangles.
  const TriMesh quad = readMesh(writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 -1\n"));
  EXPECT_EQ(quad.n_faces(), 2u);
  const TriMesh off = readMesh(writeFile("quad.off", "OFF\n# comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(off.n_faces(), 2u);
  const TriMesh stl = readMesh(writeFile("quad.stl",
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\n"
      "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\n"
      "endfacet\nendsolid s\n"));
  EXPECT_EQ(stl.n_vertices(), 4u);  // the shared corners merged
}

// 180 bytes: OpenMesh's reader looped growing ~50 MB/s.
TEST(MeshFiles, PlyFaceCountMinusInfinityIsRefused) {
  double seconds = 0;
  const std::string message = readError(hostile("face-inf.ply"), &seconds);
  EXPECT_NE(message.find("element count '-inf'"), std::string::npos) << message;
  EXPECT_LT(seconds, 1.0);
}

// A typo in the header: OpenMesh's reader segfaulted.
TEST(MeshFiles, PlyUnknownHeaderLineIsRefused) {
  EXPECT_NE(readError(hostile("elument.ply")).find("unknown header line 'elument'"), std::string::npos);
}

// OpenMesh's reader looped on a face of valence -1.
TEST(MeshFiles, OffFaceOfValenceMinusOneIsRefused) {
  const std::string message = readError(hostile("valence-minus-one.off"));
  EXPECT_NE(message.find("face valence -1 is out of range"), std::string::npos) << message;
  EXPECT_NE(message.find("line 6"), std::string::npos) << message;
}

// NaN corners were merged into other vertices and the mesh read with exit 0.
TEST(MeshFiles, StlWithNanVertexIsRefused) {
  EXPECT_NE(readError(hostile("nan.stl")).find("non-finite"), std::string::npos);
}

TEST(MeshFiles, ObjWithUnparsableVertexLineIsRefused) {
  const std::string message = readError(hostile("bad-vertex.obj"));
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
  EXPECT_NE(message.find("'1,5'"), std::string::npos) << message;
}

// Counts in headers are checked against the file before anything of their size is reserved.
TEST(MeshFiles, CountsBeyondTheFileOrTheLimitsAreRefusedQuickly) {
  double seconds = 0;
  std::string message = readError(writeFile("lie.ply", binaryPlyHeader("binary_little_endian", 2000000000, 1)), &seconds);
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  message = readError(writeFile("short.ply", binaryPlyHeader("binary_little_endian", 1000000, 1) + "abc"), &seconds);
  EXPECT_NE(message.find("exceeds the file size"), std::string::npos) << message;
  message = readError(writeFile("short2.ply", binaryPlyHeader("binary_little_endian", 3, 1) + std::string(20, '\0')), &seconds);
  EXPECT_NE(message.find("ends inside its data"), std::string::npos) << message;
  EXPECT_LT(seconds, 1.0);
  message = readError(writeFile("short.off", "OFF\n16000000 1 0\n0 0 0\n"), &seconds);
  EXPECT_NE(message.find("ends after 1 of 16000000 vertices"), std::string::npos) << message;
  EXPECT_LT(seconds, 1.0);
  message = readError(writeFile("big.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n100000 0 1 2\n"));
  EXPECT_NE(message.find("face valence 100000 is out of range"), std::string::npos) << message;
  message = readError(writeFile("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
  EXPECT_NE(message.find("face corner 3 is not one of the 3 vertices"), std::string::npos) << message;
  message = readError(writeFile("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
  EXPECT_NE(message.find("counts from 1"), std::string::npos) << message;
  message = readError(writeFile("odd.stl", "not an stl"));
  EXPECT_NE(message.find("neither binary STL"), std::string::npos) << message;
  message = readError(writeFile("binary.off", "OFF BINARY\n"));
  EXPECT_NE(message.find("binary OFF"), std::string::npos) << message;
}

TEST(MeshFiles, RepeatedOrNonManifoldFacesAreRefused) {
  std::string message = readError(writeFile("repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\n"));
  EXPECT_NE(message.find("face 1 repeats vertex 1 (0, 0, 0)"), std::string::npos) << message;
  message = readError(writeFile("fin.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"));
  EXPECT_NE(message.find("the edge between vertex 1 (0, 0, 0) and vertex 2 (1, 0, 0) is shared by 3 "
                         "faces (face 1, face 2 and face 3): a non-manifold edge"),
            std::string::npos)
      << message;
}
