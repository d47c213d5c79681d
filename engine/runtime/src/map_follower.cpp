#include "confvis/runtime/map_follower.hpp"

#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// A map is accepted only around the reference it was asked for, else a mis-wired bake (one
// ignoring the reference) would re-bake every frame without ever catching up with the head.
constexpr double kSameReference = 1e-9;

std::string describe(const glm::dvec3& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

void checkBakedMap(const RetargetMap& map, const glm::dvec3& reference) {
  if (map.ray.faceSize <= 0 || map.geom.faceSize <= 0)
    throw Error(ErrorCode::Internal, "the bake returned an empty map");
  if (!(glm::length(map.reference - reference) <= kSameReference))
    throw Error(ErrorCode::Internal, "the bake returned a map around " + describe(map.reference) +
                                         " instead of " + describe(reference));
}

}  // namespace

struct MapFollower::Shared {
  std::mutex mutex;
  std::condition_variable idle;
  bool running = false;
  glm::dvec3 reference{0.0};                  // of the running or last bake
  std::shared_ptr<const RetargetMap> result;  // a finished bake not yet swapped in
  std::shared_ptr<const DisplayConfig> display;  // the config `result` was baked for
  std::optional<std::string> error;           // a failed bake not yet reported
};

DisplayConfig withReference(const DisplayConfig& config, const glm::dvec3& reference) {
  nlohmann::json json = toJson(config);
  json["reference"] = {reference.x, reference.y, reference.z};
  return parseDisplayConfig(json, config.name);
}

MapFollower::MapFollower(DisplayConfig config, BakeFunction bake, MapFollowerOptions options)
    : config_(std::move(config)), bake_(std::move(bake)), options_(options),
      shared_(std::make_shared<Shared>()) {
  if (!bake_) throw Error(ErrorCode::InvalidInput, "MapFollower needs a bake function");
  RetargetMap first = bake_(config_, config_.reference);
  checkBakedMap(first, config_.reference);
  reference_ = config_.reference;
  current_ = std::make_shared<const RetargetMap>(std::move(first));
  currentDisplay_ = std::make_shared<const DisplayConfig>(config_);
}

MapFollower::MapFollower(DisplayConfig config, RetargetMap initial, BakeFunction bake,
                         MapFollowerOptions options)
    : config_(std::move(config)), bake_(std::move(bake)), options_(options),
      shared_(std::make_shared<Shared>()) {
  if (!bake_) throw Error(ErrorCode::InvalidInput, "MapFollower needs a bake function");
  reference_ = initial.reference;
  checkBakedMap(initial, reference_);
  current_ = std::make_shared<const RetargetMap>(std::move(initial));
  currentDisplay_ = std::make_shared<const DisplayConfig>(
      reference_ == config_.reference ? config_ : withReference(config_, reference_));
}

MapFollower::~MapFollower() {
  if (worker_.joinable()) worker_.join();
}

void MapFollower::startBake(const glm::dvec3& reference) {
  {
    const std::lock_guard lock(shared_->mutex);
    shared_->running = true;
    shared_->reference = reference;
  }
  ++stats_.bakesStarted;
  // The thread owns copies of everything it touches, and the shared state through a shared_ptr.
  worker_ = std::thread([shared = shared_, bake = bake_, config = config_, reference] {
    std::shared_ptr<const RetargetMap> result;
    std::shared_ptr<const DisplayConfig> display;
    std::optional<std::string> error;
    try {
      auto moved = std::make_shared<const DisplayConfig>(withReference(config, reference));
      RetargetMap map = bake(*moved, reference);
      checkBakedMap(map, reference);
      result = std::make_shared<const RetargetMap>(std::move(map));
      display = std::move(moved);
    } catch (const std::exception& e) {
      error = e.what();
    } catch (...) {
      error = "unknown exception";
    }
    const std::lock_guard lock(shared->mutex);
    shared->result = std::move(result);
    shared->display = std::move(display);
    shared->error = std::move(error);
    shared->running = false;
    shared->idle.notify_all();
  });
}

void MapFollower::collectFinishedBake(FollowerFrame& frame) {
  std::shared_ptr<const RetargetMap> result;
  std::shared_ptr<const DisplayConfig> display;
  std::optional<std::string> error;
  glm::dvec3 bakedAt;
  {
    const std::lock_guard lock(shared_->mutex);
    frame.baking = shared_->running;
    if (shared_->running || !worker_.joinable()) return;
    result = std::move(shared_->result);
    display = std::move(shared_->display);
    error = std::move(shared_->error);
    bakedAt = shared_->reference;
  }
  worker_.join();  // the thread has finished its bake; it is only returning
  if (result) {
    current_ = std::move(result);
    currentDisplay_ = std::move(display);
    reference_ = bakedAt;
    ++generation_;
    ++stats_.bakesSucceeded;
    failedReference_.reset();
    frame.swapped = true;
  } else {
    ++stats_.bakesFailed;
    failedReference_ = bakedAt;
    errors_.push_back("re-bake around " + describe(bakedAt) + " failed: " +
                      error.value_or("no map"));
  }
}

FollowerFrame MapFollower::beginFrame(const HeadPose& head) {
  FollowerFrame frame;
  collectFinishedBake(frame);
  const glm::dvec3 p = head.position;
  const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  const bool strayed = finite && glm::length(p - reference_) > options_.radius;
  const bool retry =
      !failedReference_ || glm::length(p - *failedReference_) > options_.radius;
  if (!frame.baking && strayed && retry) {
    startBake(p);
    frame.baking = true;
  }
  frame.map = current_;
  frame.display = currentDisplay_;
  frame.generation = generation_;
  return frame;
}

std::vector<std::string> MapFollower::takeErrors() {
  std::vector<std::string> taken;
  taken.swap(errors_);
  return taken;
}

void MapFollower::waitForBake() {
  std::unique_lock lock(shared_->mutex);
  shared_->idle.wait(lock, [&] { return !shared_->running; });
}

}  // namespace confvis
