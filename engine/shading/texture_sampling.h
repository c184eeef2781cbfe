#pragma once
// CPU texture lookups for ray-traced hits, matching OpenGL's sampling rules (OpenGL 4.5 core
// spec, section 8.14 "Texture Minification" and 8.15 "Texture Magnification"): texel centres at
// (i + 0.5) / size, wrap modes applied to integer texel indices, bilinear weights from the
// fractional part. uv follows glTF: (0, 0) is the top-left of the image (Image row 0), so
// y = v * height with no flip. No mipmaps yet: ray cones will pick a level later.
#include "engine/scene/scene.h"

namespace diptych {

// Texel index i (any integer) mapped into [0, size) by the wrap mode.
int wrapTexel(int i, int size, WrapMode mode);

// RGBA at uv. `minifying` picks the texture's minFilter (its mip part ignored) instead of the
// magFilter; without a footprint the caller normally passes false. An empty image gives
// (1, 1, 1, 1), the neutral factor.
vec4 sampleTexture(const Texture& texture, vec2 uv, bool minifying = false);
vec4 sampleNearest(const Image& image, vec2 uv, WrapMode wrapS, WrapMode wrapT);
vec4 sampleBilinear(const Image& image, vec2 uv, WrapMode wrapS, WrapMode wrapT);

// Procedural checker: colorA where floor(u * scale) + floor(v * scale) is even, else colorB.
vec3 checkerColor(const Checker& checker, vec2 uv);

}  // namespace diptych
