// G-buffer raster of an analytic sphere as a ray-cast impostor: the pixel-centre ray (built as
// gbuffer.frag builds it, diptych::primaryRay's frame) intersected with the sphere in its
// object space, the depth written from that hit, and the texel (instance + 1, 0xffffffff, NaN,
// NaN): "this instance's exact surface, not a triangle of it". The CPU passes lift it onto the
// sphere in double precision (passes/common/hits_texel.h), as they lift a triangle texel, and
// trace the pixel's ray where the exact sphere is missed after all. So the test here is
// conservative: a ray passing within a relative 5e-4 of the radius counts as a hit (a sliver
// of a pixel at the silhouette, traced on the CPU), so that float rounding never drops a pixel
// the exact sphere covers. Only visibility buffers draw impostors (engine/gl/gbuffer_raster.h).
// Ray-sphere form: the squared distance of the centre from the ray, |o - (o.d) d|^2 for unit d,
// which keeps its precision where b^2 - ac cancels (Haines et al., "Precision Improvements for
// Ray/Sphere Intersection", Ray Tracing Gems, ch. 7, 2019).
uniform vec3 uCameraPosition;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uAspect;
uniform float uTanHalfFov;
uniform vec2 uViewportSize;
uniform float uNear;

uniform uint uInstance;
uniform mat4 uToObject;
uniform float uRadius;

layout(location = 0) out uvec4 outHits;
// The sphere lies inside the box: its hit is never nearer than the box face the fragment comes
// from, so the depth written is at most the face's (reversed-Z: farther is less), which lets a
// rasterizer reject fragments by the face's depth before running this (GL 4.2 conservative
// depth).
layout(depth_less) out float gl_FragDepth;

void main() {
  vec2 ndc = 2.0 * gl_FragCoord.xy / uViewportSize - 1.0;
  // Its component along uForward is 1, so the view depth of the point at parameter t is t.
  vec3 dir = uForward + (ndc.x * uAspect * uTanHalfFov) * uRight + (ndc.y * uTanHalfFov) * uUp;
  vec3 o = (uToObject * vec4(uCameraPosition, 1.0)).xyz;
  vec3 d = (uToObject * vec4(dir, 0.0)).xyz;  // an affine map keeps t
  float len = length(d);
  vec3 n = d / len;
  float b = dot(o, n);
  vec3 l = o - b * n;  // the centre's offset from the ray's closest point
  float r2 = uRadius * uRadius;
  float h = r2 - dot(l, l);
  if (h < -1e-3 * r2) discard;
  // The near root (the camera is outside the sphere: gbuffer_raster.cpp draws impostors only
  // then), at the closest approach for a conservative near-miss.
  float t = (-b - sqrt(max(h, 0.0))) / len;
  if (t < uNear) discard;  // before the near plane: clipped, as a triangle there would be
  gl_FragDepth = uNear / t;  // reversed-Z: near / -z_view (camera_math.h)
  outHits = uvec4(uInstance + 1u, 0xffffffffu, 0x7fc00000u, 0x7fc00000u);
}
