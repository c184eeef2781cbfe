#pragma once
// Typed virtual resources of the frame graph. A resource is a 2D image (optionally layered)
// whose storage lives in the domain of its writer: a GL texture or a CpuImage
// (engine/graph/cpu_image.h). The compiler inserts transfer nodes where a reader lives in the
// other domain.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/math.h"

namespace diptych {

enum class Domain { Gl, Cpu };
const char* domainName(Domain d);

enum class Format { R32F, RG32F, RGBA32F, R32UI, RGBA32UI, D32F };
const char* formatName(Format f);
// Inline: CpuImage's per-texel accessors call it on every read and write.
constexpr int formatChannels(Format f) {
  return f == Format::RG32F ? 2 : (f == Format::RGBA32F || f == Format::RGBA32UI) ? 4 : 1;
}
bool formatIsInteger(Format f);

struct ResourceDesc {
  Format format = Format::RGBA32F;
  int width = 0, height = 0;
  int layers = 1;
  bool operator==(const ResourceDesc&) const = default;
  std::size_t bytes() const {
    return std::size_t(width) * height * layers * formatChannels(format) * 4;
  }
};
std::string describe(const ResourceDesc& d);  // "RGBA32F 640x480x1"

}  // namespace diptych
