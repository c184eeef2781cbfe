#pragma once
// Every scene texture on the GPU with the lecture's mip chain (Texture::mips, built once by
// loadScene with engine/scene/mip_chain.h; glGenerateMipmap is never called), so the GL
// samplers in shaders/gl/scene_shading.glsl read exactly the texels the CPU sampler
// (engine/shading/texture_sampling.h) reads.
//
// Storage: one RGBA32F 2D array texture, layer k = Scene::textures[k], as large as the largest
// texture; each texture's level i sits at its own size (max(1, w >> i), max(1, h >> i)) in the
// corner of level i of its layer, and the shader does wrap and filter itself with texelFetch
// (GL's own wrap would act on the layer's size, not the texture's). Linear floats: sRGB images
// were decoded by the loader, before any filtering. Per texture an ivec4 (an RGBA32I texel of the
// buffer texture on UNIT_SCENE_TEXTURE_INFO): (width, height, levels, flags), flags = wrapS + 4
// wrapT (0 repeat, 1 clamp, 2 mirrored) + 16 minFilter code (0 N, 1 L, 2 NMN, 3 LMN, 4 NML, 5 LML)
// + 128 when the magnification filter is linear.
#include "engine/gl/objects.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

struct GlSceneTextures {
  Texture texels;            // RGBA32F 2D array (a 1x1x1 dummy when the scene has no textures)
  Buffer info;               // one ivec4 per texture
  BufferTexture infoTexels;  // its RGBA32I view
  int count = 0;
  std::size_t bytes = 0;  // texel storage, all levels
  void bind() const;      // texels to UNIT_SCENE_TEXTURES, infoTexels to UNIT_SCENE_TEXTURE_INFO
};

// Throws Error naming the texture when the scene's textures exceed the context's limits.
GlSceneTextures uploadTextures(const Scene& scene);

// The flags word described above, shared with tests.
int textureFlags(const diptych::Texture& texture);

}  // namespace diptych::gl
