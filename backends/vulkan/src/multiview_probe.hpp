#pragma once
// Does the device draw multiview passes correctly? Mesa's lavapipe 22.3 (Debian 12, what CI
// runs) does not: a primitive of view 1 that needs clipping (any triangle crossing a wall's edge
// or passing behind the eye) is rasterized into layer 0, so the right eye loses it and the left
// eye shows it twice. Rather than trust driver names and versions, the backend renders one
// known case at startup and falls back to one pass per eye where the answer is wrong.
#include "frame_renderer.hpp"

namespace confvis::vulkan {

// Renders a triangle far larger than the view into both eyes of a tiny wall in one multiview
// pass; true when both layers come back fully covered.
bool multiviewKeepsClippedPrimitivesInTheirView(VulkanContext& context, Pipelines& pipelines,
                                                FrameRenderer& frames);

}  // namespace confvis::vulkan
