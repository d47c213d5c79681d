// Bake directories (files, sidecar, previews, loading back) and the bake cache (hits, keys,
// corrupt and partial entries), on synthetic DisplayMaps standing in for computeDisplayMap.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>

#include "bake_test_support.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace confvis {
namespace {

namespace fs = std::filesystem;

fs::path scratchRoot() {
  return fs::temp_directory_path() / ("confvis_bake_" + std::to_string(getpid()));
}

fs::path scratchDirectory(const std::string& name) {
  const fs::path dir = scratchRoot() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Removes this process's scratch folders when the test binary exits.
const struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ec;
    fs::remove_all(scratchRoot(), ec);
  }
} scratchCleanup;

DisplayConfig cave5() {
  return loadDisplayConfig(fs::path(CONFVIS_SOURCE_DIR) / "configs" / "cave5.json");
}

// A synthetic map (the front hemisphere shown on a rotated cap) that counts its calls.
struct CountingSource {
  int calls = 0;
  DisplayMap operator()(const DisplayConfig&) {
    ++calls;
    DisplayMap map;
    map.source = test::makeCapMesh(10, 0.5 * std::numbers::pi);
    map.target = test::makeCapMesh(10, 0.4 * std::numbers::pi, [](const Vec3d& s) {
      return test::rotate(Vec3d{s.x, -s.y, -s.z}, {0, 1, 0}, 0.3);
    });
    map.target.lit.assign(map.target.triangles.size(), 1);
    map.target.lit[0] = 0;
    map.sourceMarkers = {1, 2, 3};
    map.targetMarkers = {4, 5, 6};
    map.stats = {{"template", 0.001}, {"flow", 0.002}, {"alignment", 0.0001}};
    return map;
  }
};

BakeDisplayOptions smallBake(const fs::path& cache) {
  BakeDisplayOptions options;
  options.resolution = 16;
  options.cacheDirectory = cache;
  return options;
}

bool sameMaps(const RetargetMap& a, const RetargetMap& b) {
  for (int f = 0; f < 6; ++f)
    if (a.ray.faces[f].pixels != b.ray.faces[f].pixels ||
        a.geom.faces[f].pixels != b.geom.faces[f].pixels)
      return false;
  return a.reference == b.reference && a.resolution() == b.resolution();
}

TEST(BakeFiles, DirectoryHoldsEveryFileAndLoadsBack) {
  CountingSource source;
  const DisplayConfig config = cave5();
  const DisplayMap displayMap = source(config);
  BakeOptions options;
  options.reference = {0.1, -0.2, 0.3};
  BakeTimings timings;
  const RetargetMap map = bakeRetargetMap(displayMap, 24, options, &timings);
  const fs::path dir = scratchDirectory("files");
  const nlohmann::json written =
      writeBakeDirectory(dir, displayMap, map, makeBakeSidecar(config, displayMap, map, timings));

  const LoadedBake loaded = loadBakeDirectory(dir);
  EXPECT_TRUE(sameMaps(loaded.map, map));
  EXPECT_EQ(loaded.sidecar, written);
  const nlohmann::json& s = loaded.sidecar;
  EXPECT_EQ(s["config_hash"], config.hash);
  EXPECT_EQ(s["resolution"], 24);
  EXPECT_EQ(s["reference"], nlohmann::json({0.1, -0.2, 0.3}));
  EXPECT_EQ(s["meshes"]["target"]["triangles"], displayMap.target.triangles.size());
  EXPECT_EQ(s["meshes"]["target"]["unlit_triangles"], 1);
  EXPECT_EQ(s["meshes"]["source"]["markers"], nlohmann::json({1, 2, 3}));
  EXPECT_EQ(s["timings"]["display_map"]["flow"], 0.002);
  EXPECT_GT(s["timings"]["bake"]["total"].get<double>(), 0.0);
  EXPECT_EQ(s["quality"]["ray_conformality"]["flipped_texels"], 0);
  EXPECT_GT(s["quality"]["ray_conformality"]["measured_texels"].get<int>(), 100);
  EXPECT_EQ(s["files"].size(), 10u);

  // The OBJs: one vertex and one vt per mesh vertex, positions on the unit sphere.
  std::ifstream obj(dir / "target.obj");
  int v = 0, vt = 0, f = 0;
  for (std::string line; std::getline(obj, line);) {
    v += line.rfind("v ", 0) == 0;
    vt += line.rfind("vt ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, static_cast<int>(displayMap.target.sphere.size()));
  EXPECT_EQ(vt, v);
  EXPECT_EQ(f, static_cast<int>(displayMap.target.triangles.size()));

  // Previews: cube crosses are 4N x 3N; the disk is opaque inside, transparent in the corners.
  EXPECT_EQ(readPng(dir / "ray.png").width, 4 * 24);
  EXPECT_EQ(readPng(dir / "geom-checker.png").height, 3 * 24);
  const ImageRGBA disk = readPng(dir / "target-disk.png");
  ASSERT_GT(disk.width, 100);
  EXPECT_EQ(disk.at(disk.width / 2, disk.height / 2)[3], 1.0f);
  EXPECT_EQ(disk.at(2, 2)[3], 0.0f);
}

TEST(BakeFiles, CorruptOrPartialDirectoriesAreRejectedNamingTheCulprit) {
  CountingSource source;
  const DisplayConfig config = cave5();
  const DisplayMap displayMap = source(config);
  const RetargetMap map = bakeRetargetMap(displayMap, 16);
  const fs::path dir = scratchDirectory("corrupt");
  writeBakeDirectory(dir, displayMap, map, makeBakeSidecar(config, displayMap, map, {}));
  auto expectCorrupt = [&](const fs::path& d, const std::string& fragment) {
    test::expectError([&] { loadBakeDirectory(d); }, ErrorCode::IoFailure, fragment);
  };
  // Truncated EXR: caught by the size check; with a matching (edited) size, by the EXR reader.
  const fs::path truncated = scratchDirectory("truncated");
  copyBakeDirectory(dir, truncated);
  fs::resize_file(truncated / "geom.exr", fs::file_size(truncated / "geom.exr") / 2);
  expectCorrupt(truncated, "geom.exr has");
  nlohmann::json sidecar = nlohmann::json::parse(readTextFile(truncated / "bake.json"));
  sidecar["files"]["geom.exr"]["bytes"] = fs::file_size(truncated / "geom.exr");
  writeTextAtomically(truncated / "bake.json", sidecar.dump());
  expectCorrupt(truncated, "geom.exr does not match its checksum");
  // Sidecar that does not match the maps.
  const fs::path mismatched = scratchDirectory("mismatched");
  copyBakeDirectory(dir, mismatched);
  sidecar = nlohmann::json::parse(readTextFile(mismatched / "bake.json"));
  sidecar["resolution"] = 32;
  writeTextAtomically(mismatched / "bake.json", sidecar.dump());
  expectCorrupt(mismatched, "bake.json says 32");
  sidecar["resolution"] = 16;
  sidecar["format_version"] = 99;
  writeTextAtomically(mismatched / "bake.json", sidecar.dump());
  expectCorrupt(mismatched, "format version 99");
  sidecar["format_version"] = kBakeFormatVersion;
  sidecar["files"]["../../etc/passwd"] = {{"bytes", 1}, {"fnv1a64", "0"}};
  writeTextAtomically(mismatched / "bake.json", sidecar.dump());
  expectCorrupt(mismatched, "outside the directory");
  writeTextAtomically(mismatched / "bake.json", "{\"format\": ");
  expectCorrupt(mismatched, "not valid JSON");
  // Partial: no sidecar at all.
  EXPECT_THROW(loadBakeDirectory(scratchDirectory("empty")), Error);
}

TEST(BakeCache, SecondBakeOfTheSameConfigIsAHit) {
  CountingSource source;
  const fs::path cache = scratchDirectory("cache-hit");
  const BakedDisplay first = bakeDisplayWith(cave5(), smallBake(cache), std::ref(source));
  EXPECT_FALSE(first.fromCache);
  EXPECT_TRUE(first.displayMap.has_value());
  EXPECT_TRUE(first.cacheNote.empty()) << first.cacheNote;
  EXPECT_TRUE(fs::exists(first.cacheEntry / "bake.json"));
  EXPECT_EQ(first.cacheEntry,
            bakeCacheEntry(cache, first.config, first.sidecar.at("map_settings")));
  const BakedDisplay second = bakeDisplayWith(cave5(), smallBake(cache), std::ref(source));
  EXPECT_TRUE(second.fromCache);
  EXPECT_FALSE(second.displayMap.has_value());
  EXPECT_EQ(source.calls, 1);
  EXPECT_TRUE(sameMaps(first.map, second.map));
  EXPECT_EQ(first.sidecar, second.sidecar);
  // Without the cache, nothing is read or written.
  BakeDisplayOptions noCache = smallBake(scratchDirectory("unused"));
  noCache.useCache = false;
  const BakedDisplay uncached = bakeDisplayWith(cave5(), noCache, std::ref(source));
  EXPECT_EQ(source.calls, 2);
  EXPECT_TRUE(uncached.cacheEntry.empty());
  EXPECT_TRUE(fs::is_empty(noCache.cacheDirectory));
  EXPECT_TRUE(sameMaps(first.map, uncached.map));
}

// Every setting that changes the map is part of the key (issue 22, point 4): two bakes that
// differ only in the grading, only in the route or only in the preset never share an entry, and
// an entry whose bake.json names other map settings is not used.
TEST(BakeCache, MapSettingsChangeTheKey) {
  CountingSource source;
  const fs::path cache = scratchDirectory("cache-settings");
  BakeDisplayOptions uniform = smallBake(cache);
  uniform.edgeLength = 0.2;  // the same config (edge included) for every bake below
  BakeDisplayOptions graded = uniform;
  graded.grading = TemplateGrading{.radiusDegrees = 20};
  BakeDisplayOptions graded30 = uniform;
  graded30.grading = TemplateGrading{.radiusDegrees = 30};
  BakeDisplayOptions otherRoute = uniform;  // fast takes the Euclidean route on cave5
  otherRoute.route = DisplayMapRoute::Spherical;
  BakeDisplayOptions mobius = uniform;
  mobius.interpolation = MapInterpolation::Mobius;
  BakeDisplayOptions accurate = uniform;
  accurate.preset = BakePreset::Accurate;  // its grading and interpolation; the explicit edge stays
  BakeDisplayOptions accurateLinear = accurate;
  accurateLinear.interpolation = MapInterpolation::Linear;
  std::set<fs::path> entries;
  for (const BakeDisplayOptions* o :
       {&uniform, &graded, &graded30, &otherRoute, &mobius, &accurate, &accurateLinear}) {
    const BakedDisplay baked = bakeDisplayWith(cave5(), *o, std::ref(source));
    EXPECT_FALSE(baked.fromCache);
    EXPECT_EQ(baked.config.hash, effectiveBakeConfig(cave5(), uniform).hash);
    EXPECT_TRUE(entries.insert(baked.cacheEntry).second) << baked.cacheEntry;
    const DisplayMapOptions map = bakeMapOptions(baked.config, *o);
    EXPECT_EQ(baked.sidecar.at("map_settings"),
              mapSettingsJson(map.route, map.grading, bakeInterpolation(*o)));
  }
  EXPECT_EQ(source.calls, 7);
  // The interpolation is what the bake used: the Möbius and linear bakes of one mesh differ.
  const BakedDisplay linearBake = bakeDisplayWith(cave5(), uniform, std::ref(source));
  const BakedDisplay mobiusBake = bakeDisplayWith(cave5(), mobius, std::ref(source));
  EXPECT_FALSE(sameMaps(linearBake.map, mobiusBake.map));
  EXPECT_EQ(mobiusBake.sidecar.at("map_settings").at("interpolation"), "mobius");
  EXPECT_TRUE(bakeDisplayWith(cave5(), graded, std::ref(source)).fromCache);
  EXPECT_EQ(source.calls, 7);
  // An entry under the graded key whose bake.json says uniform (hand-copied) is rebuilt.
  const fs::path uniformEntry = bakeDisplayWith(cave5(), uniform, std::ref(source)).cacheEntry;
  const fs::path gradedEntry = bakeDisplayWith(cave5(), graded, std::ref(source)).cacheEntry;
  fs::remove_all(gradedEntry);
  fs::copy(uniformEntry, gradedEntry);
  const BakedDisplay rebuilt = bakeDisplayWith(cave5(), graded, std::ref(source));
  EXPECT_FALSE(rebuilt.fromCache);
  EXPECT_NE(rebuilt.cacheNote.find("map settings"), std::string::npos) << rebuilt.cacheNote;
  EXPECT_EQ(source.calls, 8);
}

TEST(BakeCache, PresetsScaleTheConfigEdgeUnlessOneIsGiven) {
  const DisplayConfig config = cave5();
  BakeDisplayOptions fast;
  fast.preset = BakePreset::Fast;
  BakeDisplayOptions accurate;
  accurate.preset = BakePreset::Accurate;
  EXPECT_EQ(effectiveBakeConfig(config, fast).hash, config.hash);
  EXPECT_DOUBLE_EQ(effectiveBakeConfig(config, accurate).edgeLength,
                   presetSettings(BakePreset::Accurate).edgeScale * config.edgeLength);
  accurate.edgeLength = 0.3;
  EXPECT_DOUBLE_EQ(effectiveBakeConfig(config, accurate).edgeLength, 0.3);
  EXPECT_GT(bakeMapOptions(config, accurate).grading.radiusDegrees, 0);
  EXPECT_EQ(bakeMapOptions(config, fast).grading.radiusDegrees, 0);
  EXPECT_EQ(bakeInterpolation(accurate), MapInterpolation::Mobius);
  EXPECT_EQ(bakeInterpolation(fast), MapInterpolation::Linear);
  accurate.interpolation = MapInterpolation::Linear;
  EXPECT_EQ(bakeInterpolation(accurate), MapInterpolation::Linear);
  EXPECT_EQ(parseMapInterpolation("mobius"), MapInterpolation::Mobius);
  EXPECT_EQ(parseMapInterpolation("linear"), MapInterpolation::Linear);
  test::expectError([] { parseMapInterpolation("cubic"); }, ErrorCode::InvalidInput,
                    "linear or mobius");
  EXPECT_EQ(parseBakePreset("fast"), BakePreset::Fast);
  EXPECT_EQ(parseBakePreset("accurate"), BakePreset::Accurate);
  test::expectError([] { parseBakePreset("best"); }, ErrorCode::InvalidInput, "fast or accurate");
}

TEST(BakeCache, OverridesChangeTheKeyAndAreValidated) {
  const DisplayConfig config = cave5();
  BakeDisplayOptions none;
  EXPECT_EQ(effectiveBakeConfig(config, none).hash, config.hash);
  std::set<std::string> hashes{config.hash};
  BakeDisplayOptions resolution;
  resolution.resolution = 512;
  BakeDisplayOptions edge;
  edge.edgeLength = 0.1;
  BakeDisplayOptions reference;
  reference.reference = Vec3d{0.2, 0, 0};
  for (const BakeDisplayOptions* o : {&resolution, &edge, &reference}) {
    const DisplayConfig effective = effectiveBakeConfig(config, *o);
    EXPECT_TRUE(hashes.insert(effective.hash).second);
    EXPECT_EQ(effectiveBakeConfig(config, *o).hash, effective.hash);  // deterministic
  }
  EXPECT_EQ(effectiveBakeConfig(config, resolution).cubeResolution, 512);
  EXPECT_EQ(effectiveBakeConfig(config, edge).edgeLength, 0.1);
  EXPECT_EQ(effectiveBakeConfig(config, reference).reference, glm::dvec3(0.2, 0, 0));

  auto expectError = [&](const BakeDisplayOptions& o, const std::string& fragment) {
    test::expectError([&] { effectiveBakeConfig(config, o); }, ErrorCode::InvalidInput, fragment);
  };
  BakeDisplayOptions bad;
  bad.resolution = 4;
  expectError(bad, "cube_resolution");
  bad = {};
  bad.edgeLength = -1;
  expectError(bad, "edge_length");
  bad = {};
  bad.reference = Vec3d{0, 0, -2};  // behind the front wall
  expectError(bad, "front");
}

TEST(BakeCache, CorruptOrPartialEntriesAreRebuilt) {
  CountingSource source;
  const fs::path cache = scratchDirectory("cache-corrupt");
  const BakedDisplay first = bakeDisplayWith(cave5(), smallBake(cache), std::ref(source));
  const fs::path entry = first.cacheEntry;
  auto bakeAgain = [&] { return bakeDisplayWith(cave5(), smallBake(cache), std::ref(source)); };

  fs::resize_file(entry / "ray.exr", 100);  // truncated
  BakedDisplay again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("ray.exr"), std::string::npos) << again.cacheNote;
  EXPECT_EQ(source.calls, 2);
  EXPECT_TRUE(sameMaps(first.map, again.map));
  EXPECT_TRUE(bakeAgain().fromCache);  // the rebuilt entry is good

  // A sidecar for another config (e.g. copied by hand) does not match its key.
  nlohmann::json sidecar = nlohmann::json::parse(readTextFile(entry / "bake.json"));
  sidecar["config_hash"] = "0123456789abcdef";
  writeTextAtomically(entry / "bake.json", sidecar.dump());
  again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("config hash"), std::string::npos) << again.cacheNote;

  fs::remove(entry / "bake.json");  // partial: files without their sidecar
  again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("no bake.json"), std::string::npos) << again.cacheNote;
  EXPECT_EQ(source.calls, 4);
  EXPECT_TRUE(bakeAgain().fromCache);
  // No temporary folders are left behind.
  for (const auto& item : fs::directory_iterator(entry.parent_path()))
    EXPECT_EQ(item.path().filename().string().rfind(".tmp", 0), std::string::npos) << item.path();
}

// A wrongly typed config_hash raised an uncaught JSON type error (exit 3) and stayed, failing
// every later run; a changed reference point was accepted and then failed every render. Both
// are now removed and rebuilt; a flipped bit in an EXR is caught by its checksum.
TEST(BakeCache, WronglyTypedMovedOrBitFlippedEntriesAreRebuilt) {
  CountingSource source;
  const fs::path cache = scratchDirectory("cache-hostile");
  const BakedDisplay first = bakeDisplayWith(cave5(), smallBake(cache), std::ref(source));
  const fs::path entry = first.cacheEntry;
  auto bakeAgain = [&] { return bakeDisplayWith(cave5(), smallBake(cache), std::ref(source)); };
  const auto edited = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json sidecar = nlohmann::json::parse(readTextFile(entry / "bake.json"));
    edit(sidecar);
    writeTextAtomically(entry / "bake.json", sidecar.dump());
  };

  edited([](nlohmann::json& s) { s["config_hash"] = 12345; });
  BakedDisplay again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("config hash 12345"), std::string::npos) << again.cacheNote;
  EXPECT_TRUE(bakeAgain().fromCache);  // rebuilt, so later runs hit

  edited([](nlohmann::json& s) { s["reference"] = {0.5, 0.0, 0.0}; });
  again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("reference point differs"), std::string::npos) << again.cacheNote;
  EXPECT_TRUE(sameMaps(first.map, again.map));

  edited([](nlohmann::json& s) { s["files"] = "not an object"; });
  again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_FALSE(again.cacheNote.empty());

  std::string bytes = readTextFile(entry / "geom.exr");
  bytes[bytes.size() / 2] ^= 1;
  writeTextAtomically(entry / "geom.exr", bytes);
  again = bakeAgain();
  EXPECT_FALSE(again.fromCache);
  EXPECT_NE(again.cacheNote.find("geom.exr does not match its checksum"), std::string::npos)
      << again.cacheNote;
  EXPECT_EQ(source.calls, 5);
  EXPECT_TRUE(bakeAgain().fromCache);
}

TEST(BakeCache, UnwritableCacheStillBakes) {
  CountingSource source;
  const fs::path blocker = scratchDirectory("blocked") / "not-a-directory";
  std::ofstream(blocker) << "a file where the cache folder should be";
  const BakedDisplay baked = bakeDisplayWith(cave5(), smallBake(blocker), std::ref(source));
  EXPECT_FALSE(baked.fromCache);
  EXPECT_EQ(baked.map.resolution(), 16);
  EXPECT_NE(baked.cacheNote.find("not written"), std::string::npos) << baked.cacheNote;
}

TEST(BakeCache, DefaultDirectoryFollowsTheEnvironment) {
  const char* saved[3] = {std::getenv("CONFVIS_CACHE_DIR"), std::getenv("XDG_CACHE_HOME"),
                          std::getenv("HOME")};
  const std::string copies[3] = {saved[0] ? saved[0] : "", saved[1] ? saved[1] : "",
                                 saved[2] ? saved[2] : ""};
  setenv("CONFVIS_CACHE_DIR", "/tmp/explicit", 1);
  setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  setenv("HOME", "/tmp/home", 1);
  EXPECT_EQ(defaultCacheDirectory(), fs::path("/tmp/explicit"));
  unsetenv("CONFVIS_CACHE_DIR");
  EXPECT_EQ(defaultCacheDirectory(), fs::path("/tmp/xdg/confvis"));
  unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(defaultCacheDirectory(), fs::path("/tmp/home/.cache/confvis"));
  const char* names[3] = {"CONFVIS_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  for (int i = 0; i < 3; ++i) {
    if (saved[i]) setenv(names[i], copies[i].c_str(), 1);
    else unsetenv(names[i]);
  }
}

}  // namespace
}  // namespace confvis
