// The frame plan's error walls (frame_plan.hpp): the conformal pre-pass bounds a bent edge's
// error by errorPixels of the pixels of the wall that shows it, k cos^2 with k = errorPixels x
// pitch / D (confvis_prepass_common.glsl, errorAngleToward). Checked against the angles that
// neighbouring pixel centres actually subtend at c.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "../src/frame_plan.hpp"
#include "vulkan_test_support.hpp"

namespace confvis::vulkan {
namespace {

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(VulkanFramePlan, ErrorWallsBoundTheErrorByThePixelsWhereItIsShown) {
  const DisplayConfig config = test::loadConfig("cave5");
  RetargetMap map = RetargetMap::identity(16);
  map.reference = {config.reference.x, config.reference.y, config.reference.z};  // the CAVE's centre
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.resolutionScale = 0.125;
  TessellationOptions tessellation;
  tessellation.errorPixels = 0.5;
  const FramePlan plan = planFrame(config, &map, settings, tessellation, 2);
  ASSERT_EQ(plan.errorWalls.size(), plan.walls.size());
  const glm::dvec3 c(map.reference.x, map.reference.y, map.reference.z);
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    SCOPED_TRACE(plan.walls[w]->name);
    const Wall lit = plan.walls[w]->litRectangle();
    const ErrorWall& e = plan.errorWalls[w];
    const int width = static_cast<int>(plan.widths[w]), height = static_cast<int>(plan.heights[w]);
    // Centre of output pixel (x, y) (the plan's resolution; fractional for steps), row 0 at the
    // top.
    const auto pixel = [&](double x, double y) {
      return lit.pointAt((x + 0.5) / width, 1.0 - (y + 0.5) / height);
    };
    // The bound the shader computes for the direction of pixel (x, y)'s centre.
    const auto bound = [&](int x, int y) {
      const glm::dvec3 d = glm::normalize(pixel(x, y) - c);
      const double cosine = -glm::dot(d, glm::dvec3(e.normal));
      return double(e.lowerLeft.w) * cosine * cosine;
    };
    // Half the smallest angle that a step of one pixel subtends there, in any of 32 directions
    // (the smallest: along the plane of incidence, pitch cos^2 / D).
    const auto measured = [&](int x, int y) {
      const glm::dvec3 p = pixel(x, y) - c;
      double smallest = 1e30;
      for (int k = 0; k < 32; ++k) {
        const double a = k * glm::pi<double>() / 32.0;
        smallest = std::min(smallest, angleBetween(p, pixel(x + std::cos(a), y + std::sin(a)) - c));
      }
      return 0.5 * smallest;
    };
    // The wall's plane faces c at its distance.
    EXPECT_NEAR(glm::dot(glm::dvec3(e.normal), c - lit.lowerLeft), double(e.normal.w), 1e-5);
    // At the centre a pixel subtends pitch / D; at a corner pitch cos^2 / D at least, a third of
    // it in a cube, where the bound is the strictest (the walls' smallest pixel angle).
    const int cx = width / 2, cy = height / 2;
    EXPECT_NEAR(bound(cx, cy), measured(cx, cy), 0.01 * measured(cx, cy));
    EXPECT_NEAR(bound(0, 0), measured(0, 0), 0.03 * measured(0, 0));
    EXPECT_LE(bound(0, 0), measured(0, 0) * 1.001);
    EXPECT_NEAR(bound(0, 0), 0.5 * plan.pixelAngles[w], 0.03 * bound(0, 0));
    EXPECT_GT(bound(cx, cy), 2.5 * bound(0, 0));
  }
}

TEST(VulkanFramePlan, PlainFramesHaveNoErrorWalls) {
  const DisplayConfig config = test::loadConfig("cave5");
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = 0.125;
  const FramePlan plan = planFrame(config, nullptr, settings, TessellationOptions{}, 2);
  EXPECT_TRUE(plan.errorWalls.empty());
}

}  // namespace
}  // namespace confvis::vulkan
