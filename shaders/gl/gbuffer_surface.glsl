// The surface point of a G-buffer pixel as the G-buffer pass stored it (resolved from the hits
// by gbuffer_surface.comp; layout in engine/gl/gbuffer_raster.h): three texel reads in place of
// surfaceFromHits' ~30 buffer gathers (indices, positions, normals, uvs, tangents, instance),
// the cost every full-screen pass paid per pixel (docs/benchmarks.md). The values are the ones
// surfaceFromHits computes for the same hit. Include after gl/scene_shading.glsl; the pass binds
// gbuffer.surface at UNIT_GBUFFER_SURFACE (passes/raster/gbuffer_surface.h).
#include "common/bindings.glsl"
#ifdef DIPTYCH_GBUFFER_SURFACE
layout(binding = UNIT_GBUFFER_SURFACE) uniform sampler2DArray uGBufferSurface;

SceneSurface surfaceFromGBuffer(ivec2 p, uvec4 hits) {
  SceneSurface s = sceneSurfaceDefaults(hits);
  if (!s.hit) return s;
  vec4 a = texelFetch(uGBufferSurface, ivec3(p, 0), 0);
  vec4 b = texelFetch(uGBufferSurface, ivec3(p, 1), 0);
  vec4 c = texelFetch(uGBufferSurface, ivec3(p, 2), 0);
  s.position = a.xyz;
  s.faceNormal = b.xyz;
  s.shadingNormal = c.xyz;
  s.uv = vec2(a.w, b.w);
  s.material = int(c.w);
  return s;
}
#endif

// The surface of pixel p: from gbuffer.surface when the pass was compiled with it
// (DIPTYCH_GBUFFER_SURFACE), else rebuilt from the hits.
SceneSurface gbufferSurface(ivec2 p, uvec4 hits) {
#ifdef DIPTYCH_GBUFFER_SURFACE
  return surfaceFromGBuffer(p, hits);
#else
  return surfaceFromHits(hits);
#endif
}
