// Forward renderer: world-space positions (WorldGeometry is flattened) through any
// view-projection, with an optional world-space clip plane (n, d) kept where n.x + d >= 0.
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;
uniform vec4 uClipPlane;  // (0, 0, 0, 1) when no plane is enabled

void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  gl_ClipDistance[0] = dot(uClipPlane.xyz, aPosition) + uClipPlane.w;
}
