#pragma once
// --preset fast|accurate (bake_preset.hpp), shared by bake, render, view and walk.
#include <CLI/CLI.hpp>

#include <string>

#include "confvis/conformal/bake_preset.hpp"

namespace confvis::cli {

// Adds --preset to `sub`, storing the name in `name` (preset `fallback` when not given).
inline void addPresetOption(CLI::App& sub, std::string& name, BakePreset fallback) {
  name = toString(fallback);
  sub.add_option("--preset", name,
                 "Map accuracy against bake time: fast (the config's edge_length, uniform mesh: "
                 "re-bakes within a frame budget) or accurate (half the edges, graded toward the "
                 "display's corners: ~0.9 px p99 on cave5, ~7x the bake time); see "
                 "conformal/README.md")
      ->check(CLI::IsMember({"fast", "accurate"}))
      ->capture_default_str();
}

}  // namespace confvis::cli
