// confvis mesh: writes the synthetic test meshes (disks, hemispheres, spheres) as files, for
// trying `confvis flow` and for the benchmarks.
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "command.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh_generators.hpp"

namespace confvis::cli {
namespace {

using namespace confvis::conformal;

struct MeshArgs {
  std::string kind = "hemisphere", output;
  int resolution = 32;
  double jitter = 0.2;
  unsigned seed = 1;
};

int runMesh(const MeshArgs& a) {
  TriMesh mesh;
  if (a.kind == "hemisphere") mesh = makeHemisphere(a.resolution, a.jitter, a.seed);
  else if (a.kind == "disk") mesh = makeRoundDisk(a.resolution, a.jitter, a.seed);
  else if (a.kind == "lopsided") mesh = makeLopsidedDisk(a.resolution, a.jitter, a.seed);
  else if (a.kind == "sphere") mesh = makeIcosphere(a.resolution);
  else if (a.kind == "pants") mesh = makeDiskWithTwoHoles(a.resolution);
  const std::string output = a.output.empty() ? a.kind + ".obj" : a.output;
  writeFileAtomically(output, [&](const std::filesystem::path& temp) {
    // Through our own stream, so a short write (a full disk) is seen: OpenMesh's file writer
    // reports success whatever the stream's state. The format comes from the extension.
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw Error(ErrorCode::IoFailure, "cannot open '" + output + "' for writing");
    OpenMesh::IO::Options options;
    const std::string extension = std::filesystem::path(output).extension().string();
    if (!OpenMesh::IO::write_mesh(mesh, out, extension, options, 17))
      throw Error(ErrorCode::IoFailure, "cannot write mesh '" + output +
                                            "' (OBJ, OFF, PLY and STL are supported)");
    out.close();
    if (!out)
      throw Error(ErrorCode::IoFailure,
                  "writing mesh '" + output + "' failed (" + std::strerror(errno) + ")");
  });
  std::printf("%s: %zu vertices, %zu faces\n", output.c_str(), mesh.n_vertices(), mesh.n_faces());
  return 0;
}

const RegisterCommand registration{Command{
    "mesh", "Write a synthetic test mesh (hemisphere, disk, lopsided disk, sphere, pants)",
    [](CLI::App& sub) {
      auto args = std::make_shared<MeshArgs>();
      sub.add_option("kind", args->kind, "Mesh kind")
          ->check(CLI::IsMember({"hemisphere", "disk", "lopsided", "sphere", "pants"}))
          ->capture_default_str();
      sub.add_option("-o,--output", args->output, "Output file, any OpenMesh format (default KIND.obj)");
      sub.add_option("-n,--resolution", args->resolution,
                     "Grid quads per side (sphere: subdivision levels; pants: at least 7)")
          ->check(CLI::Range(1, 4096))
          ->capture_default_str();
      sub.add_option("--jitter", args->jitter, "Random vertex displacement, fraction of spacing")
          ->check(CLI::Range(0.0, 0.9))
          ->capture_default_str();
      sub.add_option("--seed", args->seed, "Random seed")->capture_default_str();
      return [args] { return runMesh(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
