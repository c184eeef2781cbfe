#pragma once
// What ran a measurement: the GL driver (llvmpipe is a CPU rasterizer, so raster timings mean
// something else there), the CPU and the Embree build. Every timing output carries it.
#include <nlohmann/json.hpp>
#include <string>

namespace diptych {

namespace gl {
class GlContext;
}

// {"gl": {vendor, renderer, version, context} | null, "cpu": {model, threads, isa},
//  "embree": {version, native_packets}}. `context` may be null (a CPU-only run).
nlohmann::json describeDevices(const gl::GlContext* context);

// One line for logs and tables: "GL: llvmpipe (LLVM 15.0.6, 256 bits) via osmesa | CPU: ... x2 |
// Embree 3.13.5".
std::string deviceSummary(const nlohmann::json& devices);

}  // namespace diptych
