#include "confvis/base/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace confvis {

Progress::Progress(std::string label, std::size_t total, bool enabled)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      enabled_(enabled),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::advance(std::size_t steps) {
  const std::size_t done = done_.fetch_add(steps) + steps;
  if (!enabled_) return;
  const auto now = (std::chrono::steady_clock::now() - start_).count();
  // Redraw at most ~10 times a second; never block a worker on the lock.
  constexpr auto kRedrawTicks =
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::milliseconds(100))
          .count();
  if (now - lastDraw_.load(std::memory_order_relaxed) < kRedrawTicks && done < total_) return;
  std::unique_lock lock(drawMutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  lastDraw_.store(now, std::memory_order_relaxed);
  draw(done, false);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  std::lock_guard lock(drawMutex_);
  draw(total_, true);
}

void Progress::draw(std::size_t done, bool final) {
  if (done > total_) done = total_;
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (tty_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    std::fprintf(stderr, "\r%-18s [%.*s%*s] %5.1f%%  %6.1fs", label_.c_str(), filled,
                 "##############################", width - filled, "", 100.0 * fraction, seconds);
    if (final) std::fputc('\n', stderr);
  } else {
    // Without a terminal print one line per 25 %, so CI logs stay short.
    const int percent = static_cast<int>(fraction * 100.0);
    // 100 % once: the last advance() may already have printed it before finish().
    if ((final && lastPercentPrinted_ < 100) || percent / 25 > lastPercentPrinted_ / 25) {
      lastPercentPrinted_ = percent;
      std::fprintf(stderr, "%s: %d%% (%.1fs)\n", label_.c_str(), percent, seconds);
    }
  }
  std::fflush(stderr);
}

}  // namespace confvis
