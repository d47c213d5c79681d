#pragma once

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
// The library version, also reported by `confvis --version` and in every JSON report.
const char* versionString() noexcept;
}  // namespace confvis
