// Blend producers, first step (passes/raster/blend_transmission.cpp): the pixel's first visible
// surface, rebuilt once per pixel instead of in every fragment of the two forward passes and in
// the mask. Where that surface transmits (a material with k_t > 0): rgb = the factor the mask
// multiplies by (its volume transmittance over the thickness when the view enters through a
// front face, KHR_materials_volume, docs/materials.md; else 1) and a = its distance from the
// eye, the value forward.frag's "strictly behind" test compares with. Elsewhere (0, 0, 0, -1).
// Depth, where the caller attaches a depth buffer (the forward passes' own): 1 (reversed-Z near,
// which no fragment passes GL_GREATER against) where the first surface does not transmit, so
// that llvmpipe's early depth test rejects the forward fragments the mask would zero, instead of
// running the shader to discard them; 0 (the cleared value) elsewhere.
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/gbuffer_surface.glsl"

uniform vec2 uViewportSize;
uniform vec3 uEye;  // the camera centre
layout(binding = 0) uniform usampler2D uHits;
layout(location = 0) out vec4 outFirst;

void main() {
  uvec4 hits = texelFetch(uHits, ivec2(gl_FragCoord.xy), 0);
  outFirst = vec4(0.0, 0.0, 0.0, -1.0);
  // The material decides first: only pixels of a transmissive material rebuild the surface.
  if (sceneHitMayTransmit(hits)) {
    SceneSurface s = gbufferSurface(ivec2(gl_FragCoord.xy), hits);
    if (s.hit && hasTransmission(sceneMaterial(s.material, s.uv))) {
      bool front = dot(s.faceNormal, s.position - uEye) <= 0.0;
      outFirst = vec4(front ? sceneVolumeTransmittance(s.material) : vec3(1.0),
                      safeLength(s.position - uEye));
    }
  }
  gl_FragDepth = outFirst.a < 0.0 ? 1.0 : 0.0;
}
