#include "passes/raster/env_map_build.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include "engine/gl/transfer.h"
#include "passes/raster/env_maps.h"

namespace diptych {
namespace {

// Uploads an engine image (row 0 on top) as one layer of one level. transfer.h flips rows so
// that the top row lands at GL t = 1, which is right for 2D maps whose t points up; cube faces
// want their top row at t = 0 (table 8.19, environment.cpp), so `topRowAtT0` pre-flips them.
void uploadImage(const gl::Texture& texture, const Image& rgba, int layer, int level,
                 bool topRowAtT0) {
  std::vector<float> values(rgba.pixels.size());
  const std::size_t row = std::size_t(rgba.width) * 4;
  for (int y = 0; y < rgba.height; ++y) {
    const int from = topRowAtT0 ? rgba.height - 1 - y : y;
    std::copy_n(rgba.pixels.begin() + std::ptrdiff_t(from * row), row,
                values.begin() + std::ptrdiff_t(y * row));
  }
  gl::uploadTextureFloats(texture, values, layer, level);
}

// Bilinear resize of an RGBA image (texel centres aligned), for prefiltered levels computed
// below their level's size: a rough lobe is smooth, so the upsampling loses little.
Image resized(const Image& in, int width, int height) {
  if (in.width == width && in.height == height) return in;
  Image out(width, height, 4, 1.f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float fx = std::clamp((x + 0.5f) * in.width / width - 0.5f, 0.f, in.width - 1.f);
      const float fy = std::clamp((y + 0.5f) * in.height / height - 0.5f, 0.f, in.height - 1.f);
      const int x0 = int(fx), y0 = int(fy);
      const int x1 = std::min(x0 + 1, in.width - 1), y1 = std::min(y0 + 1, in.height - 1);
      const float ax = fx - float(x0), ay = fy - float(y0);
      for (int k = 0; k < 3; ++k)
        out.at(x, y, k) = (1 - ay) * ((1 - ax) * in.at(x0, y0, k) + ax * in.at(x1, y0, k)) +
                          ay * ((1 - ax) * in.at(x0, y1, k) + ax * in.at(x1, y1, k));
    }
  return out;
}

// Largest side a prefiltered level is computed at (cube face; lat-long and sphere width), then
// resized to its level: it bounds the one-time cost for large sources.
constexpr int kPrefilterCubeCap = 64, kPrefilter2dCap = 256;
constexpr int kPrefilterSourceSize = 128;  // cube face side of the prefilter's source chain
// Resampled map sizes when `resolution` is 0 (the default) and the source has another layout.
constexpr int kDefaultCubeSide = 256, kDefaultEquirectHeight = 512;

}  // namespace

// env_map_build.h
gl::Texture buildMap(const Environment& env, EnvMapKind kind, int resolution,
                     const mat3& eyeToWorld, bool prefilter, double& prefilterMs,
                     const envmap::PrefilteredCube* sphereLevels) {
  const bool constant = env.type == EnvironmentType::Color;
  // resolution 0 (cube, equirect): the source's own map when it has the map's layout, else the
  // default side. A source of that layout is used as is when the sizes agree, else resampled.
  const int res = constant ? 1 : resolution;
  const bool cubeAsIs =
      env.type == EnvironmentType::Cube && (res == 0 || res == env.cubeFaces[0].width);
  const bool equirectAsIs =
      env.type == EnvironmentType::Equirect && (res == 0 || res == env.equirect.height);
  std::vector<Image> base;  // level 0, one image per layer
  switch (kind) {
    case EnvMapKind::Cube:
      if (cubeAsIs)
        for (int f = 0; f < 6; ++f)
          base.push_back(envmap::rgbaScaled(env.cubeFaces[f], env.intensity));
      else
        for (Image& face : envmap::cubeFacesFrom(env, res > 0 ? res : kDefaultCubeSide))
          base.push_back(std::move(face));
      break;
    case EnvMapKind::Equirect:
      base.push_back(equirectAsIs
                         ? envmap::rgbaScaled(env.equirect, env.intensity)
                         : envmap::equirectFrom(env, res > 0 ? res : kDefaultEquirectHeight));
      break;
    case EnvMapKind::Sphere:
      base.push_back(envmap::sphereMapFrom(env, res, eyeToWorld));
      break;
  }
  const bool cube = kind == EnvMapKind::Cube;
  const int w = base[0].width, h = base[0].height;
  const int levels = prefilter && !constant ? envmap::prefilterLevelCount(w, h) : 1;
  gl::Texture t = cube ? gl::Texture::createCube(gl::TextureFormat::RGBA32F, w, levels)
                       : gl::Texture::create2D(gl::TextureFormat::RGBA32F, w, h, levels);
  for (std::size_t layer = 0; layer < base.size(); ++layer)
    uploadImage(t, base[layer], int(layer), 0, cube);
  // The lat-long seam at u = 0/1 is continuous: wrap, as environment.cpp's bilinear does.
  if (kind == EnvMapKind::Equirect) gl::glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  if (levels == 1) return t;
  if (kind == EnvMapKind::Sphere && sphereLevels) {
    for (int level = 1; level < levels; ++level) {
      const int side = std::max(1, w >> level);
      uploadImage(t,
                  envmap::resampledLevel(*sphereLevels, level, side, side,
                                         [&](vec2 st) {
                                           return eyeToWorld * envmap::sphereMapDirection(
                                                                   vec2(st.x, 1.f - st.y));
                                         }),
                  0, level, false);
    }
    return t;
  }
  const auto start = std::chrono::steady_clock::now();
  const envmap::CubeChain source(env, kPrefilterSourceSize);
  for (int level = 1; level < levels; ++level) {
    const float roughness = float(level) / float(levels - 1);
    const int lw = std::max(1, w >> level), lh = std::max(1, h >> level);
    const int cap = cube ? kPrefilterCubeCap : kPrefilter2dCap;
    const int cw = std::min(lw, cap), ch = std::max(1, lh * cw / lw);
    for (std::size_t layer = 0; layer < base.size(); ++layer) {
      const int f = int(layer);
      const std::function<vec3(vec2)> direction = [&](vec2 st) -> vec3 {
        if (cube) return envmap::cubeFaceDirection(f, st);
        return envmap::equirectDirection(st);
      };
      const Image filtered = envmap::prefilteredLevel(source, cw, ch, roughness, direction);
      uploadImage(t, resized(filtered, lw, lh), f, level, cube);
    }
  }
  prefilterMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return t;
}

// Faces of half the level's side (a sphere map's disc spans every direction, as two opposite
// faces do across), capped like env_cube's: rough lobes are smooth, and the per-view step is one
// bilinear lookup per texel.
envmap::PrefilteredCube sphereWorldLevels(const Environment& env, int side) {
  std::vector<int> faces(std::size_t(envmap::prefilterLevelCount(side, side)));
  for (std::size_t level = 1; level < faces.size(); ++level)
    faces[level] = std::clamp((side >> level) / 2, 1, kPrefilterCubeCap);
  return envmap::prefilteredCube(envmap::CubeChain(env, kPrefilterSourceSize), faces);
}

}  // namespace diptych
