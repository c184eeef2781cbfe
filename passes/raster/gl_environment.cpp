#include "passes/raster/gl_environment.h"

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gl/bindings.h"
#include "engine/gl/transfer.h"
#include "passes/raster/env_maps.h"

namespace diptych {
namespace {

// RGBA floats of `image` times `scale`, with sampleEnvironment()'s channel rule: channel k reads
// min(k, channels - 1), so a grey image is replicated.
std::vector<float> rgbaScaled(const Image& image, float scale) {
  std::vector<float> out(std::size_t(image.width) * image.height * 4, 1.f);
  const int channels = std::max(1, std::min(image.channels, 3));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int k = 0; k < 3; ++k)
        out[(std::size_t(y) * image.width + x) * 4 + k] =
            image.at(x, y, std::min(k, channels - 1)) * scale;
  return out;
}

}  // namespace

GlEnvironment::GlEnvironment(const Environment& env) {
  const bool known = env.type == EnvironmentType::Color || env.type == EnvironmentType::Equirect ||
                     env.type == EnvironmentType::Cube;
  if (!known) {
    // A kind this lookup does not repeat: resampled into a lat-long map by sampleEnvironment()
    // (exact at the texel centres, bilinear between), and said once.
    log().warn("GL background: environment kind {} is resampled into a 2048x1024 lat-long map",
               int(env.type));
    Environment resampled;
    resampled.type = EnvironmentType::Equirect;
    resampled.equirect = envmap::equirectFrom(env, 1024);
    *this = GlEnvironment(resampled);
    return;
  }
  const bool equirect = env.type == EnvironmentType::Equirect && !env.equirect.empty();
  const bool cube = env.type == EnvironmentType::Cube && !env.cubeFaces[0].empty();
  // The same values sampleEnvironment() returns for an empty image: black.
  type_ = equirect ? 1 : cube ? 2 : 0;
  color_ = env.type == EnvironmentType::Color ? env.color * env.intensity : vec3(0.f);
  if (equirect) {
    texels_ = gl::Texture::create2DArray(gl::TextureFormat::RGBA32F, env.equirect.width,
                                         env.equirect.height, 1);
    gl::uploadTextureFloats(texels_, rgbaScaled(env.equirect, env.intensity), 0);
  } else if (cube) {
    const int side = env.cubeFaces[0].width;
    texels_ = gl::Texture::create2DArray(gl::TextureFormat::RGBA32F, side, side, 6);
    for (int f = 0; f < 6; ++f) {
      if (env.cubeFaces[f].width != side || env.cubeFaces[f].height != side)
        throw Error("environment cube face " + std::to_string(f) + " is not " +
                    std::to_string(side) + "x" + std::to_string(side));
      gl::uploadTextureFloats(texels_, rgbaScaled(env.cubeFaces[f], env.intensity), f);
    }
  } else {
    texels_ = gl::Texture::create2DArray(gl::TextureFormat::RGBA32F, 1, 1, 1);
    gl::uploadTextureFloats(texels_, {0.f, 0.f, 0.f, 1.f}, 0);
  }
}

void GlEnvironment::bind(const gl::Program& program) const {
  program.set("uEnvironmentType", type_);
  program.set("uEnvironmentColor", color_);
  gl::glBindTextureUnit(GLuint(gl::UNIT_SCENE_ENVIRONMENT), texels_.id());
}

}  // namespace diptych
