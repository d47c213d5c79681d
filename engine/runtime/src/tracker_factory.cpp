#include "confvis/runtime/tracker_factory.hpp"

#include "confvis/base/error.hpp"

namespace confvis {

std::unique_ptr<Tracker> openTracker(const std::string& spec, const DisplayConfig&) {
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  if (colon == std::string::npos || colon + 1 == spec.size())
    throw Error(ErrorCode::InvalidInput,
                "tracker '" + spec + "': expected path:FILE.csv, dtrack:PORT or udp:PORT");
  const std::string rest = spec.substr(colon + 1);
  if (kind == "path") return std::make_unique<RecordedPathTracker>(RecordedPath::load(rest));
  throw Error(ErrorCode::InvalidInput, "tracker '" + spec + "': unknown kind '" + kind +
                                           "' (expected path:FILE.csv, dtrack:PORT or udp:PORT)");
}

}  // namespace confvis
