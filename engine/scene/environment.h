#pragma once
// Background radiance lookups on the CPU (ray misses, reference renders, tests).
#include "engine/scene/scene.h"

namespace diptych {

// Radiance arriving from `direction` (need not be unit length; zero returns black), times
// Environment::intensity. Colour: the constant. Equirect: u = 0.5 + atan2(d.z, d.x) / (2 pi),
// v = acos(clamp(d.y, -1, 1)) / pi, v = 0 on the top row, bilinear with u wrapping and v clamped.
// Cube: OpenGL face selection and (s, t) (OpenGL 4.5 spec, table 8.19), bilinear, clamped at
// the face edge; face images are stored with row 0 at the top (t = 0 is the top row).
vec3 sampleEnvironment(const Environment& environment, const vec3& direction);

// The cube face (0..5 = +x,-x,+y,-y,+z,-z) and its (s, t) in [0,1] for a direction.
int cubeFace(const vec3& direction, vec2& st);

}  // namespace diptych
