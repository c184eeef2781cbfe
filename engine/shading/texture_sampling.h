#pragma once
// CPU texture lookups for ray-traced hits, matching OpenGL's sampling rules (OpenGL 4.5 core
// spec, section 8.14 "Texture Minification" and 8.15 "Texture Magnification"): texel centres at
// (i + 0.5) / size, wrap modes applied to integer texel indices, bilinear weights from the
// fractional part. uv follows glTF: (0, 0) is the top-left of the image (Image row 0), so
// y = v * height with no flip. Levels above 0 are the lecture's box-filtered chain
// (engine/scene/mip_chain.h, Texture::mips), the same texels the GL side uploads; level choice
// follows the GL spec (8.14.1 lambda, 8.14.3 mipmapping) and EXT_texture_filter_anisotropic.
// shaders/gl/scene_shading.glsl mirrors these functions line for line (GL/CPU parity test:
// tests/unit/test_texture_parity.cpp).
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

// How many levels a texture has (1 + mips), and level i (0: the image).
int mipLevelCount(const Texture& texture);
const Image& mipLevel(const Texture& texture, int level);

// One filtered lookup at LOD lambda: texels nearest or bilinear within a level; mips None
// (level 0 only), Nearest (GL's d = ceil(lambda + 1/2) - 1) or Linear (levels floor(lambda)
// and floor(lambda) + 1 blended by frac(lambda)), levels clamped to the chain.
enum class MipSelect { None, Nearest, Linear };
vec4 sampleFiltered(const Texture& texture, vec2 uv, float lambda, bool linearTexels,
                    MipSelect mips);

// The texture's own glTF sampler at LOD lambda: magFilter at level 0 when lambda <= 0, else
// minFilter (with its mipmap mode). -infinity is sampleTexture(texture, uv).
vec4 sampleTextureLod(const Texture& texture, vec2 uv, float lambda);

// GL's scale factor (8.14.1, eq. 8.7 with the max of the two derivative lengths):
// lambda = log2(max(|du/dx, dv/dx| * size, |du/dy, dv/dy| * size)); dx, dy are uv derivatives
// per pixel.
float lodFromGradients(const Texture& texture, vec2 dx, vec2 dy);

// Anisotropic filtering as EXT_texture_filter_anisotropic suggests: N = min(ceil(Pmax / Pmin),
// maxAnisotropy) trilinear probes along the longer footprint axis at lambda = log2(Pmax / N),
// averaged.
vec4 sampleAnisotropic(const Texture& texture, vec2 uv, vec2 dx, vec2 dy, int maxAnisotropy);

// Procedural checker: colorA where floor(u * scale) + floor(v * scale) is even, else colorB.
vec3 checkerColor(const Checker& checker, vec2 uv);

}  // namespace diptych
