#pragma once
namespace confvis {
// The library version, also reported by `confvis --version` and in every JSON report.
const char* versionString() noexcept;
}  // namespace confvis
