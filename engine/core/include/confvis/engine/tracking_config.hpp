#pragma once
// A display's head tracker: where the tracker's coordinate frame sits in the room (the display's
// physical frame), what unit it measures in, which tracked body is the head, and when it counts
// as lost. The optional top-level "tracking" section of a display config (configs/README.md):
//   "tracking": {
//     "offset": [0, 0, 0],                           metres: the tracker's origin in the room
//     "rotation": {"yaw": 0, "pitch": 0, "roll": 0},  degrees: tracker axes -> room axes
//     "unit": "mm",                                  "mm" | "m"; default the protocol's own
//     "head_body": 0,                                DTrack body id of the head (0-based)
//     "timeout_seconds": 0.5                         no pose for this long: tracking lost
//   }
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// Length unit of the tracker's positions. ProtocolDefault: the protocol's own (ART DTrack sends
// millimetres, the JSON-lines protocol metres).
enum class TrackingUnit { ProtocolDefault, Millimetres, Metres };

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct TrackingConfig {
  glm::dvec3 offset{0.0};  // metres, room frame
  // R = Ry(yaw) * Rx(pitch) * Rz(roll) about the room's axes (+y up, -z forward), degrees.
  double yawDegrees = 0.0, pitchDegrees = 0.0, rollDegrees = 0.0;
  TrackingUnit unit = TrackingUnit::ProtocolDefault;
  int headBody = 0;              // ART DTrack2 numbers bodies from 0 in its output
  double timeoutSeconds = 0.5;   // > 0

  // The tracker-to-room rotation R as a unit quaternion.
  glm::dquat rotation() const;
  // Metres per tracker unit, `protocolDefault` standing in for TrackingUnit::ProtocolDefault.
  double metresPerUnit(TrackingUnit protocolDefault) const;
  // A tracked pose in the tracker's frame and units -> the head in the room, metres:
  // position R * (p * metresPerUnit) + offset; orientation R * q * R^-1, so a head body
  // calibrated with its axes parallel to the tracker's room axes is the identity head (looking
  // down -z, +y up) when it faces the room's forward direction.
  HeadPose toRoom(const glm::dvec3& trackerPosition, const glm::dquat& trackerOrientation,
                  double metresPerTrackerUnit) const;
};

// Validates the "tracking" section; `where` ("cave.json: tracking") prefixes every error, which
// names the offending key: Error(InvalidInput).
TrackingConfig parseTrackingConfig(const nlohmann::json& json, const std::string& where);

// Canonical form; "unit" is written only when set.
nlohmann::json toJson(const TrackingConfig& config);

}  // namespace confvis
