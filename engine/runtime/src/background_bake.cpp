#include "confvis/runtime/background_bake.hpp"

#include <algorithm>
#include <string>
#include <thread>

#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_display.hpp"

namespace confvis {

int defaultBackgroundBakeThreads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / 2);
}

BakeFunction backgroundBake(int threads) {
  if (threads < 0)
    throw Error(ErrorCode::InvalidInput,
                "backgroundBake: thread count " + std::to_string(threads) + " is negative");
  BakeDisplayOptions options;
  options.useCache = false;
  options.threads = threads > 0 ? threads : defaultBackgroundBakeThreads();
  return [options](const DisplayConfig& config, const glm::dvec3& /*reference*/) {
    return bakeDisplay(config, options).map;  // config's reference is already the head's
  };
}

}  // namespace confvis
