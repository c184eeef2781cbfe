// GLSL side of tests/unit/test_shading_parity.cpp: evaluates shaders/common/shading.glsl on
// records of inputs (SHADING_CASES) or scene_shading.glsl's surfaceFromHits on every texel
// of a visibility buffer (SURFACE_CASES). Record layouts are defined in the test.
#include "common/shading.glsl"

layout(local_size_x = 64) in;
uniform int uCount;

#ifdef SHADING_CASES
layout(std430, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };

const int IN_STRIDE = 64;
const int OUT_STRIDE = 24;
int base = 0;
float at(int i) { return inputs[base + i]; }
vec3 at3(int i) { return vec3(at(i), at(i + 1), at(i + 2)); }

void main() {
  int c = int(gl_GlobalInvocationID.x);
  if (c >= uCount) return;
  base = c * IN_STRIDE;
  ShadingLight light = ShadingLight(int(at(0)), at3(1), at(4), at3(5), at3(8), at(11), at(12),
                                    at(13), at(14));
  ShadingMaterial m = ShadingMaterial(at3(15), at(18), at(19), at(20), at(21), at3(22), at(25),
                                      at3(26), at(29), at3(30), at3(33), at(36), at(37),
                                      SHADING_MODEL_LECTURE, vec3(0.0), 0.0, 0.0, 0.0, 0.0,
                                      vec3(0.0), 0.0, 1.0, 0.0);
  vec3 p = at3(38), n = at3(41), v = at3(44), d = at3(51);
  float visibility = at(47), eta = at(48), cosTheta = at(49), n1 = at(50), n2 = at(54);

  LightSample s = sampleLight(light, p);
  // directTerm takes unit n, v (its precondition): the raw vectors are normalised here, as in
  // the C++ evaluation, so extreme inputs still reach it through safeNormalize.
  vec3 direct = directTerm(m, safeNormalize(n), safeNormalize(v), s.l);
  vec3 contribution = lightContribution(m, safeNormalize(n), safeNormalize(v), s, visibility);
  Refraction t = refractLecture(d, n, eta);
  vec3 r = reflectAbout(d, n);
  float f = fresnelSchlick(cosTheta, n1, n2);
  float results[OUT_STRIDE] = float[OUT_STRIDE](
      s.l.x, s.l.y, s.l.z, s.distance, s.radiance.x, s.radiance.y, s.radiance.z, direct.x,
      direct.y, direct.z, contribution.x, contribution.y, contribution.z, t.t.x, t.t.y, t.t.z,
      t.totalInternalReflection ? 1.0 : 0.0, r.x, r.y, r.z, f, 0.0, 0.0, 0.0);
  for (int i = 0; i < OUT_STRIDE; ++i) outputs[c * OUT_STRIDE + i] = results[i];
}
#endif

#ifdef SURFACE_CASES
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
layout(binding = 0) uniform usampler2D uHits;
layout(std430, binding = 7) writeonly buffer Surfaces { float surfaces[]; };
const int OUT_STRIDE = 12;

void main() {
  ivec2 size = textureSize(uHits, 0);
  int i = int(gl_GlobalInvocationID.x);
  if (i >= size.x * size.y) return;
  // GL row 0 is the bottom; the test indexes rows top first like transfer.h.
  ivec2 texel = ivec2(i % size.x, size.y - 1 - i / size.x);
  SceneSurface s = surfaceFromHits(texelFetch(uHits, texel, 0));
  float results[OUT_STRIDE] = float[OUT_STRIDE](
      s.position.x, s.position.y, s.position.z, s.faceNormal.x, s.faceNormal.y, s.faceNormal.z,
      s.shadingNormal.x, s.shadingNormal.y, s.shadingNormal.z, s.uv.x, s.uv.y, float(s.material));
  for (int k = 0; k < OUT_STRIDE; ++k) surfaces[i * OUT_STRIDE + k] = results[k];
}
#endif
