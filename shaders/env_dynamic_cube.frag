// env_dynamic_cube resolve: at each pixel of the captured instance, the cube along
// r = reflect(-v, n) from the exact G-buffer point (v toward the eye, n the shading normal on
// the side the view ray arrives from, as makeSurfacePoint()). Other pixels are left untouched.
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/gbuffer_surface.glsl"

layout(binding = 0) uniform usampler2D uHits;
layout(binding = 1) uniform samplerCube uCube;
uniform int uInstance;
uniform vec3 uEye;
layout(location = 0) out vec4 outColor;

void main() {
  // The instance decides first, from the hits texel: other pixels skip the surface rebuild
  // (llvmpipe skips the rest of the shader for blocks whose pixels are all discarded).
  uvec4 hits = texelFetch(uHits, ivec2(gl_FragCoord.xy), 0);
  if (hits.x != uint(uInstance + 1)) discard;
  SceneSurface s = gbufferSurface(ivec2(gl_FragCoord.xy), hits);
  vec3 incoming = s.position - uEye;
  vec3 n = dot(s.faceNormal, incoming) > 0.0 ? -s.shadingNormal : s.shadingNormal;
  vec3 r = reflectAbout(safeNormalize(-incoming), n);
  outColor = vec4(texture(uCube, r).rgb, 1.0);
}
