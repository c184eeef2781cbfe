#pragma once
// The lecture's shadow polygons projected one point at a time (shaders/common/
// shadow_projection.glsl) compiled as C++: shading::shadowProjectedPoint(plane, light, x).
#include "engine/shading/shading.h"

namespace diptych::shading {
#define SHADING_FN inline
#include "shaders/common/shadow_projection.glsl"
#undef SHADING_FN
}  // namespace diptych::shading
