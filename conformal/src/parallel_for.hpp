#pragma once
// A minimal parallel loop over independent tasks for the bake (std::thread, no pool): tasks are
// handed out through an atomic counter, so uneven tasks (cube faces with more or fewer
// triangles) balance themselves. The first exception thrown by a task is rethrown.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace confvis::detail {

// 0 means one thread per hardware thread.
inline int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

template <class Task>
void parallelFor(std::size_t taskCount, int threads, Task&& task) {
  const int workers =
      static_cast<int>(std::min<std::size_t>(taskCount, resolveThreadCount(threads)));
  if (workers <= 1) {
    for (std::size_t i = 0; i < taskCount; ++i) task(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < taskCount;) {
      try {
        task(i);
      } catch (...) {
        std::lock_guard lock(failureMutex);
        if (!failure) failure = std::current_exception();
        next = taskCount;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace confvis::detail
