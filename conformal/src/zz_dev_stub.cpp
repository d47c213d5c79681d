// DEV ONLY, never committed: stands in for computeDisplayMap until the templates branch lands.
#include <numbers>
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "../test/bake_test_support.hpp"
namespace confvis {
DisplayMap computeDisplayMap(const DisplayConfig&, const DisplayMapOptions&) {
  DisplayMap m; m.source = test::makeCapMesh(37, 0.9*std::numbers::pi); m.target = test::makeCapMesh(37, 0.6*std::numbers::pi);
  m.stats = {{"template", 0.0}, {"flow", 0.0}, {"alignment", 0.0}};
  return m;
}
}
