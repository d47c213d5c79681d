#pragma once
// A window's pixels from the renderer's wall images: each eye's image placed in its region
// (window_plan.hpp), linear RGB encoded to 8-bit sRGB codes exactly as the PNG previews of
// `confvis render` are (so a presented frame compares with an offscreen one), alpha opaque.
#include <cstdint>
#include <functional>

#include "confvis/base/export.hpp"
#include "confvis/base/image.hpp"
#include "confvis/runtime/window_plan.hpp"

namespace confvis CONFVIS_API {

// imageOf(eye) returns the wall's rendered image of that eye (never null). `out` holds
// plan.contentWidth x plan.contentHeight RGBA pixels, top row first. Throws Error(Internal) if
// an image is not the size its region expects.
void composeWindow(const WindowPlan& plan, const std::function<const ImageRGBA*(Eye)>& imageOf,
                   std::uint8_t* out);

// The 8-bit sRGB code of a linear value, as writePng rounds it (clamped to [0, 1]).
std::uint8_t srgbCode(float linear);

}  // namespace confvis
