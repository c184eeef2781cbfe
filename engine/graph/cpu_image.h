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
  int channels() const { return formatChannels(desc.format); }
  // Row y of `layer` as raw words (texel x's channel c at [x * channels() + c]): per-pixel loops
  // take it once per row, where f/setF recompute the format's stride and the index every call.
  const std::uint32_t* row(int y, int layer = 0) const {
    return words.data() + index(0, y, 0, layer);
  }
  std::uint32_t* row(int y, int layer = 0) { return words.data() + index(0, y, 0, layer); }
  // Fills every texel with `value` (channel c takes value[c]; floats or uints per format).
  void fill(const vec4& value);
  Image toImage(int layer = 0) const;  // float formats only
};

// One row of a float image read as CpuImage::f reads it; a null image reads as zero (the
// optional inputs of a pass). For per-pixel loops: the row address and stride are taken once.
class CpuFloatRow {
 public:
  CpuFloatRow(const CpuImage* image, int y, int layer = 0)
      : words_(image ? image->row(y, layer) : nullptr), channels_(image ? image->channels() : 0) {}
  explicit operator bool() const { return words_ != nullptr; }
  float operator()(int x, int c) const {
    return words_ ? std::bit_cast<float>(words_[std::size_t(x) * channels_ + c]) : 0.f;
  }
  vec3 rgb(int x) const { return vec3((*this)(x, 0), (*this)(x, 1), (*this)(x, 2)); }

 private:
  const std::uint32_t* words_;
  std::size_t channels_;
};

}  // namespace diptych
