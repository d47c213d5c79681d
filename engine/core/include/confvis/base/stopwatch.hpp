#pragma once
// Seconds elapsed on the steady clock: the one way confvis times its stages (bake.json's
// "timings", progress lines, render statistics, benchmarks), so none keeps its own copy.
#include <chrono>

namespace confvis {

using SteadyClock = std::chrono::steady_clock;

inline double secondsSince(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace confvis
