// planar_shadows: a projected shadow polygon darkens only the pixels whose G-buffer point lies
// on its receiver (the hits texel names the instance: x = instance + 1).
layout(binding = 0) uniform usampler2D uHits;
uniform int uReceiver;
layout(location = 0) out vec4 outVisibility;

void main() {
  if (texelFetch(uHits, ivec2(gl_FragCoord.xy), 0).x != uint(uReceiver + 1)) discard;
  outVisibility = vec4(0.0);
}
