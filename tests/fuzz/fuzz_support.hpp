#pragma once
// Shared by the harnesses: readers that take a path get the input as a file (in /dev/shm when
// there is one, so the disk is not worn), and only confvis::Error counts as a clean refusal;
// any other exception escapes and libFuzzer reports it as a finding.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace confvis::fuzz {

inline std::filesystem::path scratchFile(const std::string& name) {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    const auto d = base / ("confvis-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir / name;
}

inline std::filesystem::path writeInput(const std::string& name, const std::uint8_t* data,
                                        std::size_t size) {
  const std::filesystem::path file = scratchFile(name);
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data),
                                              static_cast<std::streamsize>(size));
  return file;
}

}  // namespace confvis::fuzz
