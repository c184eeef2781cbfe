// planar_mirror resolve: pixels of the mirror instance take the mirrored render at the same
// pixel (the reflected ray of that pixel's primary ray); other pixels are left untouched.
layout(binding = 0) uniform usampler2D uHits;
layout(binding = 1) uniform sampler2D uMirrored;
uniform int uMirrorInstance;
layout(location = 0) out vec4 outColor;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint id = texelFetch(uHits, pixel, 0).x;
  if (id != uint(uMirrorInstance + 1)) discard;
  outColor = vec4(texelFetch(uMirrored, pixel, 0).rgb, 1.0);
}
