#include "confvis/backends/embree/embree_device.hpp"

#include "confvis/base/error.hpp"

namespace confvis {

const char* toString(RTCError code) noexcept {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "unrecognised error";
}

EmbreeDevice::EmbreeDevice(const std::string& config) {
  device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!device_) {
    const RTCError code = rtcGetDeviceError(nullptr);
    throw Error(ErrorCode::DeviceUnsupported,
                std::string("Embree could not create a device: ") + toString(code) +
                    (config.empty() ? "" : " (config '" + config + "')"));
  }
  rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
  auto* device = static_cast<EmbreeDevice*>(self);
  std::lock_guard lock(device->mutex_);
  if (device->firstError_ != RTC_ERROR_NONE) return;  // the first error explains the rest
  device->firstError_ = code;
  device->firstMessage_ = message ? message : "";
}

void EmbreeDevice::check(const std::string& operation) {
  // Errors reported without the callback (none expected) are still visible here.
  const RTCError pending = rtcGetDeviceError(device_);
  std::lock_guard lock(mutex_);
  RTCError code = firstError_;
  if (code == RTC_ERROR_NONE) code = pending;
  if (code == RTC_ERROR_NONE) return;
  const std::string message = "Embree failed in " + operation + ": " + toString(code) +
                              (firstMessage_.empty() ? "" : " (" + firstMessage_ + ")");
  firstError_ = RTC_ERROR_NONE;
  firstMessage_.clear();
  throw Error(code == RTC_ERROR_INVALID_ARGUMENT ? ErrorCode::InvalidInput
              : code == RTC_ERROR_UNSUPPORTED_CPU ? ErrorCode::DeviceUnsupported
                                                   : ErrorCode::Internal,
              message);
}

}  // namespace confvis
