#include "confvis/runtime/tracker_packets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "confvis/engine/number_text.hpp"

namespace confvis {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (isBlank(s.front()) || s.front() == '\r' || s.front() == '\n'))
    s.remove_prefix(1);
  while (!s.empty() && (isBlank(s.back()) || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

// Non-blank lines (CR, LF or CR LF endings); nullopt beyond kMaxLinesPerDatagram.
std::optional<std::vector<std::string_view>> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find_first_of("\r\n", start), text.size());
    const std::string_view line = trimmed(text.substr(start, end - start));
    if (!line.empty()) {
      if (lines.size() == kMaxLinesPerDatagram) return std::nullopt;
      lines.push_back(line);
    }
    start = end + 1;
  }
  return lines;
}

// A non-negative integer that fits an int.
std::optional<int> parseCount(std::string_view text) {
  const std::optional<double> x = detail::parseNumber(text);
  if (!x || *x < 0 || *x > std::numeric_limits<int>::max() || std::floor(*x) != *x)
    return std::nullopt;
  return static_cast<int>(*x);
}

// Reads "[n n n]" blocks and numbers from one DTrack line, left to right.
class BlockReader {
 public:
  explicit BlockReader(std::string_view text) : rest_(text) {}

  std::optional<std::string_view> word() {
    skipBlanks();
    std::size_t n = 0;
    while (n < rest_.size() && !isBlank(rest_[n]) && rest_[n] != '[') ++n;
    if (n == 0) return std::nullopt;
    const std::string_view w = rest_.substr(0, n);
    rest_.remove_prefix(n);
    return w;
  }

  // The numbers of the next block into `out`; false unless it holds exactly `minCount` or
  // `maxCount` finite numbers.
  bool block(double* out, std::size_t minCount, std::size_t maxCount) {
    skipBlanks();
    if (rest_.empty() || rest_.front() != '[') return false;
    const std::size_t close = rest_.find(']');
    if (close == std::string_view::npos) return false;
    std::string_view inside = rest_.substr(1, close - 1);
    rest_.remove_prefix(close + 1);
    std::size_t count = 0;
    while (true) {
      while (!inside.empty() && isBlank(inside.front())) inside.remove_prefix(1);
      if (inside.empty()) break;
      std::size_t n = 0;
      while (n < inside.size() && !isBlank(inside[n])) ++n;
      if (count == maxCount) return false;
      const std::optional<double> x = detail::parseNumber(inside.substr(0, n));
      if (!x) return false;
      out[count++] = *x;
      inside.remove_prefix(n);
    }
    return count == minCount || count == maxCount;
  }

  bool atEnd() {
    skipBlanks();
    return rest_.empty();
  }

 private:
  void skipBlanks() {
    while (!rest_.empty() && isBlank(rest_.front())) rest_.remove_prefix(1);
  }
  std::string_view rest_;
};

// The "6d" line after its keyword. False when malformed; `head` set when the head body is listed
// and tracked with a valid rotation (left empty when it is absent or untracked).
bool parse6d(std::string_view text, int headBody, std::optional<RawTrackerPose>& head,
             bool& headListed) {
  BlockReader in(text);
  const std::optional<std::string_view> countWord = in.word();
  const std::optional<int> count = countWord ? parseCount(*countWord) : std::nullopt;
  if (!count) return false;
  for (int i = 0; i < *count; ++i) {
    double idQuality[2] = {}, location[6] = {}, columns[9] = {};
    if (!in.block(idQuality, 2, 2) || !in.block(location, 3, 6) || !in.block(columns, 9, 9))
      return false;
    const double id = idQuality[0];
    if (id < 0 || std::floor(id) != id) return false;
    if (id != headBody) continue;
    if (headListed) return false;  // the same body twice in one frame
    headListed = true;
    if (idQuality[1] < 0) continue;  // listed but not tracked
    const std::optional<glm::dquat> rotation = rotationFromColumns(columns);
    if (!rotation) return false;
    head = RawTrackerPose{{location[0], location[1], location[2]}, *rotation, std::nullopt};
  }
  return in.atEnd();
}

std::optional<RawTrackerPose> parseJsonLine(std::string_view line) {
  if (line.size() > kMaxJsonLineBytes) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::nullopt;  // also a parse error (discarded)
  for (const auto& item : j.items())
    if (item.key() != "t" && item.key() != "pos" && item.key() != "quat") return std::nullopt;
  const auto numbers = [&](const char* key, std::size_t n, double* out) {
    if (!j.contains(key)) return false;
    const nlohmann::json& a = j.at(key);
    if (!a.is_array() || a.size() != n) return false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!a[i].is_number()) return false;
      out[i] = a[i].get<double>();
      if (!std::isfinite(out[i])) return false;
    }
    return true;
  };
  double pos[3] = {}, quat[4] = {}, t = 0;
  if (!numbers("pos", 3, pos) || !numbers("quat", 4, quat)) return std::nullopt;
  RawTrackerPose pose;
  if (j.contains("t")) {
    if (!j.at("t").is_number()) return std::nullopt;
    t = j.at("t").get<double>();
    if (!std::isfinite(t)) return std::nullopt;
    pose.seconds = t;
  }
  const glm::dquat q(quat[3], quat[0], quat[1], quat[2]);  // sent as [x, y, z, w]
  const double length = glm::length(q);
  if (!(std::abs(length - 1.0) <= 0.1)) return std::nullopt;
  pose.position = {pos[0], pos[1], pos[2]};
  pose.orientation = q / length;
  return pose;
}

}  // namespace

std::optional<glm::dquat> rotationFromColumns(const double (&c)[9], double tolerance) {
  for (const double x : c)
    if (!std::isfinite(x)) return std::nullopt;
  const glm::dmat3 m(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]);  // column-major
  const glm::dmat3 gram = glm::transpose(m) * m;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(gram[i][k] - (i == k ? 1.0 : 0.0)) <= tolerance)) return std::nullopt;
  if (!(glm::determinant(m) > 0.0)) return std::nullopt;  // a reflection
  return glm::normalize(glm::quat_cast(m));
}

std::optional<RawTrackerPose> parseDTrackFrame(std::string_view datagram, int headBody) {
  if (datagram.size() > kMaxDatagramBytes) return std::nullopt;
  const auto lines = splitLines(datagram);
  if (!lines) return std::nullopt;
  std::optional<double> timestamp;
  std::optional<RawTrackerPose> head;
  bool sawFrame = false, sawBodies = false, headListed = false;
  for (const std::string_view line : *lines) {
    const std::size_t space = line.find_first_of(" \t");
    const std::string_view keyword = line.substr(0, space);
    const std::string_view rest = space == std::string_view::npos ? "" : line.substr(space + 1);
    if (keyword == "fr") {
      if (sawFrame || !parseCount(rest)) return std::nullopt;
      sawFrame = true;
    } else if (keyword == "ts") {
      if (timestamp) return std::nullopt;
      timestamp = detail::parseNumber(rest);
      if (!timestamp) return std::nullopt;
    } else if (keyword == "6d") {
      if (sawBodies || !parse6d(rest, headBody, head, headListed)) return std::nullopt;
      sawBodies = true;
    }
    // Other records (6dcal, 6df2, 3d, gl, 6di, ...) carry no head pose.
  }
  if (head) head->seconds = timestamp;
  return head;
}

std::vector<std::optional<RawTrackerPose>> parseJsonLines(std::string_view datagram) {
  if (datagram.size() > kMaxDatagramBytes) return {std::nullopt};
  std::vector<std::optional<RawTrackerPose>> poses;
  std::size_t start = 0, lineCount = 0;
  while (start <= datagram.size()) {
    const std::size_t end = std::min(datagram.find('\n', start), datagram.size());
    const std::string_view line = trimmed(datagram.substr(start, end - start));
    start = end + 1;
    if (line.empty()) continue;
    if (++lineCount > kMaxLinesPerDatagram) return {std::nullopt};
    poses.push_back(parseJsonLine(line));
  }
  return poses;
}

}  // namespace confvis
