#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/runtime/tracker.hpp"
#include "confvis/engine/number_text.hpp"

namespace confvis {

namespace {

constexpr const char* kHeader = "seconds,x,y,z,qw,qx,qy,qz";

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(trimmed(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

RecordedPath::RecordedPath(std::vector<PathKey> keys, const std::string& sourceName)
    : keys_(std::move(keys)) {
  if (keys_.empty()) throw Error(ErrorCode::InvalidInput, sourceName + ": the path has no keys");
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    PathKey& k = keys_[i];
    const std::string where = sourceName + ": key " + std::to_string(i) + ": ";
    const glm::dquat& q = k.head.orientation;
    const glm::dvec3& p = k.head.position;
    const bool finite = std::isfinite(k.seconds) && std::isfinite(p.x) && std::isfinite(p.y) &&
                        std::isfinite(p.z) && std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) &&
                        std::isfinite(q.z);
    if (!finite) throw Error(ErrorCode::InvalidInput, where + "values must be finite");
    if (!(glm::length(q) > 1e-9))
      throw Error(ErrorCode::InvalidInput, where + "the orientation quaternion is zero");
    k.head.orientation = glm::normalize(q);
    if (i > 0 && !(k.seconds > keys_[i - 1].seconds))
      throw Error(ErrorCode::InvalidInput, where + "time " + std::to_string(k.seconds) +
                                               " does not increase (previous key at " +
                                               std::to_string(keys_[i - 1].seconds) + ")");
  }
}

RecordedPath RecordedPath::parse(const std::string& text, const std::string& sourceName) {
  std::vector<PathKey> keys;
  std::stringstream in(text);
  bool headerSeen = false;
  int lineNumber = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++lineNumber;
    const std::string line = trimmed(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::string where = sourceName + ":" + std::to_string(lineNumber) + ": ";
    std::vector<std::string> fields = splitCommas(line);
    if (!headerSeen) {
      std::string header;
      for (const std::string& f : fields) header += (header.empty() ? "" : ",") + f;
      if (header != kHeader)
        throw Error(ErrorCode::InvalidInput,
                    where + "the first line must be the header '" + kHeader + "', got '" + line + "'");
      headerSeen = true;
      continue;
    }
    if (fields.size() != 8)
      throw Error(ErrorCode::InvalidInput, where + "expected 8 comma-separated numbers (" +
                                               kHeader + "), got " + std::to_string(fields.size()));
    double v[8];
    for (int k = 0; k < 8; ++k) {
      const std::optional<double> x = detail::parseNumber(fields[k]);
      if (!x)
        throw Error(ErrorCode::InvalidInput,
                    where + "field " + std::to_string(k + 1) + " is not a finite number: '" + fields[k] + "'");
      v[k] = *x;
    }
    keys.push_back({v[0], HeadPose{{v[1], v[2], v[3]}, glm::dquat(v[4], v[5], v[6], v[7])}});
    if (!(glm::length(keys.back().head.orientation) > 1e-9))
      throw Error(ErrorCode::InvalidInput, where + "the orientation quaternion is zero");
    if (keys.size() > 1 && !(v[0] > keys[keys.size() - 2].seconds))
      throw Error(ErrorCode::InvalidInput, where + "time " + fields[0] + " does not increase");
  }
  if (!headerSeen || keys.empty())
    throw Error(ErrorCode::InvalidInput, sourceName + ": the path has no keys");
  return RecordedPath(std::move(keys), sourceName);
}

RecordedPath RecordedPath::load(const std::filesystem::path& path) {
  return parse(readTextFile(path), path.string());
}

HeadPose RecordedPath::at(double seconds, bool loop) const {
  if (keys_.size() == 1 || !std::isfinite(seconds)) return keys_.front().head;
  const double t0 = keys_.front().seconds;
  double t = seconds;
  if (loop) {
    t = t0 + std::fmod(seconds - t0, duration());
    if (t < t0) t += duration();
  }
  if (t <= t0) return keys_.front().head;
  if (t >= keys_.back().seconds) return keys_.back().head;
  const auto next = std::upper_bound(keys_.begin(), keys_.end(), t,
                                     [](double s, const PathKey& k) { return s < k.seconds; });
  const PathKey& b = *next;
  const PathKey& a = *(next - 1);
  const double u = (t - a.seconds) / (b.seconds - a.seconds);
  glm::dquat qb = b.head.orientation;
  if (glm::dot(a.head.orientation, qb) < 0.0) qb = -qb;  // q and -q are one rotation: short arc
  return HeadPose{glm::mix(a.head.position, b.head.position, u),
                  glm::normalize(glm::slerp(a.head.orientation, qb, u))};
}

RecordedPathTracker::RecordedPathTracker(RecordedPath path, bool loop, Clock clock)
    : path_(std::move(path)), loop_(loop), clock_(std::move(clock)) {
  if (!clock_) {
    const auto start = SteadyClock::now();
    clock_ = [start] { return secondsSince(start); };
  }
}

std::optional<TrackedPose> RecordedPathTracker::latest() {
  const double now = clock_();
  return TrackedPose{path_.at(path_.keys().front().seconds + now, loop_), now};
}

}  // namespace confvis
