#pragma once
// Runs the confvis binary for the end-to-end CLI tests.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace confvis::testing {

struct CliRun {
  int exitCode;
  std::string output;  // stdout and stderr together
};

// `environment`: assignments put before the command ("NAME=value ...").
inline CliRun runCli(const std::string& args, const std::string& environment = "") {
  const std::string command =
      environment + " " + std::string(CONFVIS_CLI_PATH) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer;
  while (pipe && fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("confvis_cli_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

}  // namespace confvis::testing
