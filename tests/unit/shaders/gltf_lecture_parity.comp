// GLSL side of tests/unit/test_gltf_lecture_parity.cpp: shaders/common/gltf_lecture.glsl on
// records of glTF inputs (base colour, metallic, roughness, transmission, IOR).
#include "common/gltf_lecture.glsl"

layout(local_size_x = 64) in;
uniform int uCount;
layout(std430, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };

const int IN_STRIDE = 8;
const int OUT_STRIDE = 20;

void main() {
  int c = int(gl_GlobalInvocationID.x);
  if (c >= uCount) return;
  int b = c * IN_STRIDE;
  LectureCoefficients k =
      gltfPbrToLecture(vec3(inputs[b], inputs[b + 1], inputs[b + 2]), inputs[b + 3],
                       inputs[b + 4], inputs[b + 5], inputs[b + 6]);
  vec3 diffuse = gltfDiffuseColor(vec3(inputs[b], inputs[b + 1], inputs[b + 2]), inputs[b + 3]);
  float results[OUT_STRIDE] = float[OUT_STRIDE](
      k.color.x, k.color.y, k.color.z, k.kd, k.ks, k.exponent, k.specularColor.x,
      k.specularColor.y, k.specularColor.z, k.kps, k.mirrorColor.x, k.mirrorColor.y,
      k.mirrorColor.z, k.kt, k.transmitColor.x, k.transmitColor.y, k.transmitColor.z, diffuse.x,
      diffuse.y, diffuse.z);
  for (int i = 0; i < OUT_STRIDE; ++i) outputs[c * OUT_STRIDE + i] = results[i];
}
