#pragma once
// The renderers the CLI can use, by name. Adding a backend is one line in backend_factory.cpp.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/vulkan/external_device.hpp"

namespace confvis::cli {

std::vector<std::string> backendNames();
struct BackendOptions {
  std::string device;  // Vulkan: "" / "auto", an index or part of a device name
  // Vulkan conformal mode: the tessellation threshold, pixels (VulkanOptions'); unset: default.
  std::optional<double> tessellationErrorPixels;
};

// Throws Error(InvalidInput) listing the known names for an unknown one.
std::unique_ptr<RenderBackend> makeBackend(const std::string& name,
                                           const BackendOptions& options = {});

// The same on a device made elsewhere (confvis view's presenting device): Vulkan renders on it
// (its frames then never leave the GPU); other backends ignore it.
std::unique_ptr<RenderBackend> makeBackendOn(const VulkanDeviceHandles& device,
                                             const std::string& name,
                                             const BackendOptions& options = {});

}  // namespace confvis::cli
