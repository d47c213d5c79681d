// The check CliView.ReBakeInTheBackgroundHoldsNoFrameUp applies to view.json's frame log, on
// made-up logs: it passes frames that share the machine with a bake (on a quiet machine and on
// a loaded one, where every frame is slow and some stall: logs like those measured at load 18),
// and fails a render that waited for the bake, at its start or at its swap, whatever the load.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake_holdup.hpp"

namespace {

using confvis::testing::bakeHoldupProblems;
using confvis::testing::measureBakeHoldup;

struct Log {
  nlohmann::json frames = nlohmann::json::array();
  void add(double ms, bool inFlight = false, bool started = false, bool swapped = false) {
    frames.push_back({{"frame", frames.size()}, {"ms", ms}, {"bake_in_flight", inFlight},
                      {"bake_started", started}, {"map_swapped", swapped}});
  }
  // `count` frames of `ms`, every `stallEvery`th one `stallMs` instead (0: none).
  void calm(int count, double ms, int stallEvery = 0, double stallMs = 0.0) {
    for (int i = 0; i < count; ++i) add(stallEvery && i % stallEvery == 0 ? stallMs : ms);
  }
};

// A bake of `bakeMs` with frames of `ms` going on meanwhile, then its swap frame of `swapMs`.
void bakeWhileFramesGoOn(Log& log, double bakeMs, double ms, double swapMs) {
  log.add(ms, true, true);
  for (double t = ms; t < bakeMs; t += ms) log.add(ms, true);
  log.add(swapMs, false, false, true);
}

TEST(BakeHoldupCheck, FramesSharingTheMachineWithTheBakePass) {
  Log quiet;
  quiet.add(300.0);  // frame 0: swapchains made; left out
  quiet.calm(30, 4.0);
  bakeWhileFramesGoOn(quiet, 400.0, 7.0, 15.0);
  quiet.calm(150, 4.0);
  const auto m = measureBakeHoldup(quiet.frames);
  EXPECT_EQ(m.calmFrames, 180);
  EXPECT_EQ(m.bakeStartedAt, 31);
  EXPECT_GT(m.bakingFrames, 50);
  EXPECT_TRUE(bakeHoldupProblems(m, 100).empty()) << bakeHoldupProblems(m, 100).front();

  // Loaded: every frame 10 times slower, a few stalls of 150 ms on both sides, a slow bake.
  Log loaded;
  loaded.add(3000.0);
  loaded.calm(20, 40.0, 7, 150.0);
  loaded.add(40.0, true, true);
  for (int i = 0; i < 120; ++i) loaded.add(i % 9 == 0 ? 150.0 : 60.0, true);
  loaded.add(200.0, false, false, true);
  loaded.calm(150, 40.0, 11, 150.0);
  const auto l = measureBakeHoldup(loaded.frames);
  EXPECT_TRUE(bakeHoldupProblems(l, 100).empty()) << bakeHoldupProblems(l, 100).front();

  // As measured at load 18: a quick bake over few slow frames, one of them a 406 ms stall.
  Log few;
  few.add(2000.0);
  few.calm(100, 8.0, 50, 90.0);
  few.add(61.0, true, true);
  few.add(406.0, true);
  few.add(249.0, true);
  few.add(111.0, true);
  few.add(45.0, false, false, true);
  few.calm(200, 8.0, 60, 90.0);
  const auto f = measureBakeHoldup(few.frames);
  EXPECT_TRUE(bakeHoldupProblems(f, 100).empty()) << bakeHoldupProblems(f, 100).front();

  // As measured at load 19: quick calm frames (p99 2.7 ms) with rare stalls, one 128 ms frame
  // during the bake.
  Log spiky;
  spiky.add(2000.0);
  spiky.calm(500, 2.0, 250, 150.0);
  spiky.add(9.6, true, true);
  spiky.add(128.0, true);
  for (int i = 0; i < 80; ++i) spiky.add(8.5, true);
  spiky.add(12.0, false, false, true);
  spiky.calm(700, 2.0, 350, 150.0);
  const auto s = measureBakeHoldup(spiky.frames);
  EXPECT_LT(s.calmP99Ms, 3.0);
  EXPECT_TRUE(bakeHoldupProblems(s, 100).empty()) << bakeHoldupProblems(s, 100).front();

  // As measured under ctest -j2: calm frames never past 58 ms, one of 135 frames during a 4.7 s
  // bake 352 ms.
  Log stalled;
  stalled.add(2000.0);
  stalled.calm(400, 2.0, 100, 58.0);
  stalled.add(10.0, true, true);
  for (int i = 0; i < 133; ++i) stalled.add(i == 70 ? 352.0 : i % 10 == 0 ? 110.0 : 30.0, true);
  stalled.add(12.0, false, false, true);
  stalled.calm(400, 2.0, 100, 58.0);
  const auto t = measureBakeHoldup(stalled.frames);
  EXPECT_TRUE(bakeHoldupProblems(t, 100).empty()) << bakeHoldupProblems(t, 100).front();
}

TEST(BakeHoldupCheck, ARenderThatWaitedForTheBakeFails) {
  for (const double scale : {1.0, 10.0}) {  // quiet machine, loaded machine
    SCOPED_TRACE(scale);
    // Waits in the frame that started the bake.
    Log atStart;
    atStart.add(300.0);
    atStart.calm(30, 4.0 * scale);
    atStart.add(400.0 * scale, true, true);
    atStart.add(15.0 * scale, false, false, true);
    atStart.calm(150, 4.0 * scale);
    EXPECT_FALSE(bakeHoldupProblems(measureBakeHoldup(atStart.frames), 100).empty());
    // Starts it, then waits for it in the next frame, which swaps its map in.
    Log atSwap;
    atSwap.add(300.0);
    atSwap.calm(30, 4.0 * scale);
    atSwap.add(4.0 * scale, true, true);
    atSwap.add(400.0 * scale, false, false, true);
    atSwap.calm(150, 4.0 * scale);
    EXPECT_FALSE(bakeHoldupProblems(measureBakeHoldup(atSwap.frames), 100).empty());
  }
}

TEST(BakeHoldupCheck, TooFewCalmFramesOrNoBakeIsAProblemNotAPass) {
  Log few;
  few.add(300.0);
  few.calm(10, 4.0);
  bakeWhileFramesGoOn(few, 400.0, 7.0, 15.0);
  few.calm(20, 4.0);
  EXPECT_EQ(bakeHoldupProblems(measureBakeHoldup(few.frames), 100).size(), 1u);
  Log none;
  none.calm(200, 4.0);
  EXPECT_EQ(bakeHoldupProblems(measureBakeHoldup(none.frames), 100).size(), 2u);
}

}  // namespace
