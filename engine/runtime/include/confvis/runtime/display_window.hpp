#pragma once
// GLFW windows for a live display: the library session, the monitors it reports, and one window
// per WindowPlan with the input a viewer gives it (keys, mouse, close, resize, minimise).
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/runtime/window_plan.hpp"

struct GLFWwindow;

namespace confvis CONFVIS_API {

// glfwInit / glfwTerminate. Throws Error(DeviceUnsupported) when no display can be opened
// (no DISPLAY / WAYLAND_DISPLAY), with GLFW's own reason.
// Thread-safety: not thread-safe; make, poll and destroy it on the main thread (GLFW's rule).
class GlfwSession {
 public:
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
  std::vector<MonitorInfo> monitors() const;
  // Processes window-system events; callbacks fire in here.
  void pollEvents();
};

// Input gathered by the callbacks since the last takeInput().
struct WindowInput {
  bool toggleMode = false;   // C: conformal <-> plain
  bool quit = false;         // Esc
  bool resized = false;      // the framebuffer changed size
};

// Thread-safety: not thread-safe; use it on the main thread only, as GLFW requires.
class DisplayWindow {
 public:
  DisplayWindow(const WindowPlan& plan, const std::string& title);
  ~DisplayWindow();
  DisplayWindow(const DisplayWindow&) = delete;
  DisplayWindow& operator=(const DisplayWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  // The DisplayWindow that made `window` (GLFW keeps it as the window's user pointer), or null.
  static const DisplayWindow* of(GLFWwindow* window);
  const WindowPlan& plan() const { return plan_; }
  bool closeRequested() const;
  // Framebuffer pixels; 0 x 0 while minimised.
  void framebufferSize(int& width, int& height) const;
  void setTitle(const std::string& title);
  WindowInput takeInput();
  // Held keys and dragged mouse, for the camera (see camera_controls.hpp).
  bool keyDown(int glfwKey) const;
  bool dragging() const;  // left mouse button held
  void cursor(double& x, double& y) const;

 private:
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onFramebufferSize(GLFWwindow* window, int width, int height);

  WindowPlan plan_;
  GLFWwindow* window_ = nullptr;
  WindowInput input_;
};

}  // namespace confvis
