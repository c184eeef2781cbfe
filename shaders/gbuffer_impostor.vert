// G-buffer raster of an analytic sphere as a ray-cast impostor (gbuffer_impostor.frag): the
// world-space box uBoxLo..uBoxHi, which holds the sphere with a margin, as 12 triangles made
// from gl_VertexID (no vertex buffer), wound counter-clockwise seen from outside. The camera is
// outside the box (gbuffer_raster.cpp), so its front faces, drawn with back faces culled, give
// every pixel the box covers one fragment.
uniform mat4 uViewProjection;
uniform vec3 uBoxLo;
uniform vec3 uBoxHi;

// Corner c of the box: bit 0 = x, bit 1 = y, bit 2 = z at the high end.
const int kCorners[36] = int[36](0, 2, 3, 0, 3, 1,   // z low
                                 4, 5, 7, 4, 7, 6,   // z high
                                 0, 4, 6, 0, 6, 2,   // x low
                                 1, 3, 7, 1, 7, 5,   // x high
                                 0, 1, 5, 0, 5, 4,   // y low
                                 2, 6, 7, 2, 7, 3);  // y high

void main() {
  int c = kCorners[gl_VertexID];
  vec3 p = mix(uBoxLo, uBoxHi, vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)));
  gl_Position = uViewProjection * vec4(p, 1.0);
}
