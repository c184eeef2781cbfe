#include "engine/gl/scene_textures.h"

#include <algorithm>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/gl/bindings.h"
#include "engine/gl/loader.h"
#include "engine/shading/texture_sampling.h"

namespace diptych::gl {
namespace {

int wrapCode(WrapMode w) {
  return w == WrapMode::ClampToEdge ? 1 : (w == WrapMode::MirroredRepeat ? 2 : 0);
}

int minCode(FilterMode f) {
  switch (f) {
    case FilterMode::Nearest:
      return 0;
    case FilterMode::Linear:
      return 1;
    case FilterMode::NearestMipmapNearest:
      return 2;
    case FilterMode::LinearMipmapNearest:
      return 3;
    case FilterMode::NearestMipmapLinear:
      return 4;
    case FilterMode::LinearMipmapLinear:
      return 5;
  }
  return 5;
}

int levelsOf(int w, int h) {
  int levels = 1;
  while (w > 1 || h > 1) w = std::max(1, w / 2), h = std::max(1, h / 2), ++levels;
  return levels;
}

// A level as RGBA the way texture_sampling.cpp's texel() reads it (grey for one channel,
// alpha 1 when absent).
std::vector<float> rgba(const Image& image) {
  std::vector<float> out(std::size_t(image.width) * std::size_t(image.height) * 4);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      float* o = &out[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
      o[3] = 1.f;
      for (int c = 0; c < std::min(image.channels, 4); ++c) o[c] = image.at(x, y, c);
      if (image.channels == 1) o[1] = o[2] = o[0];
    }
  }
  return out;
}

}  // namespace

int textureFlags(const diptych::Texture& t) {
  return wrapCode(t.wrapS) + 4 * wrapCode(t.wrapT) + 16 * minCode(t.minFilter) +
         (t.magFilter == FilterMode::Nearest ? 0 : 128);
}

void GlSceneTextures::bind() const {
  glBindTextureUnit(UNIT_SCENE_TEXTURES, texels.id());
  infoTexels.bind(UNIT_SCENE_TEXTURE_INFO);
}

GlSceneTextures uploadTextures(const Scene& scene) {
  GlSceneTextures out;
  out.count = int(scene.textures.size());
  int width = 1, height = 1;
  for (const diptych::Texture& t : scene.textures)
    width = std::max(width, t.image.width), height = std::max(height, t.image.height);
  GLint maxSize = 0, maxLayers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  for (const diptych::Texture& t : scene.textures) {
    if (t.image.width > maxSize || t.image.height > maxSize)
      throw Error("texture '" + t.name + "' is " + std::to_string(t.image.width) + "x" +
                  std::to_string(t.image.height) + ", above GL_MAX_TEXTURE_SIZE " +
                  std::to_string(maxSize));
  }
  if (out.count > maxLayers)
    throw Error("scene has " + std::to_string(out.count) +
                " textures, above GL_MAX_ARRAY_TEXTURE_LAYERS " + std::to_string(maxLayers));
  const int levels = levelsOf(width, height);
  out.texels =
      Texture::create2DArray(TextureFormat::RGBA32F, width, height, std::max(1, out.count), levels);
  out.texels.setLabel("scene.textures");
  std::vector<std::int32_t> info;
  for (int k = 0; k < out.count; ++k) {
    const diptych::Texture& t = scene.textures[std::size_t(k)];
    const int count = t.image.empty() ? 0 : mipLevelCount(t);
    for (int level = 0; level < count; ++level) {
      const Image& image = mipLevel(t, level);
      // Loaded textures are RGBA already (validateScene): uploaded in place, without the copy
      // (a 2048^2 level is 64 MB); anything else expanded first.
      std::vector<float> expanded;
      if (image.channels != 4) expanded = rgba(image);
      const std::vector<float>& texels = image.channels == 4 ? image.pixels : expanded;
      // Image row y to GL row y (no flip): the shader fetches texel (x, y) of the image.
      glTextureSubImage3D(out.texels.id(), level, 0, 0, k, image.width, image.height, 1, GL_RGBA,
                          GL_FLOAT, texels.data());
      out.bytes += texels.size() * sizeof(float);
    }
    info.insert(info.end(), {t.image.width, t.image.height, count, textureFlags(t)});
  }
  if (info.empty()) info = {0, 0, 0, 0};
  out.info = Buffer::create(info.size() * sizeof(std::int32_t), info.data());
  out.infoTexels = BufferTexture::create(out.info, GL_RGBA32I, 16, "scene.texture_info");
  return out;
}

}  // namespace diptych::gl
