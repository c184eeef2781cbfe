#pragma once
// The CPU storage of a frame-graph resource (the GL side is a gl::Texture): 32-bit words,
// interpreted as float or uint by the format. Not to be confused with SurfacePoint
// (engine/rt/surface_point.h), a shading point on the scene.
#include <bit>
#include <cstdint>
#include <vector>

#include "engine/core/image.h"
#include "engine/graph/resource.h"

namespace diptych {

// Pixel (x, y) with y = 0 the top row; layers stored one after another.
struct CpuImage {
  ResourceDesc desc;
  std::vector<std::uint32_t> words;

  CpuImage() = default;
  explicit CpuImage(const ResourceDesc& d) : desc(d), words(d.bytes() / 4, 0u) {}
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
