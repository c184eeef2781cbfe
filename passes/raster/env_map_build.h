#pragma once
// The env_* passes' maps (passes/raster/env_reflection.cpp): built once per environment on the
// CPU (env_maps.h) or uploaded from the scene's own images, with GGX-prefiltered levels for rough
// glTF materials (env_prefilter.h). docs/environment-maps.md.
#include "engine/core/math.h"
#include "engine/gl/objects.h"
#include "engine/scene/environment.h"
#include "passes/raster/env_prefilter.h"
#include "passes/raster/env_reflection.h"

namespace diptych {

// The map of one kind for the world's environment, built on the CPU (env_maps.h) or uploaded
// from the scene's own images when they already have the right layout. A solid colour becomes
// a one-texel map: bilinear filtering of a constant is that constant. With `prefilter`, levels
// 1.. hold the GGX-prefiltered environment (env_prefilter.h); level 0 is the map itself.
// env_sphere's levels come from `sphereLevels` (world-space cube levels, integrated once per
// environment); the other kinds integrate their own levels here and time it in `prefilterMs`.
gl::Texture buildMap(const Environment& env, EnvMapKind kind, int resolution,
                     const mat3& eyeToWorld, bool prefilter, double& prefilterMs,
                     const envmap::PrefilteredCube* sphereLevels);

// env_sphere's prefiltered levels as world-space cubes: they depend on the environment and the
// level count only, not on the view.
envmap::PrefilteredCube sphereWorldLevels(const Environment& env, int side);

}  // namespace diptych
