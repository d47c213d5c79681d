#pragma once
// --preset fast|accurate (bake_preset.hpp), shared by bake, render, view and walk, and
// --interpolation linear|mobius (bake, render).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "confvis/conformal/bake_preset.hpp"

namespace confvis::cli {

// Adds --preset to `sub`, storing the name in `name` (preset `fallback` when not given).
inline void addPresetOption(CLI::App& sub, std::string& name, BakePreset fallback) {
  name = toString(fallback);
  sub.add_option("--preset", name,
                 "Map accuracy against bake time: fast (the config's edge_length, uniform mesh, "
                 "linear interpolation: re-bakes within a frame budget) or accurate (half the "
                 "edges, graded toward the display's corners, Möbius blending: ~0.4 px p99 and "
                 "smooth lines on cave5, ~13x the bake time); see conformal/README.md")
      ->check(CLI::IsMember({"fast", "accurate"}))
      ->capture_default_str();
}

// Adds --interpolation to `sub`, storing the name in `name` (empty: the preset's).
inline void addInterpolationOption(CLI::App& sub, std::string& name) {
  sub.add_option("--interpolation", name,
                 "Between the map's mesh vertices: linear or mobius (per-vertex Möbius blending: "
                 "smooth lines, ~2x the bake time); default: the preset's (fast: linear, "
                 "accurate: mobius)")
      ->check(CLI::IsMember({"linear", "mobius"}));
}

// The --interpolation override, if one was given.
inline std::optional<MapInterpolation> interpolationOverride(const std::string& name) {
  if (name.empty()) return std::nullopt;
  return parseMapInterpolation(name);
}

}  // namespace confvis::cli
