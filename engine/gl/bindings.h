#pragma once
// The shared texture units, from shaders/common/bindings.glsl (the one
// definition GLSL reads too), as constants in namespace diptych::gl.
namespace diptych::gl {
#include "shaders/common/bindings.glsl"
}  // namespace diptych::gl
