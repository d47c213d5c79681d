#pragma once
// Opens a head tracker from a command-line spec, the way `confvis view --tracker` names one.
#include <memory>
#include <string>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/runtime/tracker.hpp"

namespace confvis CONFVIS_API {

// spec: "path:FILE.csv" plays a recorded head path in real time, looping. Live trackers
// ("dtrack:PORT", ART DTrack2 ASCII over UDP; "udp:PORT", JSON lines over UDP) take the
// display's tracking section (tracker-to-room transform, unit, head body, timeout; see
// udp_tracker.hpp).
// Error(InvalidInput) naming the spec for an unknown kind or a port outside 1..65535;
// Error(IoFailure) naming the spec when the port cannot be bound; the path's own errors for a bad
// file.
std::unique_ptr<Tracker> openTracker(const std::string& spec, const DisplayConfig& display);

}  // namespace confvis
