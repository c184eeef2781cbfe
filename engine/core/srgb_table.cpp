#include "engine/core/srgb_table.h"

namespace diptych {

SrgbByteDecoder::SrgbByteDecoder() {
  for (int k = 0; k < 256; ++k) {
    const float multiplied = float(k) * (1.f / 255.f), divided = float(k) / 255.f;
    multipliedBits_[std::size_t(k)] = std::bit_cast<std::uint32_t>(multiplied);
    dividedBits_[std::size_t(k)] = std::bit_cast<std::uint32_t>(divided);
    fromMultiplied_[std::size_t(k)] = srgbToLinear(multiplied);
    fromDivided_[std::size_t(k)] = srgbToLinear(divided);
  }
}

const SrgbByteDecoder& SrgbByteDecoder::instance() {
  static const SrgbByteDecoder decoder;
  return decoder;
}

}  // namespace diptych
