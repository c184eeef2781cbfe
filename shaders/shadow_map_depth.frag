// Depth only: the rasterizer writes the (polygon-offset) depth; no colour target is attached.
#ifdef DIPTYCH_ALPHA_MASK
// Variant for alpha-tested casters only (passes/raster/shadow_map_render.cpp): the texel is cut
// out where the material's coverage is below its cutoff, as the Embree filter rejects the hit.
// The uv is the perspective-correct interpolation of the vertex uvs, not the exact ray
// barycentrics: the cut-out edge may move by a fraction of a map texel.
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"

uniform int uMaterial;
in vec2 vUv;

void main() {
  if (sceneMaterialAlpha(uMaterial, vUv) < sceneMaterialAlphaCutoff(uMaterial)) discard;
}
#else
void main() {}
#endif
