// readMesh with a MeshSource: seams of duplicated vertices are welded and unused vertices left
// out, with every mesh vertex and triangle traced to the file; welding that would make a
// non-manifold vertex is not done, and the pieces are then named as the file numbers them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh_source.hpp"

using namespace confvis;
using namespace confvis::conformal;
namespace fs = std::filesystem;

namespace {

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_meshsource_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(MeshSource, ASeamIsWeldedAndUnusedVerticesAreLeftOut) {
  // A unit square as two triangles; the second uses copies of two corners (6 = 1, 5 = 3), and
  // vertex 7 is used by no face.
  MeshSource source;
  const TriMesh mesh = readMesh(writeFile("seam.obj",
                                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 1 0\nv 0 0 0\n"
                                          "v 5 5 5\nf 1 2 3\nf 6 5 4\n"),
                                source);
  EXPECT_EQ(mesh.n_vertices(), 4u);
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(source.weldedVertices, 2);
  EXPECT_EQ(source.unreferencedVertices, 1);
  EXPECT_EQ(source.fileVertex, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(source.fileFace, (std::vector<int>{0, 1}));
  EXPECT_TRUE(analyzeTopology(mesh).isDisk()) << analyzeTopology(mesh).describe();
  EXPECT_NO_THROW(requireDisk(mesh, source));
  EXPECT_EQ(source.vertexName(3), "vertex 4 (0, 1, 0)");
  EXPECT_EQ(source.faceName(1), "face 2");
}

TEST(MeshSource, WeldingThatMakesABowtieIsNotDoneAndThePiecesAreNamed) {
  // Two triangles whose corners 3 and 6 are at the same position: welded they would touch at a
  // point only, so they stay apart, and are named as two pieces (OFF: from 0).
  MeshSource source;
  const TriMesh mesh = readMesh(writeFile("apart.off",
                                          "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n2 1 0\n2 2 0\n1 1 0\n"
                                          "3 0 1 2\n3 3 4 5\n"),
                                source);
  EXPECT_EQ(mesh.n_vertices(), 6u);
  EXPECT_EQ(source.weldedVertices, 0);
  try {
    requireDisk(mesh, source);
    ADD_FAILURE() << "two pieces passed as a disk";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(message.find("2 separate pieces: the piece with face 0 (1 triangles) and the piece "
                           "with face 1 (1 triangles)"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("numbered from 0 as in the OFF file"), std::string::npos) << message;
  }
}

TEST(MeshSource, APolygonIsOneFaceOfTheFile) {
  // A quad fanned into two triangles: both trace back to face 1; a flipped triangle after it is
  // face 2, whatever the triangle count before it.
  MeshSource source;
  try {
    readMesh(writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                                   "f 1 2 3 4\nf 2 3 5\n"),
             source);
    ADD_FAILURE() << "inconsistent orientation passed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("face 2 lists its corners the other way round"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
