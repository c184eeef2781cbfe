// Forward renderer: the shared lecture model without shadows or secondary terms,
//   L = M_E + A_G + sum_i S_i L_dir,i     (V_i = 1, k_ps M_PS L_refl = k_t M_T L_trans = 0),
// at the exact ray/triangle point of the pixel-centre ray (as gbuffer.frag), so that a
// forward-shaded pixel is what a ray tracer shading the same hit computes.
// See engine/gl/forward_renderer.h and docs/forward-producers.md.
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/ray_triangle.glsl"
#include "gl/pixel_ray.glsl"

uniform uint uInstance;
uniform uint uFirstTriangle;
uniform int uMaterial;
uniform vec3 uAmbient;
uniform int uBlend;   // 1: the output is composited as I = I_m + k_t M_T I
// Constants of the permutation (ForwardRenderer::surface): llvmpipe runs a uniform branch's body
// for every fragment, so the visibility-texel path would cost the passes that do not use it.
// 1: keep only fragments strictly behind the visibility texel's surface.
const int uBehind = FORWARD_BEHIND;
// 1 (with uBehind): also drop fragments whose pixel's first surface transmits nothing (k_t = 0):
// the blend producers zero those pixels afterwards (blend_transmission.frag, the same texel).
const int uTransmissiveOnly = FORWARD_TRANSMISSIVE_ONLY;
layout(binding = 0) uniform usampler2D uHits;
// With uTransmissiveOnly: the pixel's first-surface distance when that surface transmits, else
// negative (blend_transmission_first.frag, once per pixel): both tests below without rebuilding
// the surface.
layout(binding = UNIT_BLEND_FIRST) uniform sampler2D uFirst;

// Dual-source blending (GL 3.3 core, ARB_blend_func_extended): index 1 is the per-fragment
// destination factor k_t M_T of glBlendFunc(GL_ONE, GL_SRC1_COLOR).
layout(location = 0, index = 0) out vec4 outColor;
layout(location = 0, index = 1) out vec4 outTransmit;

// The uv of the ray through window position `fragCoord` on the plane of triangle (p0, p1, p2);
// false for a ray in that plane.
bool uvAlongPixelRay(vec2 fragCoord, vec3 p0, vec3 p1, vec3 p2, vec2 t0, vec2 t1, vec2 t2,
                     out vec2 uv) {
  vec2 b;
  if (!rayTriangleBarycentrics(uEye, pixelRayDirectionAt(fragCoord), p0, p1, p2, b)) return false;
  uv = (1.0 - b.x - b.y) * t0 + b.x * t1 + b.y * t2;
  return true;
}

// The texture level of detail a rasterizer gives this fragment (GL 4.5 core, 8.14.1): from the
// uv derivatives, here the uv of the next pixels' rays on the same triangle's plane minus the
// pixel's own, which is what dFdx and dFdy of the perspective-correct uv are on a planar
// triangle, without the 2 x 2 quad (some of its fragments may be discarded above). Returned in
// uv units, log2 max(|du/dx|, |du/dy|): sceneMaterialTexture adds each texture's log2 size (GL's
// lambda for square textures; non-square ones by the geometric mean of the two sizes). Below
// -1e38: level 0.
float forwardUvLod(vec3 p0, vec3 p1, vec3 p2, vec2 t0, vec2 t1, vec2 t2, vec2 uv) {
  vec2 ux, uy;
  if (!uvAlongPixelRay(gl_FragCoord.xy + vec2(1.0, 0.0), p0, p1, p2, t0, t1, t2, ux) ||
      !uvAlongPixelRay(gl_FragCoord.xy + vec2(0.0, 1.0), p0, p1, p2, t0, t1, t2, uy))
    return -3.0e38;
  float rho = max(length(ux - uv), length(uy - uv));
  return rho > 0.0 && !isinf(rho) ? log2(rho) : -3.0e38;
}

void main() {
  // The visibility tests that need no ray/triangle work come first, so that llvmpipe skips the
  // rest of the shader for blocks whose fragments are all discarded (docs/benchmarks.md).
  uvec4 texel = uvec4(0u);
  float firstDistance = -1.0;  // negative: no first surface to be behind (background)
  if (uBehind != 0) {
    texel = texelFetch(uHits, ivec2(gl_FragCoord.xy), 0);
    // "Behind the first visible surface": the first surface itself (same instance and
    // primitive) is excluded by identity, everything else by its distance along the same ray
    // below. The identity test reads the hits texel and the material gate one texel of uFirst,
    // so both come before any ray/triangle work (a blended object's front faces end here).
    if (texel.x != 0u && texel.x - 1u == uInstance && texel.y == uint(gl_PrimitiveID)) discard;
    if (uTransmissiveOnly != 0) {
      firstDistance = texelFetch(uFirst, ivec2(gl_FragCoord.xy), 0).a;
      if (firstDistance < 0.0) discard;  // the first surface transmits nothing
    } else {
      SceneSurface first = surfaceFromHits(texel);
      if (first.hit) firstDistance = safeLength(first.position - uEye);
    }
  }
  vec3 dir = pixelRayDirection();
  uvec3 idx = sceneTriangle(uFirstTriangle + uint(gl_PrimitiveID));
  vec3 p0 = scenePosition(idx.x), p1 = scenePosition(idx.y), p2 = scenePosition(idx.z);
  vec2 bary;
  // Only an edge-on triangle fails; its centroid is a point of it, and no NaN escapes.
  if (!rayTriangleBarycentrics(uEye, dir, p0, p1, p2, bary)) bary = vec2(1.0 / 3.0);
  float w = 1.0 - bary.x - bary.y;
  vec3 p = w * p0 + bary.x * p1 + bary.y * p2;

  if (uBehind != 0 && firstDistance >= 0.0 && safeLength(p - uEye) <= firstDistance) discard;

  vec3 face = safeNormalize(cross(p1 - p0, p2 - p0));
  vec3 n = w * sceneNormal(idx.x) + bary.x * sceneNormal(idx.y) + bary.y * sceneNormal(idx.z);
  n = maxAbsComponent(n) > 0.0 ? normalize(n) : face;
  vec2 t0 = sceneUv(idx.x);
  vec2 t1 = sceneUv(idx.y);
  vec2 t2 = sceneUv(idx.z);
  vec2 uv = w * t0 + bary.x * t1 + bary.y * t2;
  // Normal and bump maps on the front side, as makeSurfacePoint(), before the side flip.
  vec4 tg = w * sceneTangent(idx.x) + bary.x * sceneTangent(idx.y) + bary.y * sceneTangent(idx.z);
  n = sceneDetailNormal(uMaterial, n, tg, p0, p1, p2, t0, t1, t2, uv);
  // As makeSurfacePoint(): the shading normal goes to the side the ray arrives from.
  if (dot(face, dir) > 0.0) n = -n;
  // Textures filtered by their own samplers at the fragment's level of detail, as every raster
  // draw of a GPU engine is (the mirrored scene of a planar mirror, the scene behind glass, a
  // dynamic cube map's faces); the texture_filtering slot filters only the G-buffer's pixels.
  // FORWARD_TEXTURE_LOD 0 (the producers' texture_lod=level0): level 0, as a ray's hit reads.
#if DIPTYCH_SCENE_TEXTURES && FORWARD_TEXTURE_LOD
  ShadingMaterial m = sceneMaterialLod(uMaterial, uv, forwardUvLod(p0, p1, p2, t0, t1, t2, uv));
#else
  ShadingMaterial m = sceneMaterial(uMaterial, uv);
#endif

  vec3 v = safeNormalize(-dir);
  vec3 radiance = emittedAndAmbient(m, uAmbient);
  for (int i = 0; i < uLightCount; ++i) {
    radiance += lightContribution(m, n, v, sampleLight(sceneLight(i), p), 1.0f);
  }
  // Alpha: 1 for a replaced pixel; blended pixels keep the destination's alpha (0 + 1 * a).
  outColor = vec4(radiance, uBlend != 0 ? 0.0 : 1.0);
  // The transmission factor of the material's model (k_t M_T, or the glTF model's Fresnel-weighted one).
  // KHR_materials_volume: entering through a front face, Beer-Lambert over the thickness.
  vec3 volume = dot(face, dir) <= 0.0 ? sceneVolumeTransmittance(uMaterial) : vec3(1.0);
  outTransmit = vec4(secondaryWeights(m, n, v).transmission * volume, 1.0);
}
