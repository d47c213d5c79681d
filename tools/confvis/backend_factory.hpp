#pragma once
// The renderers the CLI can use, by name. Adding a backend is one line in backend_factory.cpp.
#include <memory>
#include <string>
#include <vector>

#include "confvis/backends/render_backend.hpp"

namespace confvis::cli {

std::vector<std::string> backendNames();
// Throws Error(InvalidInput) listing the known names for an unknown one.
std::unique_ptr<RenderBackend> makeBackend(const std::string& name);

}  // namespace confvis::cli
