// Environment-map reflection (passes/raster/env_reflection.cpp): for each visibility texel of a
// reflective material, the environment radiance along r = reflect(-v, n_shading); for a glTF
// material with prefiltered levels (uMaxLod > 0), the GGX lobe's prefiltered radiance at
// lod = roughness uMaxLod (split sum, Karis 2013; passes/raster/env_prefilter.h), alpha 2.
// One of ENV_CUBE, ENV_SPHERE, ENV_EQUIRECT is defined by the pass. A full-screen fragment pass
// into the cleared signal, not a compute pass: a pixel whose material cannot reflect is
// discarded before any surface work, and llvmpipe skips the rest of the shader for blocks whose
// pixels are all discarded, which it does not for a divergent branch (docs/benchmarks.md).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/gbuffer_surface.glsl"

layout(binding = 0) uniform usampler2D uHits;  // gbuffer.hits (RGBA32UI)
layout(location = 0) out vec4 outReflection;
#ifdef ENV_CUBE
layout(binding = 1) uniform samplerCube uEnvironment;
#else
layout(binding = 1) uniform sampler2D uEnvironment;
#endif
uniform vec3 uCameraPosition;
uniform mat4 uWorldToEye;  // sphere map frame: the camera's view rotation
uniform float uMaxLod;     // prefiltered levels - 1 (level i: roughness i / uMaxLod); 0: none

const float ENV_PI = 3.14159265358979;

vec3 environmentAlong(vec3 r, float lod) {
#if defined(ENV_CUBE)
  // GL selects the face by the major axis (GL 4.5 table 8.19), the same rule as cubeFace().
  return textureLod(uEnvironment, r, lod).rgb;
#elif defined(ENV_SPHERE)
  // GL_SPHERE_MAP (OpenGL 2.1 spec 2.12.4) with r in the map's eye frame. m -> 0 as r -> -z:
  // the singular direction, spread over the whole rim of the map.
  vec3 e = mat3(uWorldToEye) * r;
  float m = 2.0 * sqrt(e.x * e.x + e.y * e.y + (e.z + 1.0) * (e.z + 1.0));
  vec2 st = m > 0.0 ? e.xy / m + 0.5 : vec2(1.0, 0.5);
  return textureLod(uEnvironment, st, lod).rgb;
#else
  // engine/scene/environment.cpp: u = 0.5 + atan2(z, x) / 2pi, v = acos(y) / pi with v = 0 on
  // the top image row, which the upload put at GL t = 1; u wraps (GL_REPEAT), t clamps.
  float u = (r.x == 0.0 && r.z == 0.0) ? 0.5 : 0.5 + atan(r.z, r.x) / (2.0 * ENV_PI);
  float v = acos(clamp(r.y, -1.0, 1.0)) / ENV_PI;
  return textureLod(uEnvironment, vec2(u, 1.0 - v), lod).rgb;
#endif
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uvec4 hits = texelFetch(uHits, p, 0);
  // The material decides first: only pixels of a material that can reflect rebuild the surface;
  // the others keep the cleared 0.
  if (!sceneHitMayReflect(hits, uMaxLod > 0.0)) discard;
  vec4 result = vec4(0.0);
  {
    SceneSurface s = gbufferSurface(p, hits);
    ShadingMaterial m = sceneMaterial(s.material, s.uv);
    bool lobe = uMaxLod > 0.0 && m.model == SHADING_MODEL_GLTF;
    if (hasReflection(m, lobe)) {
      // The shading normal on the viewer's side of the face, as makeSurfacePoint() does.
      vec3 incoming = s.position - uCameraPosition;
      vec3 n = dot(s.faceNormal, incoming) > 0.0 ? -s.shadingNormal : s.shadingNormal;
      vec3 r = safeNormalize(reflectAbout(safeNormalize(-incoming), n));
      float lod = lobe ? saturate01(m.roughness) * uMaxLod : 0.0;
      result = vec4(environmentAlong(r, lod), lobe ? 2.0 : 1.0);
    }
  }
  outReflection = result;
}
