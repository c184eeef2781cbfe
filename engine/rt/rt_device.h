#pragma once
// RAII owner of an Embree 3 device. Embree reports errors through a C callback, from which no
// C++ exception may propagate; the callback therefore logs and records the error, and check()
// turns a pending error into a diptych::Error naming the Embree error code and the operation.
#include <embree3/rtcore.h>

#include <memory>
#include <string>

namespace diptych {

namespace detail {
struct EmbreeErrorState;  // the error callback's user data (rt_device.cpp)
}

// "RTC_ERROR_INVALID_ARGUMENT" etc.; "RTC_ERROR_<n>" for codes this build does not know.
std::string embreeErrorName(RTCError code);

class RtDevice {
 public:
  // config is Embree's device configuration string (e.g. "threads=4"); empty = defaults.
  // Throws Error when the device cannot be created.
  explicit RtDevice(const std::string& config = {});
  ~RtDevice();
  RtDevice(const RtDevice&) = delete;
  RtDevice& operator=(const RtDevice&) = delete;

  RTCDevice handle() const { return device_; }

  // Throws Error("Embree error RTC_ERROR_...: <message> (during <what>)") if an error is
  // pending on this device, and clears it.
  void check(const std::string& what) const;

 private:
  RTCDevice device_ = nullptr;
  std::unique_ptr<detail::EmbreeErrorState> errors_;  // callback user pointer; stable address
};

}  // namespace diptych
