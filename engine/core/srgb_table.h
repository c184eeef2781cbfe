#pragma once
// sRGB decoding (IEC 61966-2-1) of 8-bit values by table: a texture's colour channels decode
// one pow per texel otherwise (engine/scene/gltf/materials.cpp), and an 8-bit image has only
// 256 distinct values.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "engine/core/image.h"

namespace diptych {

// srgbToLinear(encoded) (engine/core/image.h), read from a 256-entry table built with
// srgbToLinear when `encoded` is exactly k * (1.f / 255), as readImage's 8-bit conversion
// (OpenImageIO's convert_type<uint8_t, float>, fmath.h) writes it, or exactly k / 255.f, for an
// integer k in 0..255 (the two differ in the last bit for some k, so each has its own entries);
// any other value goes to srgbToLinear. Bit-identical to srgbToLinear for every input.
class SrgbByteDecoder {
 public:
  static const SrgbByteDecoder& instance();

  float operator()(float encoded) const {
    // encoded * 255 lands within a rounding of k for an 8-bit value; comparing bits then
    // decides, so a value that is not exactly an 8-bit one (16-bit, float, NaN, -0.f) never
    // reads the table.
    const float scaled = encoded * 255.f;
    if (scaled >= 0.f && scaled <= 255.f) {
      const std::size_t k = std::size_t(scaled + 0.5f);
      const std::uint32_t bits = std::bit_cast<std::uint32_t>(encoded);
      if (bits == multipliedBits_[k]) return fromMultiplied_[k];
      if (bits == dividedBits_[k]) return fromDivided_[k];
    }
    return srgbToLinear(encoded);
  }
  // Entry k is srgbToLinear(k / 255.f).
  const float* dividedTable() const { return fromDivided_.data(); }

 private:
  SrgbByteDecoder();
  std::array<std::uint32_t, 256> multipliedBits_{}, dividedBits_{};
  std::array<float, 256> fromMultiplied_{}, fromDivided_{};
};

inline float srgbToLinearFromByteValue(float encoded) {
  return SrgbByteDecoder::instance()(encoded);
}

}  // namespace diptych
