// Blend producers, last step, drawn with multiplicative blending (dst * src): pixels whose first
// visible surface has no transmission (or none) get 0; the others keep the composited
// transmission, times the first surface's volume transmittance over its thickness when the view
// enters through a front face (KHR_materials_volume, docs/materials.md).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/gbuffer_surface.glsl"

uniform vec2 uViewportSize;
uniform vec3 uEye;  // the camera centre
layout(binding = 0) uniform usampler2D uHits;
layout(location = 0) out vec4 outColor;

void main() {
  uvec4 hits = texelFetch(uHits, ivec2(gl_FragCoord.xy), 0);
  outColor = vec4(0.0);
  // The material decides first: only pixels of a transmissive material rebuild the surface.
  if (!sceneHitMayTransmit(hits)) return;
  SceneSurface s = gbufferSurface(ivec2(gl_FragCoord.xy), hits);
  if (s.hit && hasTransmission(sceneMaterial(s.material, s.uv))) {
    bool front = dot(s.faceNormal, s.position - uEye) <= 0.0;
    outColor = vec4(front ? sceneVolumeTransmittance(s.material) : vec3(1.0), 1.0);
  }
}
