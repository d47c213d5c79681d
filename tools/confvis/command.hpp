#pragma once
// Subcommands register themselves (one .cpp per subcommand, compiled into the confvis binary),
// so adding a command never touches main.cpp.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace confvis::cli {

struct Command {
  std::string name;
  std::string description;
  // Adds options to `sub` and returns the action to run when the subcommand is chosen.
  std::function<std::function<int()>(CLI::App& sub)> setup;
};

std::vector<Command>& commandRegistry();

// A number > 0 (CLI::PositiveNumber's message prints the whole double range): "--scale: must
// be a number > 0, got 0".
inline const CLI::Validator kPositiveNumber(
    [](std::string& input) -> std::string {
      double value = 0.0;
      if (CLI::detail::lexical_cast(input, value) && value > 0.0) return {};
      return "must be a number > 0, got " + input;
    },
    "POSITIVE");

struct RegisterCommand {
  explicit RegisterCommand(Command command) { commandRegistry().push_back(std::move(command)); }
};

}  // namespace confvis::cli
