// The on-disk cache of baked displays (bake_display.hpp): where it lives and how entries are
// found, validated and published.
#include "bake_cache.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>

#include "confvis/base/checksum.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "confvis/engine/version.hpp"

namespace confvis {

namespace fs = std::filesystem;

fs::path defaultCacheDirectory() {
  auto env = [](const char* name) -> std::string {
    const char* value = std::getenv(name);
    return value ? value : "";
  };
  if (const std::string dir = env("CONFVIS_CACHE_DIR"); !dir.empty()) return dir;
  if (const std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) return fs::path(xdg) / "confvis";
  if (const std::string home = env("HOME"); !home.empty()) return fs::path(home) / ".cache" / "confvis";
  return fs::temp_directory_path() / "confvis-cache";
}

fs::path bakeCacheEntry(const fs::path& cacheDirectory, const DisplayConfig& effectiveConfig,
                        const nlohmann::json& mapSettings) {
  return cacheDirectory /
         ("bake-v" + std::to_string(kBakeFormatVersion) + "-confvis-" + versionString()) /
         (effectiveConfig.hash + "-" + fnv1a64Hex(mapSettings.dump()));
}

namespace detail {

std::optional<LoadedBake> loadCacheEntry(const fs::path& entry, const DisplayConfig& config,
                                         const nlohmann::json& mapSettings, std::string& note) {
  std::error_code ec;
  if (!pathExists(entry / "bake.json")) {
    if (pathExists(entry)) {  // a folder without its sidecar: an interrupted copy
      note = "cache entry '" + entry.string() + "' has no bake.json";
      fs::remove_all(entry, ec);
    }
    return std::nullopt;
  }
  try {
    LoadedBake loaded = loadBakeDirectory(entry);  // every file's size and checksum
    const nlohmann::json& hash = loaded.sidecar.contains("config_hash")
                                     ? loaded.sidecar.at("config_hash")
                                     : nlohmann::json();
    if (!hash.is_string() || hash.get<std::string>() != config.hash)
      throw Error(ErrorCode::IoFailure, "cache entry '" + entry.string() +
                                            "': bake.json is for config hash " + hash.dump());
    if (!loaded.sidecar.contains("map_settings") || loaded.sidecar["map_settings"] != mapSettings)
      throw Error(ErrorCode::IoFailure, "cache entry '" + entry.string() +
                                            "': bake.json's map settings differ from the bake's");
    if (loaded.map.resolution() != config.cubeResolution)
      throw Error(ErrorCode::IoFailure, "cache entry '" + entry.string() + "' has resolution " +
                                            std::to_string(loaded.map.resolution()));
    // The key covers the reference point, so a mismatch is a hand-edited or damaged entry:
    // used, it would fail every render (render_plan checks the map's reference).
    const glm::dvec3 reference(loaded.map.reference.x, loaded.map.reference.y,
                               loaded.map.reference.z);
    if (!(glm::length(reference - config.reference) <= 1e-9))
      throw Error(ErrorCode::IoFailure, "cache entry '" + entry.string() +
                                            "': bake.json's reference point differs from the "
                                            "config's");
    return loaded;
  } catch (const std::exception& e) {  // Error, and anything a damaged entry may raise
    note = e.what();
    fs::remove_all(entry, ec);
    return std::nullopt;
  }
}

nlohmann::json publishCacheEntry(const fs::path& entry, const DisplayMap& displayMap,
                                 const RetargetMap& map, const nlohmann::json& sidecar,
                                 int threads, bool showProgress) {
  static std::atomic<int> counter{0};
  const fs::path temp = entry.parent_path() / (".tmp-" + entry.filename().string() + "-" +
                                               std::to_string(getpid()) + "-" +
                                               std::to_string(counter++));
  std::error_code ec;
  fs::remove_all(temp, ec);
  try {
    const nlohmann::json written = writeBakeDirectory(temp, displayMap, map, sidecar, threads, showProgress);
    fs::rename(temp, entry, ec);  // atomic; fails if another process published first
    if (ec) fs::remove_all(temp, ec);
    return written;
  } catch (...) {
    fs::remove_all(temp, ec);
    throw;
  }
}

}  // namespace detail
}  // namespace confvis
