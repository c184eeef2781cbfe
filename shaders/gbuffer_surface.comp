// The G-buffer's stored surface (engine/gl/gbuffer_raster.h, `surface`), resolved once per pixel
// after the raster: surfaceFromHits on the pixel's hit, the function every GL full-screen pass
// used to run itself, so they now read three texels (gl/gbuffer_surface.glsl) and get the same
// values. A pass over the finished hits rather than extra outputs of gbuffer.frag, where it would
// run for every rasterized fragment, overdraw included (both measured in docs/benchmarks.md).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform usampler2D uHits;
layout(binding = 0, rgba32f) writeonly uniform image2DArray uSurface;

void main() {
  ivec2 size = imageSize(uSurface).xy;
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  uvec4 hits = texelFetch(uHits, p, 0);
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  if (hits.x != 0u) {
    SceneSurface s = surfaceFromHits(hits);
    a = vec4(s.position, s.uv.x);
    b = vec4(s.faceNormal, s.uv.y);
    c = vec4(s.shadingNormal, float(s.material));
  }
  imageStore(uSurface, ivec3(p, 0), a);
  imageStore(uSurface, ivec3(p, 1), b);
  imageStore(uSurface, ivec3(p, 2), c);
}
