#pragma once
// Cache entries of bakeDisplay (see bake_display.hpp for the layout and the key).
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "confvis/conformal/bake_files.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::detail {

// The entry's bake if it loads back and matches `config` (hash, resolution) and `mapSettings`
// (bake.json's "map_settings"). Otherwise removes
// whatever is there, says why in `note` (empty when there was simply no entry) and returns
// nullopt.
std::optional<LoadedBake> loadCacheEntry(const std::filesystem::path& entry,
                                         const DisplayConfig& config,
                                         const nlohmann::json& mapSettings, std::string& note);

// Writes the bake directory into a temporary folder beside `entry` and renames it into place.
// If another process published the same entry first, keeps theirs. Returns the sidecar written.
nlohmann::json publishCacheEntry(const std::filesystem::path& entry, const DisplayMap& displayMap,
                                 const RetargetMap& map, const nlohmann::json& sidecar, int threads,
                                 bool showProgress);

}  // namespace confvis::detail
