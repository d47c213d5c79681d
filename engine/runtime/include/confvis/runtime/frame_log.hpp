#pragma once
// What a live display's frames took, one record per frame, and the summary view.json reports:
// frame time mean / p50 / p99 over all frames, over those with a re-bake in flight and over
// those without (a bake must never hold a frame up: tests compare the two).
#include <array>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

struct FrameRecord {
  double frameSeconds = 0.0;    // start of this frame to the start of the next (or the end)
  double renderSeconds = 0.0;   // the backend's renderInto calls
  double presentSeconds = 0.0;  // composing, uploading and presenting every window
  std::uint64_t mapGeneration = 0;
  bool bakeInFlight = false;    // a re-bake ran in the background during the frame
  bool bakeStarted = false;     // this frame started it
  bool mapSwapped = false;      // this frame is the first with a new map
  bool conformal = true;
  // The head position the frame rendered every eye's off-axis view from (physical frame, m).
  std::array<double, 3> head{0.0, 0.0, 0.0};
  int windowsPresented = 0;     // windows that showed the frame (a minimised one shows none)
};

struct FrameTimeSummary {
  int frames = 0;
  double meanSeconds = 0.0, p50Seconds = 0.0, p99Seconds = 0.0, maxSeconds = 0.0;
};

// Nearest-rank percentiles (p in [0, 100]) of the frame times; all zero for no frames.
FrameTimeSummary summarize(const std::vector<double>& frameSeconds);

// Thread-safety: not thread-safe; one thread adds records (the frame loop); const members may
// be called from any number of threads while none adds.
class FrameLog {
 public:
  void add(const FrameRecord& record) { records_.push_back(record); }
  const std::vector<FrameRecord>& records() const { return records_; }
  // Frames whose bakeInFlight equals `baking`.
  FrameTimeSummary summary() const;
  FrameTimeSummary summary(bool baking) const;
  // {"frames": [...per frame...], "frame_time": {...}, "frame_time_baking": {...},
  //  "frame_time_not_baking": {...}} in milliseconds.
  nlohmann::json toJson() const;

 private:
  std::vector<FrameRecord> records_;
};

nlohmann::json toJson(const FrameTimeSummary& summary);

}  // namespace confvis
