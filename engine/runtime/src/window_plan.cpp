#include "confvis/runtime/window_plan.hpp"

#include <algorithm>
#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

std::string monitorList(const std::vector<MonitorInfo>& monitors) {
  std::string list;
  for (std::size_t i = 0; i < monitors.size(); ++i)
    list += (list.empty() ? "" : ", ") + std::to_string(i) + ": '" + monitors[i].name + "' " +
            std::to_string(monitors[i].width) + "x" + std::to_string(monitors[i].height) + "+" +
            std::to_string(monitors[i].x) + "+" + std::to_string(monitors[i].y);
  return list.empty() ? "none" : list;
}

int findMonitor(const MonitorChoice& choice, const std::vector<MonitorInfo>& monitors,
                const std::string& wall) {
  if (choice.index >= 0 && choice.index < static_cast<int>(monitors.size())) return choice.index;
  if (!choice.name.empty())
    for (std::size_t i = 0; i < monitors.size(); ++i)
      if (monitors[i].name.find(choice.name) != std::string::npos) return static_cast<int>(i);
  const std::string asked =
      choice.name.empty() ? "monitor " + std::to_string(choice.index) : "monitor '" + choice.name + "'";
  throw Error(ErrorCode::InvalidInput, "wall '" + wall + "': window fullscreen on " + asked +
                                           ", which does not exist (monitors: " +
                                           monitorList(monitors) + ")");
}

bool onSomeMonitor(const WindowPlan& plan, const std::vector<MonitorInfo>& monitors) {
  for (const MonitorInfo& m : monitors)
    if (plan.x < m.x + m.width && plan.x + plan.width > m.x && plan.y < m.y + m.height &&
        plan.y + plan.height > m.y)
      return true;
  return false;
}

// The eyes and their layout in content pixels for one wall image of w x h.
void layEyes(WindowPlan& plan, bool stereoRun, int w, int h) {
  const Eye left = stereoRun ? Eye::Left : Eye::Center;
  const Eye right = stereoRun ? Eye::Right : Eye::Center;
  switch (plan.stereo) {
    case StereoOutput::Mono:
      plan.regions = {{Eye::Center, 0, 0, w, h}};
      break;
    case StereoOutput::SideBySide:
      plan.regions = {{left, 0, 0, w, h}, {right, w, 0, w, h}};
      break;
    case StereoOutput::TopBottom:
      plan.regions = {{left, 0, 0, w, h}, {right, 0, h, w, h}};
      break;
    case StereoOutput::Left:
      plan.regions = {{left, 0, 0, w, h}};
      break;
    case StereoOutput::Right:
      plan.regions = {{right, 0, 0, w, h}};
      break;
  }
  plan.contentWidth = plan.contentHeight = 0;
  for (const EyeRegion& r : plan.regions) {
    plan.contentWidth = std::max(plan.contentWidth, r.x + r.width);
    plan.contentHeight = std::max(plan.contentHeight, r.y + r.height);
    if (std::find(plan.eyes.begin(), plan.eyes.end(), r.eye) == plan.eyes.end())
      plan.eyes.push_back(r.eye);
  }
}

}  // namespace

int scaledPixels(int pixels, double scale) {
  return std::max(1, static_cast<int>(std::lround(pixels * scale)));
}

std::vector<WindowPlan> planWindows(const DisplayConfig& config, bool stereoRun, double scale,
                                    const std::vector<MonitorInfo>& monitors) {
  if (monitors.empty())
    throw Error(ErrorCode::DeviceUnsupported, "the window system reports no monitor");
  std::vector<WindowPlan> plans;
  for (const Wall& wall : config.walls) {
    WindowPlan plan;
    plan.wall = wall.name;
    plan.stereo = wall.output.stereo.value_or(stereoRun ? StereoOutput::SideBySide
                                                        : StereoOutput::Mono);
    layEyes(plan, stereoRun, scaledPixels(wall.width, scale), scaledPixels(wall.height, scale));
    plan.width = plan.contentWidth;
    plan.height = plan.contentHeight;
    if (const auto& window = wall.output.window) {
      plan.decorated = window->decorated;
      if (window->size) std::tie(plan.width, plan.height) = *window->size;
      if (window->fullscreen) {
        plan.fullscreenMonitor = findMonitor(*window->fullscreen, monitors, wall.name);
        const MonitorInfo& m = monitors[plan.fullscreenMonitor];
        plan.x = m.x;
        plan.y = m.y;
        plan.width = m.width;
        plan.height = m.height;
      }
    }
    plans.push_back(plan);
  }

  // Tile the windows without a place of their own over the first monitor's work area: rows
  // left to right, all shrunk by one factor until the rows fit (never enlarged).
  const MonitorInfo& desk = monitors.front();
  std::vector<WindowPlan*> tiled;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    const auto& window = config.walls[i].output.window;
    if (!window || (!window->position && !window->fullscreen)) tiled.push_back(&plans[i]);
  }
  for (double shrink = 1.0; !tiled.empty(); shrink *= 0.9) {
    int x = 0, y = 0, rowHeight = 0;
    bool fits = true;
    for (WindowPlan* plan : tiled) {
      const auto& size = config.wall(plan->wall).output.window;
      const int w = std::max(1, static_cast<int>((size && size->size ? size->size->first : plan->contentWidth) * shrink));
      const int h = std::max(1, static_cast<int>((size && size->size ? size->size->second : plan->contentHeight) * shrink));
      if (x > 0 && x + w > desk.workWidth) {
        x = 0;
        y += rowHeight;
        rowHeight = 0;
      }
      plan->x = desk.workX + x;
      plan->y = desk.workY + y;
      plan->width = w;
      plan->height = h;
      x += w;
      rowHeight = std::max(rowHeight, h);
      fits = fits && x <= desk.workWidth && y + h <= desk.workHeight;
    }
    if (fits || shrink < 0.05) break;
  }

  for (std::size_t i = 0; i < plans.size(); ++i) {
    const auto& window = config.walls[i].output.window;
    if (!window || !window->position) continue;
    std::tie(plans[i].x, plans[i].y) = *window->position;
    if (!onSomeMonitor(plans[i], monitors))
      throw Error(ErrorCode::InvalidInput,
                  "wall '" + plans[i].wall + "': window at " + std::to_string(plans[i].x) + "," +
                      std::to_string(plans[i].y) + " of " + std::to_string(plans[i].width) + "x" +
                      std::to_string(plans[i].height) + " lies on no monitor (monitors: " +
                      monitorList(monitors) + ")");
  }
  return plans;
}

}  // namespace confvis
