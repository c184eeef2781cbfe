#pragma once
// Environment maps resampled on the CPU from Scene::environment. Every texel is one
// sampleEnvironment() lookup (engine/scene/environment.cpp, the function ray misses use), so a
// map differs from the exact environment only by where it samples and how the GPU filters it.
// Images follow the engine convention (row 0 on top) and are RGBA with alpha 1; the
// environment's intensity is baked in, as sampleEnvironment() applies it.
#include <array>

#include "engine/core/image.h"
#include "engine/scene/scene.h"

namespace diptych::envmap {

// Unit world direction through cube-face texel coordinates (s, t) in [0,1]^2, t = 0 on the
// face's top row: the inverse of the face selection of OpenGL 4.5 table 8.19 (cubeFace()).
vec3 cubeFaceDirection(int face, vec2 st);

// Six square faces in GL order (+x, -x, +y, -y, +z, -z), `size` texels on a side.
std::array<Image, 6> cubeFacesFrom(const Environment& env, int size);

// The unit direction at lat-long coordinates (u, v) in [0,1]^2 (v = 0 on the top row): the
// inverse of environment.cpp's u = 0.5 + atan2(d.z, d.x) / 2pi, v = acos(d.y) / pi.
vec3 equirectDirection(vec2 uv);

// Lat-long panorama of 2 height x height texels in environment.cpp's (u, v) convention.
Image equirectFrom(const Environment& env, int height);

// GL_SPHERE_MAP coordinates (OpenGL 2.1 compatibility spec, section 2.12.4) of a unit
// reflection vector r given in the map's eye frame (viewer on +z looking down -z):
//   m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),  s = rx / m + 1/2,  t = ry / m + 1/2  (t up).
// r = (0, 0, -1) (straight away from the viewer) is the singular point: the whole rim of the
// map; it returns (1, 1/2), one point of that rim.
vec2 sphereMapCoord(vec3 rEye);

// The inverse: the eye-frame reflection direction at (s, t). The map is a mirror ball seen
// orthographically: n = (x, y, sqrt(1 - x^2 - y^2)) with (x, y) = 2 (s, t) - 1, and
// r = reflect(-z, n) = (2 nz x, 2 nz y, 2 nz^2 - 1). Outside the disc, (x, y) is pulled onto
// the rim, so the corners repeat the rim (r = -z) and bilinear filtering at the rim stays sane.
vec3 sphereMapDirection(vec2 st);

// A size x size sphere map in the frame whose axes (world coordinates) are the columns of
// eyeToWorld (camera right, up, backward: the inverse rotation of viewMatrix()).
Image sphereMapFrom(const Environment& env, int size, const mat3& eyeToWorld);

// `image` as RGBA (missing channels: grey replicated, alpha 1), each RGB value times `scale`.
Image rgbaScaled(const Image& image, float scale);

}  // namespace diptych::envmap
