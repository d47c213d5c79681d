#pragma once
// The steady clock the bake's stage timings (bake.json's "timings", DisplayMap::stats) are read
// from, and the seconds since a stage began.
#include <chrono>

namespace confvis::detail {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace confvis::detail
