#include "confvis/runtime/tracker_factory.hpp"

#include <algorithm>
#include <cctype>

#include "confvis/base/error.hpp"
#include "confvis/runtime/udp_tracker.hpp"

namespace confvis {

namespace {

constexpr const char* kKinds = "path:FILE.csv, dtrack:PORT or udp:PORT";

// 1..65535, digits only: "udp:0" would bind a random port nobody sends to.
int parsePort(const std::string& text, const std::string& spec) {
  const bool digits = !text.empty() && text.size() <= 5 &&
                      std::all_of(text.begin(), text.end(),
                                  [](unsigned char c) { return std::isdigit(c) != 0; });
  const int port = digits ? std::stoi(text) : 0;
  if (port < 1 || port > 65535)
    throw Error(ErrorCode::InvalidInput, "tracker '" + spec + "': the port must be an integer " +
                                             "from 1 to 65535, got '" + text + "'");
  return port;
}

}  // namespace

std::unique_ptr<Tracker> openTracker(const std::string& spec, const DisplayConfig& display) {
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  if (colon == std::string::npos || colon + 1 == spec.size())
    throw Error(ErrorCode::InvalidInput, "tracker '" + spec + "': expected " + kKinds);
  const std::string rest = spec.substr(colon + 1);
  if (kind == "path") return std::make_unique<RecordedPathTracker>(RecordedPath::load(rest));
  if (kind == "dtrack" || kind == "udp") {
    const TrackerProtocol protocol =
        kind == "dtrack" ? TrackerProtocol::DTrack : TrackerProtocol::JsonLines;
    const int port = parsePort(rest, spec);
    try {
      return std::make_unique<UdpTracker>(protocol, port, display.tracking);
    } catch (const Error& e) {
      throw Error(e.code(), "tracker '" + spec + "': " + e.what());
    }
  }
  throw Error(ErrorCode::InvalidInput,
              "tracker '" + spec + "': unknown kind '" + kind + "' (expected " + kKinds + ")");
}

}  // namespace confvis
