// Forward renderer background: the environment (resampled into a cube map) along the pixel ray.
#include "gl/pixel_ray.glsl"

layout(binding = 1) uniform samplerCube uEnvironment;
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(texture(uEnvironment, pixelRayDirection()).rgb, 1.0); }
