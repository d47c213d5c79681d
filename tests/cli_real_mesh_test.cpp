// `confvis flow` on meshes as scanners and exporters write them (tests/data/meshes, made by
// make_meshes.py): scan-like disks with slivers, zero-area faces and duplicated vertices map by
// every route and scheme with no face folded over (checked on the written OBJ), or fail with a
// reason; broken inputs are named as the file numbers them, before anything is repaired.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

fs::path meshData(const std::string& name) {
  return fs::path(CONFVIS_SOURCE_DIR) / "tests" / "data" / "meshes" / name;
}

struct DiskObj {
  std::vector<std::complex<double>> uv;
  std::vector<std::array<int, 3>> faces;  // vt indices, from 0
};

DiskObj readDiskObj(const fs::path& path) {
  DiskObj obj;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "vt") {
      double u = 0, v = 0;
      ls >> u >> v;
      obj.uv.emplace_back(u, v);
    } else if (tag == "f") {
      std::array<int, 3> f{};
      for (int& corner : f) {
        std::string word;
        ls >> word;
        corner = std::stoi(word.substr(word.find('/') + 1)) - 1;
      }
      obj.faces.push_back(f);
    }
  }
  return obj;
}

// Faces whose disk image is not counter-clockwise with positive area.
int foldedFaces(const DiskObj& obj) {
  int folded = 0;
  for (const auto& f : obj.faces) {
    const auto a = obj.uv.at(f[1]) - obj.uv.at(f[0]), b = obj.uv.at(f[2]) - obj.uv.at(f[0]);
    folded += !(a.real() * b.imag() - a.imag() * b.real() > 0);
  }
  return folded;
}

TEST(CliRealMesh, ScanLikeDisksMapByEveryRouteAndSchemeWithNoFaceFolded) {
  for (const char* file : {"scan-disk.obj", "scan-disk-crlf.obj", "scan-disk.ply"})
    for (const char* route : {"euclidean", "spherical", "hyperbolic"})
      for (const char* scheme : {"tangential", "thurston", "inversive", "yamabe", "virtual", "mixed"}) {
        const std::string what = std::string(file) + " " + route + " " + scheme;
        const fs::path out = scratch("real.obj"), report = scratch("real.json");
        const CliRun run = runCli("flow " + meshData(file).string() + " -q --geometry " + route +
                                  " --scheme " + scheme + " -o " + out.string() + " --report " +
                                  report.string());
        ASSERT_EQ(run.exitCode, 0) << what << "\n" << run.output;
        const DiskObj obj = readDiskObj(out);
        // Five seam or unreferenced duplicates in scan-disk.obj are welded: all three files
        // describe the same 285-vertex surface.
        ASSERT_EQ(obj.uv.size(), 285u) << what;
        EXPECT_EQ(foldedFaces(obj), 0) << what;
        for (const auto& z : obj.uv) EXPECT_LE(std::abs(z), 1 + 1e-8) << what;
        const auto json = nlohmann::json::parse(std::ifstream(report));
        EXPECT_LE(json["max_curvature_error"].get<double>(), 1e-10) << what;
        EXPECT_EQ(json["distortion"]["flipped_faces"].get<int>(), 0) << what;
        // The zero-area faces are moved off their long edge before the flow (by 1e-4 rad), and
        // any vertex moved to undo a fold moves by under 1 % of its shortest edge.
        EXPECT_GE(json["mollified_faces"].get<int>(), std::string(file) == "scan-disk.obj" ? 2 : 0);
        EXPECT_LT(json["largest_untangle_shift"].get<double>(), 0.01) << what;
        if (std::string(file) == "scan-disk.obj") {
          EXPECT_EQ(json["welded_vertices"].get<int>(), 5) << what;
        }
      }
}

// With the flips forced off the conformal schemes cannot get past the slivers on some routes:
// that is an error with the reason, never a folded map with exit 0.
TEST(CliRealMesh, ForcedFlipSettingsMapWithoutFoldsOrFailWithAReason) {
  for (const char* route : {"euclidean", "spherical", "hyperbolic"})
    for (const char* flips : {"off", "on"}) {
      const std::string what = std::string(route) + " flips " + flips;
      const fs::path out = scratch("forced.obj");
      fs::remove(out);
      const CliRun run = runCli("flow " + meshData("scan-disk.obj").string() + " -q --geometry " +
                                route + " --flips " + flips + " -o " + out.string());
      if (run.exitCode == 0) {
        EXPECT_EQ(foldedFaces(readDiskObj(out)), 0) << what;
      } else {
        EXPECT_EQ(run.exitCode, 2) << what << "\n" << run.output;
        EXPECT_NE(run.output.find("scan-disk.obj': no fold-free disk map"), std::string::npos)
            << what << "\n" << run.output;
        EXPECT_FALSE(fs::exists(out)) << what;
      }
    }
}

TEST(CliRealMesh, BrokenMeshesAreNamedAsTheFileNumbersThem) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"nonmanifold-edge.obj",
       {"the edge between vertex 1 (0, 0, 0) and vertex 2 (", "shared by 3 faces (face 1, face 6 and face 25)",
        "a non-manifold edge"}},
      {"bowtie.obj", {"vertex 8 (0.967233, 0.25389, 0) joins 2 fans", "non-manifold vertex"}},
      {"flipped-face.obj", {"face 10 lists its corners the other way round", "inconsistent orientation"}},
      {"hole.obj", {"2 boundary loops", "a hole bounded by vertices 2, 3, 4, 5, 6 and 1 more"}},
      {"two-components.obj",
       {"2 components", "2 separate pieces: the piece with face 1 (24 triangles) and the piece with "
                        "face 25 (24 triangles)"}}};
  for (const auto& [file, expected] : cases) {
    const CliRun run = runCli("flow -q " + meshData(file).string() + " -o " + scratch("bad.obj").string());
    EXPECT_EQ(run.exitCode, 2) << file << "\n" << run.output;
    for (const std::string& part : expected)
      EXPECT_NE(run.output.find(part), std::string::npos) << file << ": " << part << "\n" << run.output;
    EXPECT_NE(run.output.find("numbered from 1 as in the OBJ file"), std::string::npos) << run.output;
    // No message of OpenMesh's own (it would print "PolyMeshT::add_face: complex edge").
    EXPECT_EQ(run.output.find("PolyMeshT"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << "one line:\n" << run.output;
  }
  // OFF counts from 0: the same flipped face is face 9 there, its vertices as the file has them.
  const fs::path off = scratch("flipped.off");
  std::ofstream(off) << "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n"
                        "3 0 1 2\n3 0 3 2\n3 0 3 4\n3 0 4 1\n";
  const CliRun run = runCli("flow -q " + off.string());
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("face 1 lists its corners the other way round"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("numbered from 0 as in the OFF file"), std::string::npos) << run.output;
}

}  // namespace
