#pragma once
// Where `confvis render` gets the conformal map of a display from.
#include <optional>
#include <string>

#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::cli {

struct MapSource {
  RetargetMap map;
  std::string origin;  // for the report: "identity (display covers the whole sphere)" or a path
};

// In order: --map DIR (a baked directory with ray.exr and geom.exr); the identity for a display
// that covers the whole sphere; otherwise Error(InvalidInput) asking for a bake.
MapSource retargetMapFor(const DisplayConfig& config, const std::string& mapDirectory);

}  // namespace confvis::cli
