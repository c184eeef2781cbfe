// Blend producers, last step: pixels whose first visible surface has k_t = 0 (or none) get 0,
// the others keep the composited transmission (discarded here).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"

uniform vec2 uViewportSize;
layout(binding = 0) uniform usampler2D uHits;
layout(location = 0) out vec4 outColor;

void main() {
  SceneSurface s = surfaceFromHits(texelFetch(uHits, ivec2(gl_FragCoord.xy), 0));
  if (s.hit && sceneMaterial(s.material, s.uv).kt > 0.0) discard;
  outColor = vec4(0.0);
}
