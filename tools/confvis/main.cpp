// confvis: conformal visualization for partially-immersive displays (command-line front end).
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cstdio>
#include <map>

#include "cluster_cli.hpp"
#include "command.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/version.hpp"

namespace confvis::cli {
std::vector<Command>& commandRegistry() {
  static std::vector<Command> registry;
  return registry;
}
}  // namespace confvis::cli

int main(int argc, char** argv) {
  using namespace confvis::cli;
  // OpenMesh logs every file it writes; our own messages name files and errors instead.
  omlog().disable();
  omout().disable();
  CLI::App app{
      "confvis: conformal retargeting of the full field of view onto CAVEs and display walls"};
  app.require_subcommand(1);
  app.set_version_flag("--version", confvis::versionString());
  auto& registry = commandRegistry();
  std::sort(registry.begin(), registry.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::map<CLI::App*, std::function<int()>> actions;
  for (const Command& command : registry) {
    CLI::App* sub = app.add_subcommand(command.name, command.description);
    actions[sub] = command.setup(*sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (auto& [sub, action] : actions) {
    if (!sub->parsed()) continue;
    try {
      return action();
    } catch (const confvis::Error& e) {
      std::fprintf(stderr, "confvis %s: error: %s\n", sub->get_name().c_str(), e.what());
      lingerAfterClusterError();
      return 2;
    } catch (const std::exception& e) {
      // Every reader turns bad input into confvis::Error naming the file; reaching this is a bug.
      std::fprintf(stderr, "confvis %s: unexpected error: %s\n", sub->get_name().c_str(),
                   e.what());
      return 3;
    } catch (...) {
      std::fprintf(stderr, "confvis %s: unexpected error (not a std::exception)\n",
                   sub->get_name().c_str());
      return 3;
    }
  }
  return 1;
}
