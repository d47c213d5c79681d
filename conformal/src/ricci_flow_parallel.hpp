#pragma once
// Internal: splitting the flow's per-edge and per-face loops across the machine's cores. Small
// loops stay on the calling thread: starting a thread costs tens of microseconds, about what
// 20k faces of metric evaluation take on one core.
#include <algorithm>
#include <thread>
#include <vector>

namespace confvis::conformal::detail {

inline int workerCount() {
  static const int count =
      std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
  return count;
}

// body(begin, end, part) over [0, n) in contiguous parts, part 0 on the calling thread.
// Returns the number of parts used.
template <typename Body>
int parallelFor(int n, Body&& body, int grain = 20000) {
  const int parts = std::clamp(n / grain, 1, workerCount());
  if (parts == 1) {
    body(0, n, 0);
    return 1;
  }
  std::vector<std::thread> workers;
  workers.reserve(parts - 1);
  for (int p = 1; p < parts; ++p)
    workers.emplace_back([&body, n, parts, p] {
      body(static_cast<int>(static_cast<long long>(n) * p / parts),
           static_cast<int>(static_cast<long long>(n) * (p + 1) / parts), p);
    });
  body(0, static_cast<int>(static_cast<long long>(n) / parts), 0);
  for (auto& w : workers) w.join();
  return parts;
}

}  // namespace confvis::conformal::detail
