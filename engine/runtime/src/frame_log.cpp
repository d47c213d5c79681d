#include "confvis/runtime/frame_log.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace confvis {

FrameTimeSummary summarize(const std::vector<double>& frameSeconds) {
  FrameTimeSummary s;
  s.frames = static_cast<int>(frameSeconds.size());
  if (frameSeconds.empty()) return s;
  std::vector<double> sorted = frameSeconds;
  std::sort(sorted.begin(), sorted.end());
  auto rank = [&](double p) {  // nearest rank: the smallest value with >= p % at or below it
    const auto k = static_cast<std::size_t>(std::ceil(p / 100.0 * sorted.size()));
    return sorted[std::clamp<std::size_t>(k, 1, sorted.size()) - 1];
  };
  s.meanSeconds = std::accumulate(sorted.begin(), sorted.end(), 0.0) / sorted.size();
  s.p50Seconds = rank(50.0);
  s.p99Seconds = rank(99.0);
  s.maxSeconds = sorted.back();
  return s;
}

FrameTimeSummary FrameLog::summary() const {
  std::vector<double> times;
  for (const FrameRecord& r : records_) times.push_back(r.frameSeconds);
  return summarize(times);
}

FrameTimeSummary FrameLog::summary(bool baking) const {
  std::vector<double> times;
  for (const FrameRecord& r : records_)
    if (r.bakeInFlight == baking) times.push_back(r.frameSeconds);
  return summarize(times);
}

nlohmann::json toJson(const FrameTimeSummary& s) {
  return {{"frames", s.frames},
          {"mean_ms", s.meanSeconds * 1e3},
          {"p50_ms", s.p50Seconds * 1e3},
          {"p99_ms", s.p99Seconds * 1e3},
          {"max_ms", s.maxSeconds * 1e3}};
}

nlohmann::json FrameLog::toJson() const {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t i = 0; i < records_.size(); ++i) {
    const FrameRecord& r = records_[i];
    frames.push_back({{"frame", i},
                      {"ms", r.frameSeconds * 1e3},
                      {"render_ms", r.renderSeconds * 1e3},
                      {"present_ms", r.presentSeconds * 1e3},
                      {"map_generation", r.mapGeneration},
                      {"bake_in_flight", r.bakeInFlight},
                      {"bake_started", r.bakeStarted},
                      {"map_swapped", r.mapSwapped},
                      {"mode", r.conformal ? "conformal" : "plain"},
                      {"head", r.head},
                      {"windows_presented", r.windowsPresented}});
  }
  return {{"frames", frames},
          {"frame_time", confvis::toJson(summary())},
          {"frame_time_baking", confvis::toJson(summary(true))},
          {"frame_time_not_baking", confvis::toJson(summary(false))}};
}

}  // namespace confvis
