// What a window's presenter does each frame with what the surface and the swapchain calls
// report: the minimised window's 0 x 0 surface (skipped, no swapchain of zero size, a new one
// once it has an area again), resizes, and the results of acquire and present.
#include <gtest/gtest.h>

#include "confvis/base/error.hpp"
#include "confvis/runtime/swapchain_state.hpp"
#include "confvis/runtime/zero_extent_injection.hpp"

namespace confvis {
namespace {

constexpr VkExtent2D kZero{0, 0}, kWindow{96, 96}, kResized{160, 120};

// A state with a swapchain of kWindow presenting.
SwapchainState presenting() {
  SwapchainState state;
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Present);
  return state;
}

TEST(SwapchainState, FirstFrameCreatesAndMatchingFramesPresent) {
  SwapchainState state;
  EXPECT_FALSE(state.hasSwapchain());
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  EXPECT_TRUE(state.hasSwapchain());
  EXPECT_EQ(state.extent().width, 96u);
  for (int frame = 0; frame < 3; ++frame) EXPECT_EQ(state.next(kWindow), SwapchainStep::Present);
  EXPECT_EQ(state.recreations(), 0) << "the first swapchain is no recreation";
}

TEST(SwapchainState, ZeroExtentSkipsWithoutCreatingAndRecreatesWhenTheAreaComesBack) {
  SwapchainState state = presenting();
  // Minimised: nothing presented, nothing made, however many frames it lasts; either side
  // alone being zero is no area either.
  for (VkExtent2D none : {kZero, VkExtent2D{0, 96}, VkExtent2D{96, 0}, kZero})
    EXPECT_EQ(state.next(none), SwapchainStep::Skip);
  EXPECT_TRUE(state.stale());
  EXPECT_EQ(state.extent().width, 96u) << "the old swapchain is kept until replaced";
  // Restored at the same size: a new swapchain all the same (the old one may be out of date).
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  EXPECT_FALSE(state.stale());
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Present);
  EXPECT_EQ(state.recreations(), 1);
}

TEST(SwapchainState, MinimisedFromTheStartCreatesNothingUntilItHasAnArea) {
  SwapchainState state;
  EXPECT_EQ(state.next(kZero), SwapchainStep::Skip);
  EXPECT_EQ(state.next(kZero), SwapchainStep::Skip);
  EXPECT_FALSE(state.hasSwapchain());
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  EXPECT_EQ(state.recreations(), 0);
}

// The window had an area but the surface reports none when the swapchain is made (a minimise
// racing the frame): no swapchain of zero size, the old one stays stale, the next frame tries again.
TEST(SwapchainState, SurfaceWithoutAreaAtCreationLeavesItStaleAndTriesAgain) {
  SwapchainState state = presenting();
  EXPECT_EQ(state.next(kResized), SwapchainStep::Recreate);
  state.created(kZero);
  EXPECT_TRUE(state.stale());
  EXPECT_EQ(state.extent().width, 96u);
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate)
      << "a stale swapchain is not presented even at its own size";
  state.created(kWindow);
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Present);
  EXPECT_EQ(state.recreations(), 1);

  SwapchainState fresh;
  EXPECT_EQ(fresh.next(kWindow), SwapchainStep::Recreate);
  fresh.created(kZero);
  EXPECT_FALSE(fresh.hasSwapchain());
  EXPECT_EQ(fresh.next(kWindow), SwapchainStep::Recreate);
}

TEST(SwapchainState, ResizeRecreatesAtTheNewExtent) {
  SwapchainState state = presenting();
  EXPECT_EQ(state.next(kResized), SwapchainStep::Recreate);
  state.created(kResized);
  EXPECT_EQ(state.next(kResized), SwapchainStep::Present);
  EXPECT_EQ(state.extent().width, 160u);
  EXPECT_EQ(state.extent().height, 120u);
  EXPECT_EQ(state.recreations(), 1);
}

TEST(SwapchainState, AcquireResults) {
  SwapchainState state = presenting();
  EXPECT_EQ(state.afterAcquire(VK_SUCCESS), AcquireOutcome::Use);
  EXPECT_FALSE(state.stale());
  // Suboptimal: this image is presented, the next frame recreates.
  EXPECT_EQ(state.afterAcquire(VK_SUBOPTIMAL_KHR), AcquireOutcome::Use);
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  // Out of date: nothing this frame, recreated at the next.
  EXPECT_EQ(state.afterAcquire(VK_ERROR_OUT_OF_DATE_KHR), AcquireOutcome::Skip);
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate);
  state.created(kWindow);
  for (VkResult lost : {VK_ERROR_SURFACE_LOST_KHR, VK_ERROR_DEVICE_LOST,
                        VK_ERROR_OUT_OF_HOST_MEMORY, VK_TIMEOUT, VK_NOT_READY})
    EXPECT_EQ(state.afterAcquire(lost), AcquireOutcome::Fail) << lost;
}

TEST(SwapchainState, PresentResults) {
  SwapchainState state = presenting();
  EXPECT_TRUE(state.afterPresent(VK_SUCCESS));
  EXPECT_EQ(state.next(kWindow), SwapchainStep::Present);
  for (VkResult changed : {VK_SUBOPTIMAL_KHR, VK_ERROR_OUT_OF_DATE_KHR}) {
    EXPECT_TRUE(state.afterPresent(changed));
    EXPECT_EQ(state.next(kWindow), SwapchainStep::Recreate) << changed;
    state.created(kWindow);
  }
  EXPECT_FALSE(state.afterPresent(VK_ERROR_SURFACE_LOST_KHR));
  EXPECT_FALSE(state.afterPresent(VK_ERROR_DEVICE_LOST));
}

TEST(ZeroExtentInjection, ParsesWallFirstFrameAndCount) {
  const ZeroExtentInjection injection = parseZeroExtentInjection("front:10:8");
  EXPECT_EQ(injection.wall, "front");
  EXPECT_EQ(injection.firstFrame, 10);
  EXPECT_EQ(injection.frames, 8);
  EXPECT_FALSE(injection.covers("front", 9));
  EXPECT_TRUE(injection.covers("front", 10));
  EXPECT_TRUE(injection.covers("front", 17));
  EXPECT_FALSE(injection.covers("front", 18));
  EXPECT_FALSE(injection.covers("left", 12));
  EXPECT_EQ(parseZeroExtentInjection("wall:a:0:1").wall, "wall:a") << "a wall name with ':'";
}

TEST(ZeroExtentInjection, BadTextIsOneErrorNamingTheVariable) {
  for (const char* bad : {"", "front", "front:10", ":1:2", "front:-1:2", "front:1:0", "front:x:2",
                          "front:1:2x"}) {
    try {
      parseZeroExtentInjection(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& error) {
      EXPECT_EQ(error.code(), ErrorCode::InvalidInput);
      EXPECT_NE(std::string(error.what()).find("CONFVIS_TEST_ZERO_EXTENT"), std::string::npos)
          << error.what();
    }
  }
}

TEST(ZeroExtentInjection, ProcessWideUntilRemoved) {
  setZeroExtentInjection(parseZeroExtentInjection("front:2:1"));
  EXPECT_TRUE(zeroExtentInjected("front", 2));
  EXPECT_FALSE(zeroExtentInjected("front", 3));
  setZeroExtentInjection(std::nullopt);
  EXPECT_FALSE(zeroExtentInjected("front", 2));
}

}  // namespace
}  // namespace confvis
