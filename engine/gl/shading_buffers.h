#pragma once
// Materials, lights and per-instance data on the GPU, so that full-screen and forward passes
// evaluate the shared shading model (shaders/common/shading.glsl) on the same inputs as the CPU
// passes. Read in GLSL through shaders/gl/scene_shading.glsl.
//
// Limitation: colour and emission textures are not sampled on the GPU yet (the procedural
// checker is); a GL producer shading a textured material uses the material's constant colour.
#include <vector>

#include "engine/gl/objects.h"
#include "engine/gl/scene_buffers.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

// SSBO binding points, after the geometry bindings 0..3 of scene_buffers.h.
inline constexpr GLuint kSceneMaterialsBinding = 4;
inline constexpr GLuint kSceneInstancesBinding = 5;
inline constexpr GLuint kSceneLightsBinding = 6;

struct GlShadingBuffers {
  Buffer materials;  // 8 vec4 per material; entry 0 is the default material, m + 1 is materials[m]
  Buffer instances;  // 2 ints per instance: (material + 1, first triangle in the shared buffers)
  Buffer lights;     // 5 vec4 per light
  int materialCount = 0, instanceCount = 0, lightCount = 0;

  void bindStorage() const;  // binds the three buffers to their kScene* points
};

GlShadingBuffers uploadShading(const Scene& scene, const GlSceneBuffers& geometry);

}  // namespace diptych::gl
