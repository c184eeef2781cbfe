#pragma once
// What ran a measurement: the GL driver (llvmpipe is a CPU rasterizer, so raster timings mean
// something else there), the CPU and the Embree build. Every timing output carries it.
#include <nlohmann/json.hpp>
#include <string>

namespace diptych {

namespace gl {
class GlContext;
}

// {"gl": {vendor, renderer, version, context} | null, "cpu": {model, threads, isa, load_average},
//  "embree": {version, native_packets}}. `context` may be null (a CPU-only run).
nlohmann::json describeDevices(const gl::GlContext* context);

// The system's load average over 1, 5 and 15 minutes (/proc/loadavg; null where there is none):
// processes waiting for the cores, this one included. A figure measured under load > ~0.5 per
// core shares its cores with other work.
nlohmann::json loadAverage();

// One line for logs and tables: "GL: llvmpipe (LLVM 15.0.6, 256 bits) via osmesa | CPU: ... x2 |
// Embree 3.13.5" (with ", load L" after the CPU where the load average is known).
std::string deviceSummary(const nlohmann::json& devices);

}  // namespace diptych
