#include "engine/rt/rt_device.h"

#include <mutex>

#include "engine/core/error.h"
#include "engine/core/log.h"

namespace diptych {

namespace detail {
struct EmbreeErrorState {
  std::mutex mutex;
  std::string lastMessage;  // of the most recent error; the code comes from rtcGetDeviceError
};
}  // namespace detail

namespace {

// Embree calls this on the failing thread. It is a C callback: it must not throw, so it only
// logs and records; RtDevice::check() raises the C++ error at a well-defined point.
void onEmbreeError(void* user, RTCError code, const char* message) {
  const std::string text = message ? message : "";
  log().error("Embree error {}: {}", embreeErrorName(code), text);
  if (auto* state = static_cast<detail::EmbreeErrorState*>(user)) {
    std::lock_guard lock(state->mutex);
    state->lastMessage = text;
  }
}

}  // namespace

std::string embreeErrorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
      return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
      return "RTC_ERROR_CANCELLED";
  }
  return "RTC_ERROR_" + std::to_string(int(code));
}

RtDevice::RtDevice(const std::string& config)
    : errors_(std::make_unique<detail::EmbreeErrorState>()) {
  device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!device_) {
    // Without a device the error is reported on the null device (Embree 3 rtcNewDevice docs).
    throw Error("Embree error " + embreeErrorName(rtcGetDeviceError(nullptr)) +
                ": cannot create a device with config '" + config + "'");
  }
  rtcSetDeviceErrorFunction(device_, onEmbreeError, errors_.get());
}

RtDevice::~RtDevice() {
  if (device_) rtcReleaseDevice(device_);
}

void RtDevice::check(const std::string& what) const {
  const RTCError code = rtcGetDeviceError(device_);
  if (code == RTC_ERROR_NONE) return;
  std::string message;
  {
    std::lock_guard lock(errors_->mutex);
    message.swap(errors_->lastMessage);
  }
  throw Error("Embree error " + embreeErrorName(code) + (message.empty() ? "" : ": " + message) +
              " (during " + what + ")");
}

}  // namespace diptych
