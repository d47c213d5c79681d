// A bake run through inBackground lowers the priority of the thread it runs on, and of that
// thread alone: the renderer's thread keeps its own.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <thread>

#include "confvis/runtime/background_priority.hpp"

using namespace confvis;

namespace {
int threadNice() {
  errno = 0;
  return ::getpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)));
}
}  // namespace

TEST(BackgroundPriority, TheBakeThreadAloneRunsNicer) {
  const int callerBefore = threadNice();
  int seenInBake = -100, seenInBakeWorker = -100;
  const BakeFunction bake = inBackground(
      [&](const DisplayConfig&, const glm::dvec3& reference) {
        seenInBake = threadNice();
        std::thread worker([&] { seenInBakeWorker = threadNice(); });  // the bake's own workers
        worker.join();
        return RetargetMap::identity(8, Vec3d{reference.x, reference.y, reference.z});
      },
      10);
  std::thread bakeThread([&] { (void)bake(DisplayConfig{}, glm::dvec3(0.0)); });
  bakeThread.join();
  EXPECT_GE(seenInBake, 10);
  EXPECT_EQ(seenInBakeWorker, seenInBake);
  EXPECT_EQ(threadNice(), callerBefore) << "the calling thread keeps its priority";
}
