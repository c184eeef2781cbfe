// The world-space ray through the centre of the current pixel for a camera given by matrices
// (engine/gl/forward_renderer.h): a point of the pixel is unprojected with the inverse
// view-projection and joined to the eye. Valid for any invertible projection (mirrored views,
// cube faces); for the frame camera it is the ray of diptych::primaryRay up to float rounding.
uniform mat4 uInverseViewProjection;
uniform vec3 uEye;
uniform vec2 uViewportSize;

// The ray through window position `fragCoord` (a pixel centre is gl_FragCoord.xy).
vec3 pixelRayDirectionAt(vec2 fragCoord) {
  vec2 ndc = 2.0 * fragCoord / uViewportSize - 1.0;
  // Depth 0.5 is a finite point for reversed-Z infinite projections (depth 0 is at infinity).
  vec4 h = uInverseViewProjection * vec4(ndc, 0.5, 1.0);
  return h.xyz / h.w - uEye;
}

vec3 pixelRayDirection() { return pixelRayDirectionAt(gl_FragCoord.xy); }
