#pragma once
// sRGB decoding (IEC 61966-2-1) of 8-bit values by table: a texture's colour channels decode
// one pow per texel otherwise (engine/scene/gltf/materials.cpp), and an 8-bit image has only
// 256 distinct values.

namespace diptych {

// srgbToLinear(encoded) (engine/core/image.h), read from a 256-entry table built with
// srgbToLinear when `encoded` is exactly k / 255.f, or exactly k * (1.f / 255) as readImage's
// 8-bit conversion writes it, for an integer k in 0..255; any other value goes to srgbToLinear.
// Bit-identical to srgbToLinear for every input.
float srgbToLinearFromByteValue(float encoded);

// The k / 255.f table: entry k is srgbToLinear(k / 255.f).
const float* srgbToLinearByteTable();

}  // namespace diptych
