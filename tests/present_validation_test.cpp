// The presenting context's validation count, which the view tests assert to be zero, does count:
// a deliberately invalid call (a buffer of size 0) is reported as an error.
#include <gtest/gtest.h>

#include <cstdlib>

#include <vulkan/vulkan.h>

#include "confvis/runtime/display_window.hpp"
#include "confvis/runtime/present_context.hpp"
#include "view_test_support.hpp"

using confvis::testing::VirtualDisplay;

TEST(PresentContext, ValidationMessagesAreCounted) {
  if (VirtualDisplay::shared().name().empty()) {
    GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable();
  }
  ::setenv("DISPLAY", VirtualDisplay::shared().name().c_str(), 1);
  confvis::GlfwSession glfw;
  confvis::PresentContext context(confvis::PresentContextOptions{.validation = true});
  EXPECT_EQ(context.validation().errors, 0) << "a fresh context is clean";
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;  // VUID-VkBufferCreateInfo-size-00912
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS && buffer)
    vkDestroyBuffer(context.device(), buffer, nullptr);
  const confvis::ValidationReport report = context.validation();
  EXPECT_TRUE(report.enabled);
  EXPECT_GE(report.errors, 1);
  ASSERT_FALSE(report.messages.empty());
  EXPECT_NE(report.messages.front().find("00912"), std::string::npos) << report.messages.front();
}
