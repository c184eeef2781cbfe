#pragma once
// Scene shader permutations (docs/gl.md): the defines of shaders/gl/scene_features.glsl for one
// scene, so that a GL pass compiles only the material models, texture paths and light types the
// scene has. llvmpipe executes both sides of every branch under a lane mask, uniform branches
// included, so a path that no pixel takes still costs every pixel unless it is compiled out.
#include <vector>

#include "engine/gl/shader.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

// DIPTYCH_SCENE_FEATURES plus DIPTYCH_SCENE_TEXTURES, _NORMAL_MAPS, _CHECKER, _REMAP (a material
// re-mapped per texel: remapsPerTexel), _IRIDESCENCE (0/1),
// _MODEL and _LIGHT_TYPE (the one value every shaded material / light has, else -1). The default
// material (entry 0 of the GL material buffer) counts only where a mesh has no material of its own.
std::vector<ShaderDefine> sceneShaderDefines(const Scene& scene);

// `base` followed by `extra`: the per-pass defines after the scene's.
std::vector<ShaderDefine> withDefines(std::vector<ShaderDefine> base,
                                      const std::vector<ShaderDefine>& extra);

}  // namespace diptych::gl
