// Display map benchmark (run by hand, never in CI): computeDisplayMap for a config at several
// edge lengths (default: configs/cave5.json at 20, 10 and 5 cm), split into the template, flow
// and alignment stages, best of N repetitions. Usage:
//   confvis_bench_display_map [CONFIG] [--edges 0.2,0.1,0.05] [--reference x,y,z] [--repeat N]
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/display_config.hpp"

using namespace confvis;

namespace {

std::vector<double> parseList(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(std::stod(item));
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string path = std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json";
    std::vector<double> edges{0.2, 0.1, 0.05};
    std::vector<double> reference;
    int repeat = 5;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--edges" && i + 1 < argc)
        edges = parseList(argv[++i]);
      else if (arg == "--reference" && i + 1 < argc)
        reference = parseList(argv[++i]);
      else if (arg == "--repeat" && i + 1 < argc)
        repeat = std::max(1, std::stoi(argv[++i]));
      else if (arg == "--help") {
        std::printf("usage: %s [CONFIG] [--edges 0.2,0.1,0.05] [--reference x,y,z] [--repeat N]\n",
                    argv[0]);
        return 0;
      } else
        path = arg;
    }
    DisplayConfig config = loadDisplayConfig(path);
    if (reference.size() == 3) config.reference = {reference[0], reference[1], reference[2]};
    std::printf("config %s, reference (%g, %g, %g), best of %d\n\n", config.name.c_str(),
                config.reference.x, config.reference.y, config.reference.z, repeat);
    std::printf(
        "| edge m | source V | target V | template ms | flow ms | alignment ms | total ms | "
        "flow iterations S/T | flips S/T |\n|---|---|---|---|---|---|---|---|---|\n");
    for (double edge : edges) {
      DisplayMapOptions options;
      options.edgeLength = edge;
      double best = 1e30;
      nlohmann::json bestStats;
      for (int r = 0; r < repeat; ++r) {
        const DisplayMap map = computeDisplayMap(config, options);
        const double total = map.stats["template"].get<double>() + map.stats["flow"].get<double>() +
                             map.stats["alignment"].get<double>();
        if (total < best) best = total, bestStats = map.stats;
      }
      const auto& s = bestStats;
      std::printf("| %.3f | %d | %d | %.2f | %.2f | %.2f | %.2f | %d/%d | %s/%s |\n", edge,
                  s["source"]["vertices"].get<int>(), s["target"]["vertices"].get<int>(),
                  1e3 * s["template"].get<double>(), 1e3 * s["flow"].get<double>(),
                  1e3 * s["alignment"].get<double>(), 1e3 * best,
                  s["source"]["flow_iterations"].get<int>(),
                  s["target"]["flow_iterations"].get<int>(),
                  s["source"]["used_flips"].get<bool>() ? "yes" : "no",
                  s["target"]["used_flips"].get<bool>() ? "yes" : "no");
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
