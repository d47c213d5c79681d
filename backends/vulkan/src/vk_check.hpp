#pragma once
// Vulkan results to confvis errors: every failing call becomes one Error naming the call.
#include <string>

#include <vulkan/vulkan.h>

#include "confvis/base/error.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

const char* toString(VkResult result) noexcept;

// Throws Error(Internal) naming `call` and the result unless it is VK_SUCCESS; out of memory
// and a lost device are reported as such (still Internal: nothing the input could fix).
void check(VkResult result, const char* call);

}  // namespace vulkan
}  // namespace confvis
