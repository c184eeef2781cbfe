#pragma once
// CPU <-> GL texture transfers, used by the frame graph's readback and upload nodes.
// Data is one 32-bit word per component, row-major with row 0 the TOP of the image (the
// engine's image convention; GL's row 0 is the bottom, so rows are flipped here):
//   float, half and normalized formats: the float32 bits of each component;
//   R32UI, RGBA32UI: the unsigned integer;  D32F: the depth as float32 bits.
// SRGB8_ALPHA8 transfers its stored (encoded) values; no sRGB conversion is applied.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/gl/objects.h"

namespace diptych::gl {

// Words per texel row/column: width * height * formatInfo(format).components.
std::size_t texelWordCount(const Texture& texture, int level = 0);

// `layer`: array layer, or cube face in GL order (+x, -x, +y, -y, +z, -z); 0 for 2D.
std::vector<std::uint32_t> readTexture(const Texture& texture, int layer = 0, int level = 0);
// The same into caller storage of exactly texelWordCount(texture, level) words (no copy).
void readTextureInto(const Texture& texture, std::span<std::uint32_t> words, int layer = 0,
                     int level = 0);
// Top row first, as readTexture returns it; exactly texelWordCount(texture, level) words.
void uploadTexture(const Texture& texture, std::span<const std::uint32_t> words, int layer = 0,
                   int level = 0);

// Convenience views of the same data for float formats.
std::vector<float> readTextureFloats(const Texture& texture, int layer = 0, int level = 0);
void uploadTextureFloats(const Texture& texture, const std::vector<float>& values, int layer = 0,
                         int level = 0);

}  // namespace diptych::gl
