#pragma once
// Materials, lights and per-instance data on the GPU, so that full-screen and forward passes
// evaluate the shared shading model (shaders/common/shading.glsl) on the same inputs as the CPU
// passes. Read in GLSL through shaders/gl/scene_shading.glsl.
//
// Every scene texture is uploaded with its mip chain (engine/gl/scene_textures.h; on demand, by
// RenderWorld::glShading) and sceneMaterial samples base colour, emission, metallic-roughness and
// occlusion as resolveMaterial does on the CPU. The alpha of alpha-masked (AlphaMode::Mask)
// materials' colour textures is also kept in its own R32F array for the cut-outs of the G-buffer
// and shadow-map depth passes (sceneMaterialAlpha in GLSL).
#include <vector>

#include "engine/gl/objects.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/scene_textures.h"
#include "engine/gl/shader_features.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

// How a raster pass draws a mesh of a given material.
enum class AlphaDraw {
  Opaque,      // not masked, or masked with a constant coverage at or above the cutoff
  Hidden,      // masked with a constant coverage below the cutoff: cut out everywhere
  AlphaTested  // masked with a colour texture: per-fragment sceneMaterialAlpha test
};

// AlphaDraw of scene.material(material), from the same coverage rule as resolveMaterial.
AlphaDraw alphaDraw(const Scene& scene, int material);

// Largest side of an alpha-mask layer; larger textures are resampled down to it.
inline constexpr int kMaxAlphaMaskSize = 2048;

struct GlShadingBuffers {
  Buffer materials;  // 20 vec4 per material (packMaterial); entry 0 is the default material, m + 1
                     // is materials[m]
  Buffer instances;  // 2 ints per instance: (material + 1, first triangle in the shared buffers)
  Buffer lights;     // 5 vec4 per light
  // Their views (RGBA32F, RG32I, RGBA32F) on UNIT_SCENE_MATERIALS, _INSTANCES, _LIGHTS.
  BufferTexture materialTexels, instanceTexels, lightTexels;
  // R32F 2D array: layer k holds the alpha of one colour texture used by a masked material, at
  // its own size in the corner of the layer (GLSL does the wrap and the filter, as
  // sampleTexture does, with texelFetch). A 1x1x1 dummy when no material is alpha-tested.
  Texture alphaMasks;
  int alphaMaskLayers = 0;
  // Every Scene::textures entry with its mip chain: not uploaded by uploadShading, but by
  // RenderWorld::glShading(true) (empty, bound as id 0, until then).
  GlSceneTextures textures;
  std::vector<AlphaDraw> drawModes;  // index material + 1, as `materials`
  int materialCount = 0, instanceCount = 0, lightCount = 0;
  // The scene's shader permutation (shader_features.h): passes compile with these first.
  std::vector<ShaderDefine> defines;

  // Binds the three views to their UNIT_SCENE_* units, alphaMasks to UNIT_SCENE_ALPHA_MASKS and
  // the textures (engine/gl/bindings.h).
  void bind() const;
  AlphaDraw alphaDraw(int material) const;  // -1 or out of range: the default material
  bool anyAlphaTested() const { return alphaMaskLayers > 0; }
};

GlShadingBuffers uploadShading(const Scene& scene, const GlSceneBuffers& geometry);

}  // namespace diptych::gl
