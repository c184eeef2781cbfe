// GLSL side of tests/shared_scenes/test_texture_materials_gl.cpp: for every texel of a
// visibility buffer, sceneMaterial at the reconstructed surface point (C, alpha, M_E, k_a, k_d,
// k_s, e, k_ps, the normal-mapped shading normal, d_i, M_PS, M_T, the glTF base colour, metallic
// and roughness, the film's strength and thickness).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
layout(local_size_x = 64) in;
layout(binding = 0) uniform usampler2D uHits;
layout(std430, binding = 7) writeonly buffer Materials { float materials[]; };
const int OUT_STRIDE = 32;

void main() {
  ivec2 size = textureSize(uHits, 0);
  int i = int(gl_GlobalInvocationID.x);
  if (i >= size.x * size.y) return;
  // GL row 0 is the bottom; the test indexes rows top first like transfer.h.
  ivec2 texel = ivec2(i % size.x, size.y - 1 - i / size.x);
  SceneSurface s = surfaceFromHits(texelFetch(uHits, texel, 0));
  ShadingMaterial m = sceneMaterial(s.material, s.uv);
  float r[OUT_STRIDE] = float[OUT_STRIDE](
      m.color.x, m.color.y, m.color.z, m.alpha, m.emission.x, m.emission.y, m.emission.z, m.ka,
      m.kd, m.ks, m.exponent, m.kps, s.shadingNormal.x, s.shadingNormal.y, s.shadingNormal.z,
      m.specularColor.x, m.specularColor.y, m.specularColor.z, m.mirrorColor.x, m.mirrorColor.y,
      m.mirrorColor.z, m.transmitColor.x, m.transmitColor.y, m.transmitColor.z, m.baseColor.x,
      m.baseColor.y, m.baseColor.z, m.metallic, m.roughness, m.iridescence,
      m.iridescenceThickness, 0.0);
  for (int k = 0; k < OUT_STRIDE; ++k) materials[i * OUT_STRIDE + k] = r[k];
}
