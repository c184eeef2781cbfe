// planar_shadows: a caster's world-space vertex projected from the light onto the receiver's
// plane (common/shadow_projection.glsl), then through the camera. Two clip distances keep the
// part of the triangle that can block a receiver point's segment to the light: on the light's
// side of the plane (beyond the receiver's own flatness tolerance, so that coplanar triangles
// cast nothing) and, for a point light, nearer the plane than the light (the projection's w > 0;
// for a direction w is the constant P.L > 0).
#include "common/shadow_projection.glsl"

layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProjection;
uniform vec4 uPlane;  // oriented toward the light
uniform vec4 uLight;  // homogeneous: w = 1 a point, w = 0 the direction toward the light
uniform float uTolerance;

void main() {
  vec4 s = shadowProjectedPoint(uPlane, uLight, aPosition);
  gl_ClipDistance[0] = dot(uPlane.xyz, aPosition) + uPlane.w - uTolerance;
  gl_ClipDistance[1] = s.w;
  gl_Position = uViewProjection * s;
}
