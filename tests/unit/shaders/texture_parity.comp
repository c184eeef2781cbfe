// GLSL side of tests/unit/test_texture_parity.cpp: shaders/gl/scene_textures.glsl's samplers on
// records (texture, uv, lambda, dx, dy); 9 vec4 out per record: sceneSampleTextureLod, the six
// sceneSampleFiltered modes (nearest/linear texels x none/nearest/linear mips),
// sceneSampleAnisotropic (max 8), and (sceneLodFromGradients, 0, 0, 0).
#include "gl/scene_textures.glsl"

layout(local_size_x = 64) in;
uniform int uCount;
layout(std430, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

void main() {
  int c = int(gl_GlobalInvocationID.x);
  if (c >= uCount) return;
  int b = c * 8;
  int tex = int(inputs[b]);
  vec2 uv = vec2(inputs[b + 1], inputs[b + 2]);
  float lambda = inputs[b + 3];
  vec2 dx = vec2(inputs[b + 4], inputs[b + 5]), dy = vec2(inputs[b + 6], inputs[b + 7]);
  int o = c * 9;
  outputs[o] = sceneSampleTextureLod(tex, uv, lambda);
  for (int k = 0; k < 6; ++k)
    outputs[o + 1 + k] = sceneSampleFiltered(tex, uv, lambda, (k & 1) != 0, k >> 1);
  outputs[o + 7] = sceneSampleAnisotropic(tex, uv, dx, dy, 8);
  outputs[o + 8] = vec4(sceneLodFromGradients(tex, dx, dy), 0.0, 0.0, 0.0);
}
