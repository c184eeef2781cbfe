#pragma once
// SSBO binding points and the shared texture unit, from shaders/common/bindings.glsl (the one
// definition GLSL reads too), as constants in namespace diptych::gl.
namespace diptych::gl {
#include "shaders/common/bindings.glsl"
}  // namespace diptych::gl
