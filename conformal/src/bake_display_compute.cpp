// bakeDisplay with confvis's own templates (computeDisplayMap). Kept apart from
// bakeDisplayWith so that programs using only the latter do not link the template code.
#include "confvis/conformal/bake_display.hpp"

namespace confvis {

BakedDisplay bakeDisplay(const DisplayConfig& config, const BakeDisplayOptions& options) {
  return bakeDisplayWith(config, options, [&](const DisplayConfig& effective) {
    DisplayMapOptions mapOptions;
    mapOptions.showProgress = options.showProgress;
    return computeDisplayMap(effective, mapOptions);
  });
}

}  // namespace confvis
