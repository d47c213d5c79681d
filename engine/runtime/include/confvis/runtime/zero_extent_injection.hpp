#pragma once
// A test seam for the presenter's minimised-window path: the surface of one wall's window
// reports 0 x 0 for a few frames, as a minimised window's does on Windows and on some
// compositors. Xvfb never reports 0 x 0 (an iconified X window keeps its size), so without it
// that path would run nowhere in CI. `confvis view` sets it from CONFVIS_TEST_ZERO_EXTENT; an
// application never needs it.
#include <optional>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value; read it from any number of threads at once.
struct ZeroExtentInjection {
  std::string wall;
  long firstFrame = 0;  // the presenter's frames, counted from 0
  long frames = 0;
  bool covers(const std::string& windowWall, long frame) const {
    return windowWall == wall && frame >= firstFrame && frame - firstFrame < frames;
  }
};

// The environment variable `confvis view` reads it from.
inline constexpr const char* kZeroExtentVariable = "CONFVIS_TEST_ZERO_EXTENT";

// "WALL:FIRST:FRAMES" (the wall name may itself hold ':'). Throws Error(InvalidInput) naming
// CONFVIS_TEST_ZERO_EXTENT and the text otherwise.
ZeroExtentInjection parseZeroExtentInjection(const std::string& text);

// Process-wide; WindowPresenters consult it every frame. Set it before the frame loop starts
// (not while presenters run on another thread); nullopt removes it.
void setZeroExtentInjection(std::optional<ZeroExtentInjection> injection);
// True while the injection makes `wall`'s surface report 0 x 0 at `frame`.
bool zeroExtentInjected(const std::string& wall, long frame);

}  // namespace confvis
