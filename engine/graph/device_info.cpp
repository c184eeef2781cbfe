#include "engine/graph/device_info.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <fstream>
#include <thread>

#include "engine/gl/context.h"
#include "engine/rt/rt_device.h"

namespace diptych {
namespace {

// The first "model name" and "flags" lines of /proc/cpuinfo (Linux); empty elsewhere.
std::pair<std::string, std::string> cpuModelAndFlags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model, flags;
  auto value = [](const std::string& l) {
    const auto colon = l.find(':');
    return colon == std::string::npos ? std::string()
                                      : l.substr(l.find_first_not_of(" \t", colon + 1));
  };
  while (std::getline(in, line) && (model.empty() || flags.empty())) {
    if (model.empty() && line.rfind("model name", 0) == 0) model = value(line);
    if (flags.empty() && line.rfind("flags", 0) == 0) flags = " " + value(line) + " ";
  }
  return {model, flags};
}

// The widest vector ISA the CPU offers that Embree 3 has kernels for.
std::string widestIsa(const std::string& flags) {
  for (const char* isa : {"avx512f", "avx2", "avx", "sse4_2"})
    if (flags.find(std::string(" ") + isa + " ") != std::string::npos) return isa;
  return "sse2";
}

}  // namespace

nlohmann::json loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0, fifteen = 0;
  if (!(in >> one >> five >> fifteen)) return nullptr;
  return {one, five, fifteen};
}

nlohmann::json describeDevices(const gl::GlContext* context) {
  nlohmann::json out;
  if (context) {
    const gl::ContextInfo& info = context->info();
    out["gl"] = {{"vendor", info.vendor},
                 {"renderer", info.renderer},
                 {"version", info.version},
                 {"context", std::string(context->name())}};
  } else {
    out["gl"] = nullptr;
  }
  const auto [model, flags] = cpuModelAndFlags();
  out["cpu"] = {{"model", model.empty() ? "unknown" : model},
                {"threads", std::thread::hardware_concurrency()},
                {"isa", widestIsa(flags)},
                {"load_average", loadAverage()}};
  RtDevice device;
  auto property = [&](RTCDeviceProperty p) { return rtcGetDeviceProperty(device.handle(), p); };
  nlohmann::json packets = nlohmann::json::array();
  if (property(RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) packets.push_back(4);
  if (property(RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) packets.push_back(8);
  if (property(RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) packets.push_back(16);
  out["embree"] = {{"version", fmt::format("{}.{}.{}", property(RTC_DEVICE_PROPERTY_VERSION_MAJOR),
                                           property(RTC_DEVICE_PROPERTY_VERSION_MINOR),
                                           property(RTC_DEVICE_PROPERTY_VERSION_PATCH))},
                   {"native_packets", packets}};
  return out;
}

std::string deviceSummary(const nlohmann::json& d) {
  std::string gl = "none";
  if (!d["gl"].is_null())
    gl = fmt::format("{} ({}) via {}", d["gl"]["renderer"].get<std::string>(),
                     d["gl"]["version"].get<std::string>(), d["gl"]["context"].get<std::string>());
  // The 1-minute load when measured: other work on the cores stretches every timing.
  const nlohmann::json load = d["cpu"].value("load_average", nlohmann::json());
  const std::string loadText =
      load.is_array() && !load.empty() ? fmt::format(", load {:.2f}", load[0].get<double>()) : "";
  return fmt::format("GL: {} | CPU: {}, {} threads, {}{} | Embree {}", gl,
                     d["cpu"]["model"].get<std::string>(), d["cpu"]["threads"].get<unsigned>(),
                     d["cpu"]["isa"].get<std::string>(), loadText,
                     d["embree"]["version"].get<std::string>());
}

}  // namespace diptych
