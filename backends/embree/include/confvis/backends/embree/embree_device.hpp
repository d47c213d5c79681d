#pragma once
// An Embree device whose errors become confvis::Error at the boundary: Embree reports errors
// through a C callback, which records them; check() turns the recorded error into an exception
// naming the operation that failed.
#include <embree3/rtcore.h>

#include <mutex>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: Embree calls onError from any thread (recorded under a mutex); check() from one
// thread at a time, the thread that drives the device.
class EmbreeDevice {
 public:
  // Throws Error(DeviceUnsupported) when Embree cannot create a device (e.g. unsupported CPU).
  explicit EmbreeDevice(const std::string& config = "");
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice handle() const { return device_; }
  // Throws Error(Internal, or InvalidInput for invalid arguments) naming `operation` when Embree
  // has reported an error since the last check; clears it.
  void check(const std::string& operation);

 private:
  static void onError(void* self, RTCError code, const char* message);

  RTCDevice device_ = nullptr;
  std::mutex mutex_;
  RTCError firstError_ = RTC_ERROR_NONE;
  std::string firstMessage_;
};

const char* toString(RTCError code) noexcept;

}  // namespace confvis
