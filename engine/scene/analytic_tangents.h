#pragma once
// The exact shapes' t_u = dp/du and t_v = dp/dv: the lecture's tangents for bump mapping
// (shaders/common/bump.glsl) and the frame of normal maps on analytic shapes.
#include "engine/scene/analytic_shape.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

// dp/du and dp/dv in object space (not normalised: their lengths are the surface's metric),
// differentiated in closed form from shapePointAndNormal's parameterisation. Zero at a sphere's
// poles (dp/du).
void shapeDerivatives(const AnalyticShape& s, int part, vec2 uv, dvec3& du, dvec3& dv);

// The same in world space: through the instance's linear part.
void analyticTangents(const AnalyticInstance& a, int part, vec2 uv, vec3& tu, vec3& tv);

}  // namespace diptych
