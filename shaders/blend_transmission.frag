// Blend producers, last step, drawn with multiplicative blending (dst * src): pixels whose first
// visible surface has no transmission (or none) get 0; the others keep the composited
// transmission, times the factor blend_transmission_first.frag stored for them (the first
// surface's volume transmittance when the view enters through a front face,
// KHR_materials_volume).
#include "common/bindings.glsl"
layout(binding = UNIT_BLEND_FIRST) uniform sampler2D uFirst;
layout(location = 0) out vec4 outColor;

void main() {
  vec4 first = texelFetch(uFirst, ivec2(gl_FragCoord.xy), 0);
  outColor = first.a >= 0.0 ? vec4(first.rgb, 1.0) : vec4(0.0);
}
