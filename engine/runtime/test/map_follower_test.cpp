// The map follower re-bakes in the background when the head strays, never makes a frame wait,
// swaps only at frame boundaries and survives failing bakes. Bakes are fakes returning identity
// maps; a slow one blocks on a gate the test opens, so "no frame waits" is shown by frames
// completing while the bake provably cannot finish, not by timing.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <stdexcept>

#include "../../core/test/engine/display_test_support.hpp"
#include "confvis/runtime/map_follower.hpp"
#include "confvis/base/error.hpp"

using namespace confvis;
using confvis::testing::shippedConfig;
using confvis::testing::vecNear;
using namespace std::chrono_literals;

namespace {

// Long enough never to trip on a loaded machine; only a deadlock (a frame waiting for the
// blocked bake) would reach it.
constexpr auto kDeadlockGuard = 120s;
constexpr int kResolution = 8;

RetargetMap identityAt(const glm::dvec3& c) {
  return RetargetMap::identity(kResolution, Vec3d{c.x, c.y, c.z});
}

HeadPose at(double x, double y = 0, double z = 0) { return HeadPose{{x, y, z}}; }

// A bake that records its calls, optionally throws, and can be held until the test opens it.
class FakeBaker {
 public:
  explicit FakeBaker(bool gated = false) : state_(std::make_shared<State>()) {
    if (!gated) open();
  }

  BakeFunction function() const {
    return [s = state_](const DisplayConfig& config, const glm::dvec3& reference) {
      {
        const std::lock_guard lock(s->mutex);
        s->references.push_back(reference);
        s->configReferences.push_back(config.reference);
      }
      if (s->calls.fetch_add(1) == 0) s->entered.set_value();
      s->gate.wait();
      if (s->failuresLeft.fetch_sub(1) > 0) throw std::runtime_error("flow diverged (fake)");
      if (s->ignoreReference) return identityAt({0, 0, 0});
      return identityAt(reference);
    };
  }

  void open() { std::call_once(state_->opened, [&] { state_->open.set_value(); }); }
  bool waitUntilEntered() const { return state_->enteredFuture.wait_for(kDeadlockGuard) == std::future_status::ready; }
  int calls() const { return state_->calls.load(); }
  void failNext(int n) { state_->failuresLeft = n; }
  void ignoreReference() { state_->ignoreReference = true; }
  std::vector<glm::dvec3> references() const {
    const std::lock_guard lock(state_->mutex);
    return state_->references;
  }
  std::vector<glm::dvec3> configReferences() const {
    const std::lock_guard lock(state_->mutex);
    return state_->configReferences;
  }

 private:
  struct State {
    std::mutex mutex;
    std::vector<glm::dvec3> references, configReferences;
    std::atomic<int> calls{0}, failuresLeft{0};
    std::atomic<bool> ignoreReference{false};
    std::promise<void> open, entered;
    std::shared_future<void> gate = open.get_future().share();
    std::future<void> enteredFuture = entered.get_future();
    std::once_flag opened;
  };
  std::shared_ptr<State> state_;
};

// Opens the gate when the test leaves, before the follower (declared earlier) joins its bake.
struct OpenOnExit {
  FakeBaker& baker;
  ~OpenOnExit() { baker.open(); }
};

// A usable frame: a map around `reference` that maps directions to themselves (identity).
void expectValidFrame(const FollowerFrame& frame, const glm::dvec3& reference) {
  ASSERT_TRUE(frame.map);
  EXPECT_EQ(frame.map->resolution(), kResolution);
  EXPECT_TRUE(vecNear({frame.map->reference.x, frame.map->reference.y, frame.map->reference.z},
                      reference));
  const Vec3d d = normalized(Vec3d{0.3, -0.2, -1.0});
  const std::optional<Vec3d> v = frame.map->toVirtual(d);
  ASSERT_TRUE(v);
  EXPECT_LT(norm(*v - d), 0.02);  // bilinear between 8x8 texel directions
}

MapFollowerOptions radius(double r) {
  MapFollowerOptions options;
  options.radius = r;
  return options;
}

}  // namespace

TEST(MapFollower, FirstMapIsBakedAroundTheConfiguredReference) {
  FakeBaker baker;
  MapFollower follower(shippedConfig("cave5.json"), baker.function());
  EXPECT_EQ(baker.calls(), 1);
  const FollowerFrame frame = follower.beginFrame(at(0));
  expectValidFrame(frame, {0, 0, 0});
  EXPECT_EQ(frame.generation, 0u);
  EXPECT_FALSE(frame.baking);
}

TEST(MapFollower, HeadInsideTheRadiusNeverRebakes) {
  FakeBaker baker;
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function(),
                       radius(0.1));
  const auto first = follower.beginFrame(at(0)).map;
  for (int i = 0; i < 50; ++i) {
    const FollowerFrame frame = follower.beginFrame(at(0.099 * std::sin(i), 0.0, 0.05 * std::cos(i)));
    EXPECT_EQ(frame.map, first);
    EXPECT_FALSE(frame.baking);
  }
  EXPECT_EQ(baker.calls(), 0);
  EXPECT_EQ(follower.stats().bakesStarted, 0);
}

TEST(MapFollower, StrayingHeadTriggersOneBackgroundBakeWhileFramesGoOnAndSwapsAtAFrameBoundary) {
  FakeBaker baker(/*gated=*/true);
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function(),
                       radius(0.1));
  OpenOnExit openOnExit{baker};

  const FollowerFrame before = follower.beginFrame(at(0.05));
  expectValidFrame(before, {0, 0, 0});
  EXPECT_FALSE(before.baking);

  // The head steps 30 cm to the right: a bake starts on another thread...
  const FollowerFrame trigger = follower.beginFrame(at(0.3));
  EXPECT_TRUE(trigger.baking);
  EXPECT_EQ(trigger.map, before.map);
  ASSERT_TRUE(baker.waitUntilEntered()) << "the bake never started";

  // ...and while it cannot finish, frames keep coming with the old map (a frame waiting for the
  // bake would hang here until the guard gives up).
  auto during = std::async(std::launch::async, [&] {
    std::vector<FollowerFrame> frames;
    for (int i = 0; i < 100; ++i) frames.push_back(follower.beginFrame(at(0.3 + 0.04 * std::sin(i))));
    return frames;
  });
  if (during.wait_for(kDeadlockGuard) != std::future_status::ready) {
    baker.open();
    FAIL() << "beginFrame waited for the bake";
  }
  for (const FollowerFrame& frame : during.get()) {
    expectValidFrame(frame, {0, 0, 0});
    EXPECT_TRUE(frame.baking);
    EXPECT_EQ(frame.generation, 0u);
    EXPECT_FALSE(frame.swapped);
  }
  EXPECT_EQ(baker.calls(), 1);  // one bake in flight at a time

  // A frame in progress keeps its map even when the bake finishes under it.
  const FollowerFrame inProgress = follower.beginFrame(at(0.3));
  baker.open();
  follower.waitForBake();
  expectValidFrame(inProgress, {0, 0, 0});

  // The next frame boundary swaps the new map in, around where the bake was asked.
  const FollowerFrame after = follower.beginFrame(at(0.3));
  expectValidFrame(after, {0.3, 0, 0});
  EXPECT_TRUE(after.swapped);
  EXPECT_EQ(after.generation, 1u);
  EXPECT_FALSE(after.baking);
  EXPECT_TRUE(vecNear(follower.reference(), {0.3, 0, 0}));
  expectValidFrame(inProgress, {0, 0, 0});  // the old frame's map is still alive and intact

  // Staying near the new reference: exactly one re-bake in all.
  for (int i = 0; i < 20; ++i) {
    const FollowerFrame frame = follower.beginFrame(at(0.3 + 0.05 * std::sin(i)));
    EXPECT_EQ(frame.map, after.map);
    EXPECT_FALSE(frame.swapped);
  }
  EXPECT_EQ(baker.calls(), 1);
  const MapFollowerStats stats = follower.stats();
  EXPECT_EQ(stats.bakesStarted, 1);
  EXPECT_EQ(stats.bakesSucceeded, 1);
  EXPECT_EQ(stats.bakesFailed, 0);
  // The bake saw the display with its reference moved to the head.
  ASSERT_EQ(baker.configReferences().size(), 1u);
  EXPECT_TRUE(vecNear(baker.configReferences()[0], {0.3, 0, 0}));
  EXPECT_TRUE(vecNear(baker.references()[0], {0.3, 0, 0}));
}

TEST(MapFollower, FailedBakeIsReportedAndRenderingGoesOnWithTheOldMap) {
  FakeBaker baker;
  baker.failNext(1);
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function(),
                       radius(0.1));
  const auto original = follower.beginFrame(at(0)).map;
  follower.beginFrame(at(0.3));
  follower.waitForBake();
  const FollowerFrame afterFailure = follower.beginFrame(at(0.3));
  expectValidFrame(afterFailure, {0, 0, 0});
  EXPECT_EQ(afterFailure.map, original);
  EXPECT_FALSE(afterFailure.swapped);
  const std::vector<std::string> errors = follower.takeErrors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("flow diverged (fake)"), std::string::npos) << errors[0];
  EXPECT_TRUE(follower.takeErrors().empty());  // reported once

  // No retry storm while the head stays where the bake failed...
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(follower.beginFrame(at(0.32)).baking);
  EXPECT_EQ(baker.calls(), 1);
  // ...but moving on retries, and that bake succeeds.
  EXPECT_TRUE(follower.beginFrame(at(0.6)).baking);
  follower.waitForBake();
  const FollowerFrame recovered = follower.beginFrame(at(0.6));
  expectValidFrame(recovered, {0.6, 0, 0});
  EXPECT_EQ(recovered.generation, 1u);
  const MapFollowerStats stats = follower.stats();
  EXPECT_EQ(stats.bakesStarted, 2);
  EXPECT_EQ(stats.bakesFailed, 1);
  EXPECT_EQ(stats.bakesSucceeded, 1);
}

TEST(MapFollower, HeadOutsideTheDisplayIsAnErrorNamingTheWallNotACrash) {
  FakeBaker baker;
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function());
  follower.beginFrame(at(0, 0, -2.0));  // half a metre behind the front wall's plane
  follower.waitForBake();
  const FollowerFrame frame = follower.beginFrame(at(0, 0, -2.0));
  expectValidFrame(frame, {0, 0, 0});
  const std::vector<std::string> errors = follower.takeErrors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("'front'"), std::string::npos) << errors[0];
  EXPECT_EQ(baker.calls(), 0);  // rejected before baking
}

TEST(MapFollower, BakeIgnoringTheReferenceIsRejectedInsteadOfLoopingForever) {
  FakeBaker baker;
  baker.ignoreReference();
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function());
  follower.beginFrame(at(0.3));
  follower.waitForBake();
  const FollowerFrame frame = follower.beginFrame(at(0.3));
  EXPECT_EQ(frame.generation, 0u);
  const std::vector<std::string> errors = follower.takeErrors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("instead of"), std::string::npos) << errors[0];
}

TEST(MapFollower, NonFiniteHeadIsIgnored) {
  FakeBaker baker;
  MapFollower follower(shippedConfig("cave5.json"), identityAt({0, 0, 0}), baker.function());
  const FollowerFrame frame = follower.beginFrame(at(std::nan(""), 0, 0));
  expectValidFrame(frame, {0, 0, 0});
  EXPECT_FALSE(frame.baking);
  EXPECT_EQ(baker.calls(), 0);
}

TEST(MapFollower, WithReferenceMovesTheReferenceAndRehashes) {
  const DisplayConfig cave = shippedConfig("cave5.json");
  const DisplayConfig moved = withReference(cave, {0.2, -0.1, 0.3});
  EXPECT_TRUE(vecNear(moved.reference, {0.2, -0.1, 0.3}));
  EXPECT_NE(moved.hash, cave.hash);
  EXPECT_EQ(moved.walls.size(), cave.walls.size());
  EXPECT_EQ(withReference(moved, cave.reference).hash, cave.hash);
  EXPECT_THROW((void)withReference(cave, {0, -1.6, 0}), Error);  // below the floor
}
