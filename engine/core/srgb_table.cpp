#include "engine/core/srgb_table.h"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "engine/core/image.h"

namespace diptych {
namespace {

// An 8-bit value k reaches us as a float written one of two ways: k / 255.f, or k * (1.f / 255)
// as OpenImageIO's convert_type<uint8_t, float> (fmath.h) does; the two differ in the last bit
// for some k. Each gets its own entries, each srgbToLinear of that exact float.
struct ByteTables {
  std::array<std::uint32_t, 256> divided{}, multiplied{};  // the keys' bits
  std::array<float, 256> fromDivided{}, fromMultiplied{};
};

const ByteTables& byteTables() {
  static const ByteTables tables = [] {
    ByteTables t;
    for (int k = 0; k < 256; ++k) {
      const float divided = float(k) / 255.f, multiplied = float(k) * (1.f / 255.f);
      t.divided[std::size_t(k)] = std::bit_cast<std::uint32_t>(divided);
      t.multiplied[std::size_t(k)] = std::bit_cast<std::uint32_t>(multiplied);
      t.fromDivided[std::size_t(k)] = srgbToLinear(divided);
      t.fromMultiplied[std::size_t(k)] = srgbToLinear(multiplied);
    }
    return t;
  }();
  return tables;
}

}  // namespace

const float* srgbToLinearByteTable() {
  return byteTables().fromDivided.data();
}

float srgbToLinearFromByteValue(float c) {
  // c * 255 lands within a rounding of k for an 8-bit value; comparing bits then decides, so a
  // value that is not exactly an 8-bit one (16-bit, float, NaN, -0.f) never reads the table.
  const float scaled = c * 255.f;
  if (scaled >= 0.f && scaled <= 255.f) {
    const std::size_t k = std::size_t(scaled + 0.5f);
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(c);
    const ByteTables& t = byteTables();
    if (bits == t.divided[k]) return t.fromDivided[k];
    if (bits == t.multiplied[k]) return t.fromMultiplied[k];
  }
  return srgbToLinear(c);
}

}  // namespace diptych
