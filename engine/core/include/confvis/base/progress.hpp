#pragma once
// Progress for long-running commands: a redrawn bar on a terminal, occasional plain lines
// otherwise (CI logs), nothing when disabled. Thread-safe: workers may call advance().
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: advance() may be called from any number of threads at once (workers);
// construction, finish() and destruction from one thread.
class Progress {
 public:
  Progress(std::string label, std::size_t total, bool enabled = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::size_t steps = 1);
  void finish();

 private:
  void draw(std::size_t done, bool final);

  std::string label_;
  std::size_t total_;
  bool enabled_;
  bool tty_;
  std::atomic<std::size_t> done_{0};
  std::mutex drawMutex_;
  std::chrono::steady_clock::time_point start_;
  // Steady-clock ticks since start_ at the last redraw: every worker reads it outside the lock.
  std::atomic<std::chrono::steady_clock::rep> lastDraw_{0};
  int lastPercentPrinted_ = -1;
  bool finished_ = false;
};

}  // namespace confvis
