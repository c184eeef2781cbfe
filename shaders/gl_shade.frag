// The shade pass on GL (passes/raster/gl_shade.cpp): the lecture's illumination model from the
// G-buffer, with the same shared code the CPU shade pass runs (common/shading.glsl):
//   L = M_E + A_G + sum_i V_i S_i L_dir,i + k_ps M_PS L_refl + k_t M_T L_trans
// Inputs are read with imageLoad (image units 0..5, the pass's own), so that the texture units
// stay free for the scene's textures. Which optional inputs are connected, and the light count,
// are compile-time constants (SHADE_* below, one program per combination and scene in
// gl_shade.cpp; llvmpipe runs every side of a branch, docs/gl-shade.md): V_i = 1, L_refl =
// L_trans = 0 and the material's own C and alpha when unconnected, as in passes/cpu/shade.cpp.
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/scene_environment.glsl"
#include "gl/gbuffer_surface.glsl"

layout(binding = 0, rgba32ui) readonly uniform uimage2D uHits;
layout(binding = 1, r32f) readonly uniform image2D uVisibility;            // one light
layout(binding = 2, r32f) readonly uniform image2DArray uVisibilityLayers;  // a layer per light
layout(binding = 3, rgba32f) readonly uniform image2D uReflection;
layout(binding = 4, rgba32f) readonly uniform image2D uTransmission;
layout(binding = 5, rgba32f) readonly uniform image2D uAlbedo;
const int kVisibilityCount = SHADE_VISIBILITY;  // layers of light_visibility; 0: unconnected
const bool kHasReflection = SHADE_REFLECTION != 0;
const bool kHasTransmission = SHADE_TRANSMISSION != 0;
const bool kHasAlbedo = SHADE_ALBEDO != 0;
const int kLightCount = SHADE_LIGHTS;  // the scene's lights (uLightCount, as a constant)
uniform vec3 uAmbient;  // A_G

// The pixel-centre ray, built as diptych::primaryRay builds it (engine/scene/camera_math.cpp);
// GL row y is image row height - 1 - y, which makes ndcY = 2 fragY / height - 1.
uniform vec3 uCameraPosition;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uAspect;
uniform float uTanHalfFov;
uniform vec2 uViewportSize;

layout(location = 0) out vec4 outColor;

// Which pixels this program shades (gl_shade.cpp): 0 every pixel; with the G-buffer's depth
// attached and tested, 1 the background (depth 0, the cleared far end of reversed-Z) and 2 the
// surfaces. Split, each program runs only on its own pixels behind an early depth test, and
// llvmpipe, which runs both sides of a branch under a lane mask, no longer evaluates the
// environment lookup for surface pixels nor the surface rebuild and lights for the sky.
#define SHADE_PART_ALL 0
#define SHADE_PART_BACKGROUND 1
#define SHADE_PART_SURFACES 2
#if SHADE_PART != SHADE_PART_ALL
layout(early_fragment_tests) in;
#endif

float lightVisibility(ivec2 p, int i) {
  if (i >= kVisibilityCount) return 1.0;
  if (kVisibilityCount == 1) return imageLoad(uVisibility, p).r;
  return imageLoad(uVisibilityLayers, ivec3(p, i)).r;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 ndc = 2.0 * gl_FragCoord.xy / uViewportSize - 1.0;
  vec3 eye = normalize(uForward + (ndc.x * uAspect * uTanHalfFov) * uRight +
                       (ndc.y * uTanHalfFov) * uUp);
#if SHADE_PART == SHADE_PART_BACKGROUND
  outColor = vec4(sceneEnvironment(eye), 1.0);
#else
  SceneSurface s = gbufferSurface(p, imageLoad(uHits, p));
#if SHADE_PART == SHADE_PART_ALL
  if (!s.hit) {
    outColor = vec4(sceneEnvironment(eye), 1.0);
    return;
  }
#endif
  ShadingMaterial m = sceneMaterial(s.material, s.uv);
  if (kHasAlbedo) {
    // The texture-filtering slot's signal replaces the resolved colour and coverage, as
    // passes/cpu/shade.cpp applyAlbedo, where it wrote one (a >= 0). On lecture-model materials
    // re-mapped per texel (remapsPerTexel, gate 8) it is the base colour, and the coefficients
    // are mapped from it (withBaseColorSignal; docs/textures.md).
    vec4 albedo = imageLoad(uAlbedo, p);
    bool remapped = m.model != SHADING_MODEL_GLTF &&
                    (int(sceneMaterialRecord(s.material).modelTransSpec.w) & 8) != 0;
    if (albedo.a >= 0.0 && remapped) {
      sceneApplyGltfPbr(m, albedo.xyz, m.metallic, m.roughness, m.transmission);
      m.baseColor = albedo.xyz;
      m.alpha = albedo.w;
    } else if (albedo.a >= 0.0) {
      m = withTextureSignal(m, albedo.xyz, albedo.w);
    }
  }
  // makeSurfacePoint(): the shading normal on the side the eye ray arrives from.
  vec3 n = dot(s.faceNormal, eye) <= 0.0 ? s.shadingNormal : -s.shadingNormal;
  vec3 v = -eye;
  vec3 radiance = emittedAndAmbient(m, uAmbient);
  for (int i = 0; i < kLightCount; ++i) {
    LightSample ls = sampleLight(sceneLight(i), s.position);
    radiance += lightContribution(m, n, v, ls, lightVisibility(p, i));
  }
  // Alpha: 1 a mirror ray, 2 a prefiltered lobe (secondaryTermsOf, common/shading.glsl).
  vec4 reflected = kHasReflection ? imageLoad(uReflection, p) : vec4(0.0);
  vec3 transmitted = kHasTransmission ? imageLoad(uTransmission, p).rgb : vec3(0.0);
  radiance += secondaryTermsOf(m, n, v, reflected.rgb, reflected.a, transmitted);
  outColor = vec4(radiance, 1.0);
#endif
}
