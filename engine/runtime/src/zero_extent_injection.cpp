#include "confvis/runtime/zero_extent_injection.hpp"

#include <charconv>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

std::optional<ZeroExtentInjection>& injected() {
  static std::optional<ZeroExtentInjection> injection;
  return injection;
}

bool parseCount(const std::string& text, long& value) {
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && at == end && value >= 0;
}

}  // namespace

ZeroExtentInjection parseZeroExtentInjection(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return Error(ErrorCode::InvalidInput, std::string(kZeroExtentVariable) + "='" + text +
                                              "': " + why + " (expected WALL:FIRST:FRAMES)");
  };
  const std::size_t last = text.rfind(':');
  const std::size_t middle = last == std::string::npos || last == 0
                                 ? std::string::npos
                                 : text.rfind(':', last - 1);
  if (middle == std::string::npos) throw bad("not three ':'-separated fields");
  ZeroExtentInjection injection;
  injection.wall = text.substr(0, middle);
  if (injection.wall.empty()) throw bad("no wall name");
  if (!parseCount(text.substr(middle + 1, last - middle - 1), injection.firstFrame))
    throw bad("the first frame is not a whole number >= 0");
  if (!parseCount(text.substr(last + 1), injection.frames) || injection.frames == 0)
    throw bad("the frame count is not a whole number > 0");
  return injection;
}

void setZeroExtentInjection(std::optional<ZeroExtentInjection> injection) {
  injected() = std::move(injection);
}

bool zeroExtentInjected(const std::string& wall, long frame) {
  return injected() && injected()->covers(wall, frame);
}

}  // namespace confvis
