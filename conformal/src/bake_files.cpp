#include "confvis/conformal/bake_files.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "bake_previews.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/base/json_text.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "confvis/conformal/obj_output.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/version.hpp"
#include "parallel_for.hpp"

namespace confvis {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kDiskPreviewSize = 512;

json meshJson(const SphereDiskMesh& mesh, const std::array<int, 3>& markers) {
  const auto unlit = static_cast<std::size_t>(std::count(mesh.lit.begin(), mesh.lit.end(), 0));
  return {{"vertices", mesh.sphere.size()},
          {"triangles", mesh.triangles.size()},
          {"boundary_vertices", mesh.boundary.size()},
          {"unlit_triangles", unlit},
          {"markers", markers}};
}

[[noreturn]] void corrupt(const fs::path& directory, const std::string& what) {
  throw Error(ErrorCode::IoFailure, "bake directory '" + directory.string() + "': " + what);
}

// The names under "files" of a sidecar, each a plain file name (never a path out of the folder).
std::vector<std::string> listedFiles(const fs::path& directory, const json& sidecar) {
  std::vector<std::string> names;
  for (const auto& [name, size] : sidecar.at("files").items()) {
    try {
      requireFileNameSafe(name, "listed file");
    } catch (const Error& e) {
      corrupt(directory, std::string("bake.json lists a file outside the directory: ") + e.what());
    }
    names.push_back(name);
  }
  return names;
}

// Each file's size and checksum under "files", then bake.json itself, last and atomically.
json finishDirectory(const fs::path& directory, const std::vector<std::string>& names, json sidecar) {
  json files = json::object();
  for (const std::string& name : names)
    files[name] = {{"bytes", fs::file_size(directory / name)},
                   {"fnv1a64", fileChecksum(directory / name)}};
  sidecar["files"] = files;
  writeTextAtomically(directory / "bake.json", sidecar.dump(2) + "\n");
  return sidecar;
}

void createDirectory(const fs::path& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec)
    throw Error(ErrorCode::IoFailure,
                "cannot create bake directory '" + directory.string() + "': " + ec.message());
}

// Every listed file is there, of the recorded size and checksum: a flipped bit, a truncated
// file or two swapped files are all caught before any of them is decoded.
void verifyListedFiles(const fs::path& directory, const json& sidecar) {
  for (const std::string& name : listedFiles(directory, sidecar)) {
    std::error_code ec;
    const auto actual = fs::file_size(directory / name, ec);
    if (ec) corrupt(directory, name + " is missing");
    const json& entry = sidecar.at("files").at(name);
    if (actual != entry.at("bytes").get<std::uintmax_t>())
      corrupt(directory, name + " has " + std::to_string(actual) + " bytes, bake.json says " +
                             entry.at("bytes").dump());
    if (fileChecksum(directory / name) != entry.at("fnv1a64").get<std::string>())
      corrupt(directory, name + " does not match its checksum in bake.json (changed or swapped "
                                "since the bake)");
  }
}

}  // namespace

json makeBakeSidecar(const DisplayConfig& config, const DisplayMap& displayMap,
                     const RetargetMap& map, const BakeTimings& timings, int qualityStride,
                     bool showProgress) {
  const int n = map.resolution();
  const int stride = qualityStride > 0 ? qualityStride : std::max(1, n / 128);
  const auto start = SteadyClock::now();
  Progress progress("quality", 5, showProgress);
  const ConformalityOptions conformality{.margin = 2, .discontinuityTolerance = 0.5, .stride = stride};
  const BakedConformality rayConformality = measureBakedConformality(map.ray, conformality);
  progress.advance();
  const BakedConformality geomConformality = measureBakedConformality(map.geom, conformality);
  progress.advance();
  const RoundTripStats rayGeom = measureRoundTrip(map, RoundTrip::RayThenGeom, stride);
  progress.advance();
  const RoundTripStats geomRay = measureRoundTrip(map, RoundTrip::GeomThenRay, stride);
  progress.advance();
  const CoverageStats coverage = measureCoverage(map, 1.0, stride);
  progress.finish();
  const double qualitySeconds = secondsSince(start);
  return {
      {"format", kBakeFormat},
      {"format_version", kBakeFormatVersion},
      {"confvis_version", versionString()},
      {"config_name", config.name},
      {"config_hash", config.hash},
      {"config", toJson(config)},
      {"reference", {map.reference.x, map.reference.y, map.reference.z}},
      {"resolution", n},
      {"edge_length", config.edgeLength},
      {"meshes",
       {{"source", meshJson(displayMap.source, displayMap.sourceMarkers)},
        {"target", meshJson(displayMap.target, displayMap.targetMarkers)}}},
      {"timings",
       {{"display_map", displayMap.stats},
        {"bake",
         {{"locators", timings.locators},
          {"ray", timings.ray},
          {"geom", timings.geom},
          {"extend", timings.extend},
          {"total", timings.total}}},
        {"quality", qualitySeconds}}},
      {"quality",
       {{"texel_angle_radians", texelAngle(n)},
        {"stride", stride},
        {"ray_conformality", toJson(rayConformality)},
        {"geom_conformality", toJson(geomConformality)},
        {"round_trip_ray_then_geom", toJson(rayGeom)},
        {"round_trip_geom_then_ray", toJson(geomRay)},
        {"coverage", toJson(coverage)}}},
  };
}

json writeBakeDirectory(const fs::path& directory, const DisplayMap& displayMap,
                        const RetargetMap& map, json sidecar, int threads, bool showProgress) {
  createDirectory(directory);
  const PngOptions data{.exposure = 1.0f, .srgb = false, .alpha = false};
  const std::vector<std::pair<std::string, std::function<void(const fs::path&)>>> files = {
      {"ray.exr", [&](const fs::path& p) { writeCubeExr(p, map.ray); }},
      {"geom.exr", [&](const fs::path& p) { writeCubeExr(p, map.geom); }},
      {"source.obj",
       [&](const fs::path& p) {
         conformal::writeObjWithDiskCoordinates(p, displayMap.source.sphere,
                                                displayMap.source.triangles, displayMap.source.disk);
       }},
      {"target.obj",
       [&](const fs::path& p) {
         conformal::writeObjWithDiskCoordinates(p, displayMap.target.sphere,
                                                displayMap.target.triangles, displayMap.target.disk);
       }},
      {"ray.png", [&](const fs::path& p) { writeCubeCrossPng(p, detail::directionPreview(map.ray), data); }},
      {"geom.png", [&](const fs::path& p) { writeCubeCrossPng(p, detail::directionPreview(map.geom), data); }},
      {"ray-checker.png", [&](const fs::path& p) { writeCubeCrossPng(p, detail::checkerPreview(map.ray)); }},
      {"geom-checker.png", [&](const fs::path& p) { writeCubeCrossPng(p, detail::checkerPreview(map.geom)); }},
      {"source-disk.png",
       [&](const fs::path& p) {
         writePng(p, detail::diskPreview(displayMap.source, kDiskPreviewSize), {.alpha = true});
       }},
      {"target-disk.png",
       [&](const fs::path& p) {
         writePng(p, detail::diskPreview(displayMap.target, kDiskPreviewSize), {.alpha = true});
       }},
  };
  const auto start = SteadyClock::now();
  Progress progress("files", files.size(), showProgress);
  detail::parallelFor(files.size(), threads, [&](std::size_t i) {
    files[i].second(directory / files[i].first);
    progress.advance();
  });
  progress.finish();
  sidecar["timings"]["files"] = secondsSince(start);
  std::vector<std::string> names;
  for (const auto& [name, write] : files) names.push_back(name);
  return finishDirectory(directory, names, std::move(sidecar));
}

json writeRetargetMapDirectory(const fs::path& directory, const RetargetMap& map) {
  createDirectory(directory);
  writeCubeExr(directory / "ray.exr", map.ray);
  writeCubeExr(directory / "geom.exr", map.geom);
  const json sidecar = {{"format", kBakeFormat},
                        {"format_version", kBakeFormatVersion},
                        {"confvis_version", versionString()},
                        {"reference", {map.reference.x, map.reference.y, map.reference.z}},
                        {"resolution", map.resolution()}};
  return finishDirectory(directory, {"ray.exr", "geom.exr"}, sidecar);
}

LoadedBake loadBakeDirectory(const fs::path& directory) {
  LoadedBake loaded;
  const std::string text = readTextFile(directory / "bake.json");  // FileNotFound if missing
  try {
    loaded.sidecar = parseJsonText(text, "bake.json");
  } catch (const Error& e) {
    corrupt(directory, std::string("bake.json is not valid JSON (") + e.what() + ")");
  }
  const json& s = loaded.sidecar;
  int resolution = 0;
  try {
    if (s.at("format").get<std::string>() != kBakeFormat) corrupt(directory, "bake.json is not a confvis bake");
    if (s.at("format_version").get<int>() != kBakeFormatVersion)
      corrupt(directory, "bake.json has format version " + s.at("format_version").dump() +
                             ", this confvis reads " + std::to_string(kBakeFormatVersion));
    resolution = s.at("resolution").get<int>();
    const auto reference = s.at("reference").get<std::array<double, 3>>();
    loaded.map.reference = {reference[0], reference[1], reference[2]};
    verifyListedFiles(directory, s);
  } catch (const json::exception& e) {
    corrupt(directory, std::string("bake.json lacks a field or has a wrong type (") + e.what() + ")");
  }
  for (const char* name : {"ray.exr", "geom.exr"}) {
    if (!s.at("files").contains(name)) corrupt(directory, std::string("bake.json does not list ") + name);
    CubeMap cube;
    try {
      cube = readCubeExr(directory / name);
    } catch (const Error& e) {
      corrupt(directory, e.what());
    }
    if (cube.faceSize != resolution)
      corrupt(directory, std::string(name) + " has " + std::to_string(cube.faceSize) +
                             " texels per face, bake.json says " + std::to_string(resolution));
    for (const ImageRGBA& face : cube.faces)
      if (!face.allFinite()) corrupt(directory, std::string(name) + " holds non-finite texels");
    (std::string(name) == "ray.exr" ? loaded.map.ray : loaded.map.geom) = std::move(cube);
  }
  return loaded;
}

void copyBakeDirectory(const fs::path& from, const fs::path& to) {
  json sidecar;
  try {  // a verified source only: sizes and checksums as recorded
    sidecar = parseJsonText(readTextFile(from / "bake.json"), (from / "bake.json").string());
    verifyListedFiles(from, sidecar);
  } catch (const json::exception& e) {
    corrupt(from, std::string("bake.json lacks a field or has a wrong type (") + e.what() + ")");
  }
  std::vector<std::string> names = listedFiles(from, sidecar);
  names.push_back("bake.json");  // last: a complete copy is one with its sidecar
  for (const std::string& name : names)
    writeFileAtomically(to / name, [&](const fs::path& temp) {
      fs::copy_file(from / name, temp, fs::copy_options::overwrite_existing);
    });
}

}  // namespace confvis
