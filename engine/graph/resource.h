#pragma once
// Typed virtual resources of the frame graph. A resource is a 2D image (optionally layered)
// whose storage lives in the domain of its writer: a GL texture or a CPU Surface. The compiler
// inserts transfer nodes where a reader lives in the other domain.
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/math.h"

namespace diptych {

enum class Domain { Gl, Cpu };
const char* domainName(Domain d);

enum class Format { R32F, RG32F, RGBA32F, R32UI, RGBA32UI, D32F };
const char* formatName(Format f);
int formatChannels(Format f);
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

// CPU storage: 32-bit words, interpreted as float or uint by the format. Pixel (x, y) with
// y = 0 the top row; layers stored one after another.
struct Surface {
  ResourceDesc desc;
  std::vector<std::uint32_t> words;

  Surface() = default;
  explicit Surface(const ResourceDesc& d) : desc(d), words(d.bytes() / 4, 0u) {}
  std::size_t index(int x, int y, int c, int layer = 0) const {
    return ((std::size_t(layer) * desc.height + y) * desc.width + x) * formatChannels(desc.format) +
           c;
  }
  float f(int x, int y, int c, int layer = 0) const {
    return std::bit_cast<float>(words[index(x, y, c, layer)]);
  }
  void setF(int x, int y, int c, float v, int layer = 0) {
    words[index(x, y, c, layer)] = std::bit_cast<std::uint32_t>(v);
  }
  std::uint32_t u(int x, int y, int c, int layer = 0) const { return words[index(x, y, c, layer)]; }
  void setU(int x, int y, int c, std::uint32_t v, int layer = 0) {
    words[index(x, y, c, layer)] = v;
  }
  // Fills every texel with `value` (channel c takes value[c]; floats or uints per format).
  void fill(const vec4& value);
  Image toImage(int layer = 0) const;  // float formats only
};

}  // namespace diptych
