// GLSL side of tests/unit/test_pbr_parity.cpp: the glTF model of shaders/common/pbr.glsl, through
// the shared dispatch points (directResponse, secondaryWeights), on records of inputs.
#include "common/shading.glsl"

layout(local_size_x = 64) in;
uniform int uCount;
layout(std430, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };

const int IN_STRIDE = 32;
const int OUT_STRIDE = 16;
int base = 0;
float at(int i) { return inputs[base + i]; }
vec3 at3(int i) { return vec3(at(i), at(i + 1), at(i + 2)); }

void main() {
  int c = int(gl_GlobalInvocationID.x);
  if (c >= uCount) return;
  base = c * IN_STRIDE;
  ShadingMaterial m = ShadingMaterial(vec3(0.0), 0.0, 0.0, 0.0, 0.0, vec3(0.0), 0.0, vec3(0.0),
                                      0.0, vec3(0.0), vec3(0.0), at(0), 1.0, SHADING_MODEL_GLTF,
                                      at3(1), at(4), at(5), at(6), at(7), at3(8), at(20),
                                      at(21), at(22));
  vec3 n = at3(11), v = at3(14), l = at3(17);
  vec3 direct = directResponse(m, n, v, l);
  SecondaryWeights w = secondaryWeights(m, n, v);
  vec2 ab = pbrEnvironmentBrdf(dot(safeNormalize(n), safeNormalize(v)), m.roughness);
  vec3 film = pbrFilmFresnel(m.iridescenceIor, m.baseColor, m.iridescenceThickness, at(23));
  float results[OUT_STRIDE] = float[OUT_STRIDE](
      direct.x, direct.y, direct.z, w.reflection.x, w.reflection.y, w.reflection.z,
      w.transmission.x, w.transmission.y, w.transmission.z, ab.x, ab.y, 0.0, film.x, film.y,
      film.z, 0.0);
  for (int i = 0; i < OUT_STRIDE; ++i) outputs[c * OUT_STRIDE + i] = results[i];
}
