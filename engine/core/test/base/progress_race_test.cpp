// Progress::advance() from several workers at once (the bake's files, its cube-face bands): the
// redraw throttle's last-draw time was read without the lock while the drawing worker wrote it
// under the lock, a data race ThreadSanitizer reported (tools/sanitizers/tsan.sh runs this
// suite). The count and the 25 % lines must also come out whole.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "confvis/base/progress.hpp"

namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(ProgressRace, WorkersAdvancingTogetherWhileOneRedrawsPrintEachQuarterOnce) {
  constexpr int kWorkers = 4, kStepsEach = 400;
  testing::internal::CaptureStderr();  // not a terminal: one line per 25 %
  {
    confvis::Progress progress("race", kWorkers * kStepsEach, true);
    std::vector<std::thread> workers;
    // ~0.4 s in all: redraws (every 100 ms) happen while the other workers advance.
    for (int w = 0; w < kWorkers; ++w)
      workers.emplace_back([&] {
        for (int i = 0; i < kStepsEach; ++i) {
          progress.advance();
          std::this_thread::sleep_for(std::chrono::microseconds(1000));
        }
      });
    for (std::thread& t : workers) t.join();
    progress.finish();
  }
  const std::string output = testing::internal::GetCapturedStderr();
  EXPECT_EQ(occurrences(output, "race: 100%"), 1u) << output;
  EXPECT_LE(occurrences(output, "race: "), 4u) << output;  // 25, 50, 75, 100 % at most
}
