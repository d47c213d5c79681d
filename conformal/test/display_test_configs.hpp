#pragma once
// Displays for the template and display-map tests: the shipped configs and small hand-made ones
// (walls from corners, with or without bezels).
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "confvis/engine/display_config.hpp"

namespace confvis::testing {

inline DisplayConfig shipped(const std::string& name) {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" /
                           (name + ".json"));
}

inline Wall makeWall(const std::string& name, glm::dvec3 lowerLeft, glm::dvec3 lowerRight,
                     glm::dvec3 upperLeft, Bezel bezel = {}) {
  Wall w;
  w.name = name;
  w.lowerLeft = lowerLeft;
  w.lowerRight = lowerRight;
  w.upperLeft = upperLeft;
  w.width = 100;
  w.height = 100;
  w.bezel = bezel;
  return w;
}

inline DisplayConfig makeDisplay(const std::string& name, std::vector<Wall> walls,
                                 SourceField source = SourceField::FullSphere) {
  DisplayConfig config;
  config.name = name;
  config.walls = std::move(walls);
  config.source = source;
  return config;
}

// The front half of a box room around the origin, half-sizes (hx, hy) and depth d: the front
// wall and the front halves of the side walls, floor and ceiling, whose back edges lie in the
// plane z = 0 through the reference. It covers exactly the front hemisphere of directions.
inline DisplayConfig frontHemisphereDisplay(double hx = 1.5, double hy = 1.0, double d = 1.2) {
  return makeDisplay("front-hemisphere",
                     {makeWall("front", {-hx, -hy, -d}, {hx, -hy, -d}, {-hx, hy, -d}),
                      makeWall("left", {-hx, -hy, 0}, {-hx, -hy, -d}, {-hx, hy, 0}),
                      makeWall("right", {hx, -hy, -d}, {hx, -hy, 0}, {hx, hy, -d}),
                      makeWall("floor", {-hx, -hy, 0}, {hx, -hy, 0}, {-hx, -hy, -d}),
                      makeWall("ceiling", {-hx, hy, -d}, {hx, hy, -d}, {-hx, hy, 0})},
                     SourceField::Hemisphere);
}

}  // namespace confvis::testing
