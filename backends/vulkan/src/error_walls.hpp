#pragma once
// A wall's local bend error bound for the conformal pre-pass (ErrorWall of pipelines.hpp), used by
// the frame plan and by the bring-your-own pre-pass step alike.
#include <cstdint>

#include <glm/glm.hpp>

#include "confvis/engine/display_config.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

// The wall's lit rectangle relative to c with the bend error it tolerates, errorPixels of its
// pixels where the edge is shown (README: "The error bound where the edge is shown").
ErrorWall errorWall(const Wall& wall, std::uint32_t width, std::uint32_t height,
                    const glm::dvec3& c, double errorPixels);

}  // namespace confvis::vulkan
