#pragma once
// Shared by the harnesses: readers that take a path get the input as a file (in /dev/shm when
// there is one, so the disk is not worn), and only confvis::Error counts as a clean refusal;
// any other exception escapes and libFuzzer reports it as a finding.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

// The readers' warnings about accepted input (a missing MTL, flat normals) go to std::cerr, once
// per execution: at a million executions that is gigabytes of log and most of the time. Dropped
// here; sanitizer and libFuzzer reports are written to file descriptor 2 directly, so they stay.
// Not inline (an unused inline function is never emitted): each harness is one file.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::cerr.rdbuf(nullptr);
  return 0;
}

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
