#pragma once
// Helpers shared by the image, EXR, PNG and cube-map tests.
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

#include "confvis/base/vec3.hpp"

namespace confvis::test {

// An empty directory unique to this test process; callers remove it when done.
inline std::filesystem::path freshTestDir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("confvis_" + name + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline int countEntries(const std::filesystem::path& dir) {
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  return entries;
}

// Uniformly distributed unit vector.
inline Vec3d randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Vec3d d{normal(rng), normal(rng), normal(rng)};
  while (norm(d) < 1e-6) d = {normal(rng), normal(rng), normal(rng)};
  return normalized(d);
}

}  // namespace confvis::test
