// One triangle covering the viewport (vertices (-1,-1), (3,-1), (-1,3)), no vertex buffer:
// the shadow-map lookup runs once per pixel of the G-buffer.
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
