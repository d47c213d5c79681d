#include "confvis/runtime/display_window.hpp"

#include <cstdio>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// GLFW reports errors through a callback; the latest is kept for the exception that follows.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int code, const char* description) {
  lastGlfwError() = std::string(description ? description : "unknown") + " (GLFW error " +
                    std::to_string(code) + ")";
}

}  // namespace

GlfwSession::GlfwSession() {
  glfwSetErrorCallback(&onGlfwError);
  if (glfwInit() != GLFW_TRUE)
    throw Error(ErrorCode::DeviceUnsupported,
                "cannot open the window system: " + lastGlfwError() +
                    " (confvis view needs a display: set DISPLAY or WAYLAND_DISPLAY, or run "
                    "under Xvfb)");
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw Error(ErrorCode::DeviceUnsupported,
                "GLFW finds no Vulkan loader (Debian: libvulkan1, mesa-vulkan-drivers)");
  }
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

std::vector<MonitorInfo> GlfwSession::monitors() const {
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  std::vector<MonitorInfo> result;
  for (int i = 0; i < count; ++i) {
    MonitorInfo info;
    const char* name = glfwGetMonitorName(monitors[i]);
    info.name = name ? name : "monitor " + std::to_string(i);
    glfwGetMonitorPos(monitors[i], &info.x, &info.y);
    if (const GLFWvidmode* mode = glfwGetVideoMode(monitors[i])) {
      info.width = mode->width;
      info.height = mode->height;
    }
    glfwGetMonitorWorkarea(monitors[i], &info.workX, &info.workY, &info.workWidth,
                           &info.workHeight);
    if (info.workWidth <= 0 || info.workHeight <= 0) {
      info.workX = info.x;
      info.workY = info.y;
      info.workWidth = info.width;
      info.workHeight = info.height;
    }
    result.push_back(info);
  }
  return result;
}

void GlfwSession::pollEvents() { glfwPollEvents(); }

DisplayWindow::DisplayWindow(const WindowPlan& plan, const std::string& title) : plan_(plan) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // presented with Vulkan
  glfwWindowHint(GLFW_DECORATED, plan.decorated ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once placed
  GLFWmonitor* monitor = nullptr;
  if (plan.fullscreenMonitor >= 0) {
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    if (plan.fullscreenMonitor < count) monitor = monitors[plan.fullscreenMonitor];
  }
  window_ = glfwCreateWindow(plan.width, plan.height, title.c_str(), monitor, nullptr);
  if (!window_)
    throw Error(ErrorCode::DeviceUnsupported,
                "wall '" + plan.wall + "': cannot open its window: " + lastGlfwError());
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &DisplayWindow::onKey);
  glfwSetFramebufferSizeCallback(window_, &DisplayWindow::onFramebufferSize);
  if (!monitor) glfwSetWindowPos(window_, plan.x, plan.y);
  glfwShowWindow(window_);
}

DisplayWindow::~DisplayWindow() {
  if (window_) glfwDestroyWindow(window_);
}

const DisplayWindow* DisplayWindow::of(GLFWwindow* window) {
  return window ? static_cast<const DisplayWindow*>(glfwGetWindowUserPointer(window)) : nullptr;
}

bool DisplayWindow::closeRequested() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void DisplayWindow::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
  if (glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE) width = height = 0;
}

void DisplayWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

WindowInput DisplayWindow::takeInput() {
  const WindowInput input = input_;
  input_ = {};
  return input;
}

bool DisplayWindow::keyDown(int glfwKey) const { return glfwGetKey(window_, glfwKey) == GLFW_PRESS; }

bool DisplayWindow::dragging() const {
  return glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
}

void DisplayWindow::cursor(double& x, double& y) const { glfwGetCursorPos(window_, &x, &y); }

void DisplayWindow::onKey(GLFWwindow* window, int key, int, int action, int) {
  auto* self = static_cast<DisplayWindow*>(glfwGetWindowUserPointer(window));
  if (!self || action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) self->input_.quit = true;
  if (key == GLFW_KEY_C) self->input_.toggleMode = true;
}

void DisplayWindow::onFramebufferSize(GLFWwindow* window, int, int) {
  if (auto* self = static_cast<DisplayWindow*>(glfwGetWindowUserPointer(window)))
    self->input_.resized = true;
}

}  // namespace confvis
