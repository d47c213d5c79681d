#include "confvis/engine/tracking_config.hpp"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numbers>

#include "confvis/base/error.hpp"

namespace confvis {

using nlohmann::json;

glm::dquat TrackingConfig::rotation() const {
  const auto about = [](double degrees, const glm::dvec3& axis) {
    return glm::angleAxis(degrees * std::numbers::pi / 180.0, axis);
  };
  return about(yawDegrees, {0, 1, 0}) * about(pitchDegrees, {1, 0, 0}) *
         about(rollDegrees, {0, 0, 1});
}

double TrackingConfig::metresPerUnit(TrackingUnit protocolDefault) const {
  const TrackingUnit effective = unit == TrackingUnit::ProtocolDefault ? protocolDefault : unit;
  return effective == TrackingUnit::Millimetres ? 1e-3 : 1.0;
}

HeadPose TrackingConfig::toRoom(const glm::dvec3& trackerPosition,
                                const glm::dquat& trackerOrientation,
                                double metresPerTrackerUnit) const {
  const glm::dquat r = rotation();
  return HeadPose{r * (trackerPosition * metresPerTrackerUnit) + offset,
                  glm::normalize(r * trackerOrientation * glm::conjugate(r))};
}

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& key, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, where + ": '" + key + "' " + what);
}

double finite(const json& v, const std::string& where, const std::string& key) {
  if (!v.is_number()) fail(where, key, "must be a number, got " + std::string(v.type_name()));
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(where, key, "must be finite");
  return x;
}

void rejectUnknownKeys(const json& object, const std::string& where,
                       std::initializer_list<const char*> known) {
  for (const auto& item : object.items()) {
    bool isKnown = false;
    std::string list;
    for (const char* k : known) {
      isKnown = isKnown || item.key() == k;
      list += (list.empty() ? "" : ", ") + std::string(k);
    }
    if (!isKnown)
      throw Error(ErrorCode::InvalidInput,
                  where + ": unknown key '" + item.key() + "' (allowed: " + list + ")");
  }
}

void requireObject(const json& v, const std::string& where) {
  if (!v.is_object())
    throw Error(ErrorCode::InvalidInput,
                where + ": must be a JSON object, got " + std::string(v.type_name()));
}

void readRotation(const json& v, const std::string& where, TrackingConfig& config) {
  const std::string inner = where + ": rotation";
  requireObject(v, inner);
  rejectUnknownKeys(v, inner, {"yaw", "pitch", "roll"});
  if (v.contains("yaw")) config.yawDegrees = finite(v.at("yaw"), inner, "yaw");
  if (v.contains("pitch")) config.pitchDegrees = finite(v.at("pitch"), inner, "pitch");
  if (v.contains("roll")) config.rollDegrees = finite(v.at("roll"), inner, "roll");
}

}  // namespace

TrackingConfig parseTrackingConfig(const json& v, const std::string& where) {
  requireObject(v, where);
  rejectUnknownKeys(v, where, {"offset", "rotation", "unit", "head_body", "timeout_seconds"});
  TrackingConfig config;
  if (v.contains("offset")) {
    const json& o = v.at("offset");
    if (!o.is_array() || o.size() != 3) fail(where, "offset", "must be an array of 3 numbers");
    config.offset = {finite(o[0], where, "offset"), finite(o[1], where, "offset"),
                     finite(o[2], where, "offset")};
  }
  if (v.contains("rotation")) readRotation(v.at("rotation"), where, config);
  if (v.contains("unit")) {
    const json& u = v.at("unit");
    if (u == "mm") config.unit = TrackingUnit::Millimetres;
    else if (u == "m") config.unit = TrackingUnit::Metres;
    else fail(where, "unit", "must be \"mm\" or \"m\", got " + u.dump());
  }
  if (v.contains("head_body")) {
    const json& b = v.at("head_body");
    constexpr auto kMax = static_cast<std::int64_t>(std::numeric_limits<int>::max());
    const bool inRange = b.is_number_unsigned()
                             ? b.get<std::uint64_t>() <= static_cast<std::uint64_t>(kMax)
                             : b.is_number_integer() && b.get<std::int64_t>() >= 0 &&
                                   b.get<std::int64_t>() <= kMax;
    if (!inRange)
      fail(where, "head_body",
           "must be a non-negative integer (a DTrack body id), got " + b.dump());
    config.headBody = b.get<int>();
  }
  if (v.contains("timeout_seconds")) {
    config.timeoutSeconds = finite(v.at("timeout_seconds"), where, "timeout_seconds");
    if (!(config.timeoutSeconds > 0.0))
      fail(where, "timeout_seconds", "must be positive, got " + v.at("timeout_seconds").dump());
  }
  return config;
}

json toJson(const TrackingConfig& config) {
  json out = {{"offset", json::array({config.offset.x, config.offset.y, config.offset.z})},
              {"rotation",
               {{"yaw", config.yawDegrees},
                {"pitch", config.pitchDegrees},
                {"roll", config.rollDegrees}}},
              {"head_body", config.headBody},
              {"timeout_seconds", config.timeoutSeconds}};
  if (config.unit != TrackingUnit::ProtocolDefault)
    out["unit"] = config.unit == TrackingUnit::Millimetres ? "mm" : "m";
  return out;
}

}  // namespace confvis
