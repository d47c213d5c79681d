#pragma once
// Did a background re-bake hold a frame of `confvis view` up? Read from view.json's frame log.
// A frame that waited for the bake would last about as long as the bake itself; frames that
// merely share the machine's cores with it are slower, but each is a small part of it. On a
// loaded machine every frame is slow and some stall for a few hundred milliseconds (measured: a
// 406 ms frame among the 5 of an 873 ms bake, at load 18 on 2 cores, with calm frames of
// 8.5 ms p50 and 83 ms p99; under ctest -j2 a 352 ms frame during a 4.7 s bake whose calm
// frames never passed 58 ms), so the bounds are relative to the same run's frames, with room
// for the scheduler's stalls.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace confvis::testing {

struct BakeHoldup {
  int calmFrames = 0;            // frames without a bake in flight, nor swapping a map in
  double calmP50Ms = 0.0, calmP99Ms = 0.0, calmMaxMs = 0.0;
  int bakeStartedAt = -1, swappedAt = -1;  // frames; -1: none
  int bakingFrames = 0;          // from the one that started the bake to the one that swapped
  double bakeMs = 0.0;           // those frames' times together: the bake's wall time, at least
  double worstBakingMs = 0.0;    // the slowest of them
};

// Frame 0 (which creates the swapchains) is left out of every figure. Only the first re-bake
// is looked at.
inline BakeHoldup measureBakeHoldup(const nlohmann::json& frames) {
  BakeHoldup m;
  std::vector<double> calm;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const nlohmann::json& f = frames[i];
    const double ms = f["ms"].get<double>();
    const bool swapped = f["map_swapped"].get<bool>();
    if (m.bakeStartedAt < 0 && f["bake_started"].get<bool>()) m.bakeStartedAt = static_cast<int>(i);
    const bool inBake = m.bakeStartedAt >= 0 && m.swappedAt < 0;
    if (inBake) {
      ++m.bakingFrames;
      m.bakeMs += ms;
      m.worstBakingMs = std::max(m.worstBakingMs, ms);
    } else if (!f["bake_in_flight"].get<bool>()) {
      calm.push_back(ms);
    }
    if (inBake && swapped) m.swappedAt = static_cast<int>(i);
  }
  m.calmFrames = static_cast<int>(calm.size());
  if (!calm.empty()) {
    std::sort(calm.begin(), calm.end());
    m.calmP50Ms = calm[calm.size() / 2];
    m.calmP99Ms = calm[static_cast<std::size_t>(std::ceil(0.99 * calm.size())) - 1];
    m.calmMaxMs = calm.back();
  }
  return m;
}

// What is wrong with a run (empty: nothing): no frame from the bake's start to its swap may take
// 3/4 of that span (a frame that waited for the bake would take nearly all of it, however loaded
// the machine), nor be slower than both 10 x the calm frames' p99 + 400 ms and 1.5 x the slowest
// calm frame (generous: the bake competes for the cores, and a loaded machine stalls frames with
// or without it).
inline std::vector<std::string> bakeHoldupProblems(const BakeHoldup& m, int minimumCalmFrames) {
  std::vector<std::string> problems;
  if (m.bakeStartedAt < 0) problems.push_back("no re-bake started");
  if (m.swappedAt < 0) problems.push_back("no re-bake swapped its map in");
  if (m.calmFrames < minimumCalmFrames)
    problems.push_back(std::to_string(m.calmFrames) + " frames without a bake, fewer than " +
                       std::to_string(minimumCalmFrames));
  if (!problems.empty()) return problems;
  if (m.worstBakingMs >= 0.75 * m.bakeMs)
    problems.push_back("a frame during the bake took " + std::to_string(m.worstBakingMs) +
                       " ms of the bake's " + std::to_string(m.bakeMs) + " ms");
  if (m.worstBakingMs > std::max(10.0 * m.calmP99Ms + 400.0, 1.5 * m.calmMaxMs))
    problems.push_back("a frame during the bake took " + std::to_string(m.worstBakingMs) +
                       " ms, beyond 10 x the calm frames' p99 of " + std::to_string(m.calmP99Ms) +
                       " ms + 400 ms and 1.5 x their slowest, " + std::to_string(m.calmMaxMs) +
                       " ms");
  return problems;
}

}  // namespace confvis::testing
