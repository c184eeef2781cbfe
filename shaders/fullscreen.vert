// One triangle covering the viewport, no vertex buffer: vertex ids 0, 1, 2 give
// (-1, -1), (3, -1), (-1, 3) in clip space, at depth 0 (the far end of reversed-Z).
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
