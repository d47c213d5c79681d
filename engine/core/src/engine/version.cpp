#include "confvis/engine/version.hpp"

namespace confvis {
const char* versionString() noexcept { return "0.1.0"; }
}  // namespace confvis
