// G-buffer raster: hits (instance+1, primitive, u, v) and, with GBUFFER_NORMAL, the shading
// normal + material (with the normal or bump map when the scene has them: DIPTYCH_DETAIL_NORMAL);
// the surface target is resolved afterwards by gbuffer_surface.comp. GBUFFER_VISIBILITY: a
// visibility buffer, (instance+1, primitive, NaN, NaN), for frames whose only readers of the hits
// compute (u, v) themselves (the CPU passes, passes/common/hits_texel.h).
// Layout and method: engine/gl/gbuffer_raster.h and docs/gl.md.
#include "gl/scene_buffers.glsl"
#include "gl/ray_triangle.glsl"
#if defined(DIPTYCH_ALPHA_MASK) || defined(DIPTYCH_DETAIL_NORMAL)
// DIPTYCH_ALPHA_MASK: variant for alpha-tested meshes only (engine/gl/gbuffer_raster.cpp): a
// discard in the shader of every mesh would cost opaque scenes their early depth test.
// DIPTYCH_DETAIL_NORMAL: the scene has normal or bump maps (compiled with its defines).
#include "common/shading.glsl"
#include "gl/scene_shading.glsl"
#endif

// Camera frame exactly as diptych::primaryRay builds it (camera_math.cpp).
uniform vec3 uCameraPosition;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uAspect;
uniform float uTanHalfFov;
uniform vec2 uViewportSize;

uniform uint uInstance;
uniform uint uFirstTriangle;
uniform float uMaterial;

layout(location = 0) out uvec4 outHits;
#ifdef GBUFFER_NORMAL
layout(location = 1) out vec4 outNormal;
#endif

void main() {
#ifdef GBUFFER_VISIBILITY
  // (u, v) = quiet NaN: "not computed" (0 would be vertex 0, a valid point).
  outHits = uvec4(uInstance + 1u, uint(gl_PrimitiveID), 0x7fc00000u, 0x7fc00000u);
#else
  // gl_FragCoord.xy is the pixel centre with y up; primaryRay's image y runs down, so its
  // ndcY = 1 - 2 (H - fragY) / H = 2 fragY / H - 1, the same form as x.
  vec2 ndc = 2.0 * gl_FragCoord.xy / uViewportSize - 1.0;
  vec3 dir = uForward + (ndc.x * uAspect * uTanHalfFov) * uRight + (ndc.y * uTanHalfFov) * uUp;

  uint triangle = uFirstTriangle + uint(gl_PrimitiveID);
  uvec3 idx = sceneTriangle(triangle);
  vec3 p0 = scenePosition(idx.x);
  vec3 p1 = scenePosition(idx.y);
  vec3 p2 = scenePosition(idx.z);
  vec2 uv;
  if (!rayTriangleBarycentrics(uCameraPosition, dir, p0, p1, p2, uv)) {
    // Only an edge-on triangle gets here; its centroid is a point of it, and no NaN escapes.
    uv = vec2(1.0 / 3.0);
  }

  float w = 1.0 - uv.x - uv.y;
#ifdef DIPTYCH_ALPHA_MASK
  // Texture uv at the exact barycentrics, in interpolateUv's order, so the hole is the one the
  // Embree filter cuts for the same primary ray.
  vec2 t0 = sceneUv(idx.x);
  vec2 t1 = sceneUv(idx.y);
  vec2 t2 = sceneUv(idx.z);
  int material = int(uMaterial);
  if (sceneMaterialAlpha(material, w * t0 + uv.x * t1 + uv.y * t2) <
      sceneMaterialAlphaCutoff(material)) {
    discard;
  }
#endif
  outHits = uvec4(uInstance + 1u, uint(gl_PrimitiveID), floatBitsToUint(uv.x),
                        floatBitsToUint(uv.y));
#ifdef GBUFFER_NORMAL
  vec3 n = w * sceneNormal(idx.x) + uv.x * sceneNormal(idx.y) + uv.y * sceneNormal(idx.z);
  float len = length(n);
  // Same fallback as interpolateNormal(): the geometric normal when the blend cancels out.
  n = len > 0.0 ? n / len : normalize(cross(p1 - p0, p2 - p0));
#ifdef DIPTYCH_DETAIL_NORMAL
  // The shading normal every pass reconstructs from this texel (normal map, bump), same code.
  n = surfaceFromHits(outHits).shadingNormal;
#endif
  outNormal = vec4(n, uMaterial);
#endif
#endif  // GBUFFER_VISIBILITY
}
