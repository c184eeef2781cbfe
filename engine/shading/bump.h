#pragma once
// The lecture's bump mapping (shaders/common/bump.glsl) compiled as C++, plus the finite
// differences of a greyscale height texture sampled the way the CPU side samples textures.
#include "engine/shading/shading.h"

namespace diptych::shading {
#define in
#define SHADING_FN inline
#include "shaders/common/bump.glsl"
#undef SHADING_FN
#undef in
}  // namespace diptych::shading

namespace diptych {

// n' at uv for a height texture (red channel, bilinear, the texture's wrap modes): d_u and d_v
// by the lecture's central differences with step `delta` in uv, scaled by k; then
// shading::bumpNormal(tu, tv, n, d_u, d_v).
vec3 bumpNormalFromTexture(const Texture& height, vec2 uv, float k, float delta, const vec3& tu,
                           const vec3& tv, const vec3& n);

// f_h of the procedural sinusoid of a BumpMap: amplitude sin(2 pi fu u) cos(2 pi fv v).
float bumpSinusoid(const BumpMap& bump, vec2 uv);

// n' of a material's BumpMap at uv: the lecture's central differences (step bump.delta, scale
// bump.k) on its height texture (bumpNormalFromTexture) or on the procedural sinusoid, then
// shading::bumpNormal. A texture index out of range returns the unit n.
vec3 bumpMapNormal(const Scene& scene, const BumpMap& bump, vec2 uv, const vec3& tu, const vec3& tv,
                   const vec3& n);

// dP/du and dP/dv of a triangle from its positions and uvs (constant over the triangle, the
// lecture's "constantes en cada polígono"); zero vectors when the uv triangle is degenerate.
struct SurfaceTangents {
  vec3 tu{0.f}, tv{0.f};
};
SurfaceTangents triangleTangents(const vec3& p0, const vec3& p1, const vec3& p2, vec2 uv0, vec2 uv1,
                                 vec2 uv2);

}  // namespace diptych
