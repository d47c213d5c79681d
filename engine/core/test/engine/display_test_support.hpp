#pragma once
// Shared by the display-config and view tests: the shipped configs and vector comparisons.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "confvis/base/atomic_file.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::testing {

inline std::filesystem::path configDir() {
  return std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs";
}

inline DisplayConfig shippedConfig(const std::string& fileName) {
  return loadDisplayConfig(configDir() / fileName);
}

inline nlohmann::json shippedConfigJson(const std::string& fileName) {
  return nlohmann::json::parse(readTextFile(configDir() / fileName));
}

inline ::testing::AssertionResult vecNear(const glm::dvec3& actual, const glm::dvec3& expected,
                                          double tolerance = 1e-12) {
  if (glm::length(actual - expected) <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") != (" << expected.x
         << ", " << expected.y << ", " << expected.z << ")";
}

}  // namespace confvis::testing
