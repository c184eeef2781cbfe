// Scene textures with the lecture's mip chain (engine/gl/scene_textures.cpp), sampled the way
// engine/shading/texture_sampling.cpp samples them on the CPU, function for function: wrap on
// texel indices, texel centres at (i + 0.5) / size, GL's level selection (4.5 core, 8.14) and
// EXT_texture_filter_anisotropic's probes. Included by scene_shading.glsl.
#include "common/bindings.glsl"
#include "gl/scene_features.glsl"
// Per texture (width, height, levels, flags), RGBA32I (engine/gl/scene_textures.h).
layout(binding = UNIT_SCENE_TEXTURE_INFO) uniform isamplerBuffer uSceneTextureInfo;
ivec4 sceneTextureInfo(int tex) { return texelFetch(uSceneTextureInfo, tex); }
layout(binding = UNIT_SCENE_TEXTURES) uniform sampler2DArray uSceneTextures;

// The wrap modes (0 repeat, 1 clamp to edge, 2 mirrored repeat): the coordinate reduced by
// whole periods, then texel indices.
float sceneReduceCoordinate(float t, int mode) {
  if (isnan(t) || isinf(t)) return 0.0;
  if (mode == 0) return t - floor(t);
  if (mode == 2) return t - 2.0 * floor(0.5 * t);
  return clamp(t, -1.0, 2.0);
}

int sceneWrapTexel(int i, int size, int mode) {
  // GLSL leaves % undefined for negative operands. After sceneReduceCoordinate a texel index is
  // at least -size - 1 (clamp: t >= -1, bilinear -0.5), so adding 4 size keeps it non-negative
  // without changing the result modulo size or 2 size.
  if (size <= 1) return 0;
  if (mode == 0) return (i + 4 * size) % size;
  if (mode == 2) {
    int m = (i + 4 * size) % (2 * size);
    return m < size ? m : 2 * size - 1 - m;
  }
  return clamp(i, 0, size - 1);
}

bool sceneTextureValid(int tex) {
#if !DIPTYCH_SCENE_TEXTURES && !DIPTYCH_SCENE_NORMAL_MAPS && !DIPTYCH_SCENE_BUMP
  return false;  // folds every texture path away (scene_features.glsl)
#endif
  return tex >= 0 && tex < textureSize(uSceneTextureInfo) && sceneTextureInfo(tex).z > 0;
}

ivec2 sceneTextureLevelSize(int tex, int level) {
  return max(ivec2(1), sceneTextureInfo(tex).xy >> ivec2(level));
}

vec4 sceneTexelAt(int tex, int level, int x, int y) {
  return texelFetch(uSceneTextures, ivec3(x, y, tex), level);
}

vec4 sceneSampleLevel(int tex, int level, vec2 uv, bool linearTexels) {
  ivec2 size = sceneTextureLevelSize(tex, level);
  int flags = sceneTextureInfo(tex).w;
  int wrapS = flags & 3, wrapT = (flags >> 2) & 3;
  vec2 t = vec2(sceneReduceCoordinate(uv.x, wrapS), sceneReduceCoordinate(uv.y, wrapT));
  if (!linearTexels) {
    ivec2 p = ivec2(floor(t * vec2(size)));
    return sceneTexelAt(tex, level, sceneWrapTexel(p.x, size.x, wrapS),
                        sceneWrapTexel(p.y, size.y, wrapT));
  }
  vec2 x = t * vec2(size) - 0.5;
  vec2 x0 = floor(x);
  vec2 f = x - x0;
  ivec2 i0 = ivec2(x0);
  int xa = sceneWrapTexel(i0.x, size.x, wrapS), xb = sceneWrapTexel(i0.x + 1, size.x, wrapS);
  int ya = sceneWrapTexel(i0.y, size.y, wrapT), yb = sceneWrapTexel(i0.y + 1, size.y, wrapT);
  vec4 top = mix(sceneTexelAt(tex, level, xa, ya), sceneTexelAt(tex, level, xb, ya), f.x);
  vec4 bottom = mix(sceneTexelAt(tex, level, xa, yb), sceneTexelAt(tex, level, xb, yb), f.x);
  return mix(top, bottom, f.y);
}

const int SCENE_MIPS_NONE = 0, SCENE_MIPS_NEAREST = 1, SCENE_MIPS_LINEAR = 2;

// sampleFiltered: texels nearest or bilinear, level 0 (mips none), GL's nearest level
// d = ceil(lambda + 1/2) - 1, or levels floor(lambda), floor(lambda) + 1 blended.
vec4 sceneSampleFiltered(int tex, vec2 uv, float lambda, bool linearTexels, int mips) {
  if (!sceneTextureValid(tex)) return vec4(1.0);
  int top = sceneTextureInfo(tex).z - 1;
  if (mips == SCENE_MIPS_NONE || !(lambda > 0.0)) return sceneSampleLevel(tex, 0, uv, linearTexels);
  float l = min(lambda, float(top));
  if (mips == SCENE_MIPS_NEAREST)
    return sceneSampleLevel(tex, l > 0.5 ? int(ceil(l + 0.5)) - 1 : 0, uv, linearTexels);
  int d1 = int(floor(l));
  float f = l - float(d1);
  if (d1 >= top || f == 0.0) return sceneSampleLevel(tex, d1, uv, linearTexels);
  return mix(sceneSampleLevel(tex, d1, uv, linearTexels),
             sceneSampleLevel(tex, d1 + 1, uv, linearTexels), f);
}

// sampleTextureLod: the texture's own sampler; magnification (level 0) when lambda <= 0.
vec4 sceneSampleTextureLod(int tex, vec2 uv, float lambda) {
  if (!sceneTextureValid(tex)) return vec4(1.0);
  int flags = sceneTextureInfo(tex).w;
  if (!(lambda > 0.0)) return sceneSampleFiltered(tex, uv, 0.0, (flags & 128) != 0, SCENE_MIPS_NONE);
  int minCode = (flags >> 4) & 7;  // 0 N, 1 L, 2 NMN, 3 LMN, 4 NML, 5 LML
  bool linearTexels = minCode == 1 || minCode == 3 || minCode == 5;
  int mips = minCode < 2 ? SCENE_MIPS_NONE : (minCode < 4 ? SCENE_MIPS_NEAREST : SCENE_MIPS_LINEAR);
  return sceneSampleFiltered(tex, uv, lambda, linearTexels, mips);
}

// Level 0 with the magnification filter: what the CPU's sampleTexture(texture, uv) returns.
vec4 sceneSampleTexture(int tex, vec2 uv) { return sceneSampleTextureLod(tex, uv, 0.0); }

// lodFromGradients: lambda = log2(max(|dx| size, |dy| size)).
float sceneLodFromGradients(int tex, vec2 dx, vec2 dy) {
  vec2 size = vec2(sceneTextureInfo(tex).xy);
  float rho = max(length(dx * size), length(dy * size));
  return rho > 0.0 ? log2(rho) : -3.0e38;
}

// sampleAnisotropic: N = min(ceil(Pmax / Pmin), maxAnisotropy) trilinear probes along the
// longer axis at lambda = log2(Pmax / N).
vec4 sceneSampleAnisotropic(int tex, vec2 uv, vec2 dx, vec2 dy, int maxAnisotropy) {
  if (!sceneTextureValid(tex)) return vec4(1.0);
  vec2 size = vec2(sceneTextureInfo(tex).xy);
  float px = length(dx * size), py = length(dy * size);
  float pmax = max(px, py), pmin = min(px, py);
  if (!(pmax > 0.0) || isinf(pmax)) return sceneSampleFiltered(tex, uv, 0.0, true, SCENE_MIPS_LINEAR);
  float most = float(max(1, maxAnisotropy));
  int n = int(clamp(pmin > 0.0 ? ceil(pmax / pmin) : most, 1.0, most));
  float lambda = log2(pmax / float(n));
  vec2 axis = px >= py ? dx : dy;
  vec4 sum = vec4(0.0);
  for (int i = 0; i < n; ++i) {
    float offset = (float(i) + 0.5) / float(n) - 0.5;
    sum += sceneSampleFiltered(tex, uv + offset * axis, lambda, true, SCENE_MIPS_LINEAR);
  }
  return sum / float(n);
}
