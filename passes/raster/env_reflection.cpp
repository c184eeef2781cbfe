#include "passes/raster/env_reflection.h"

#include <map>
#include <optional>
#include <utility>

#include "engine/gl/objects.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "passes/raster/env_maps.h"

namespace diptych {
namespace {

// Uploads an engine image (row 0 on top) as one layer. transfer.h flips rows so that the top
// row lands at GL t = 1, which is right for 2D maps whose t points up; cube faces want their
// top row at t = 0 (table 8.19, environment.cpp), so `topRowAtT0` pre-flips them.
void uploadImage(const gl::Texture& texture, const Image& rgba, int layer, bool topRowAtT0) {
  std::vector<float> values(rgba.pixels.size());
  const std::size_t row = std::size_t(rgba.width) * 4;
  for (int y = 0; y < rgba.height; ++y) {
    const int from = topRowAtT0 ? rgba.height - 1 - y : y;
    std::copy_n(rgba.pixels.begin() + std::ptrdiff_t(from * row), row,
                values.begin() + std::ptrdiff_t(y * row));
  }
  gl::uploadTextureFloats(texture, values, layer);
}

gl::Texture makeCube(const std::array<Image, 6>& faces) {
  gl::Texture t = gl::Texture::createCube(gl::TextureFormat::RGBA32F, faces[0].width);
  for (int f = 0; f < 6; ++f) uploadImage(t, faces[f], f, true);
  return t;
}

gl::Texture make2D(const Image& rgba, bool wrapS) {
  gl::Texture t = gl::Texture::create2D(gl::TextureFormat::RGBA32F, rgba.width, rgba.height);
  uploadImage(t, rgba, 0, false);
  // The lat-long seam at u = 0/1 is continuous: wrap, as environment.cpp's bilinear does.
  if (wrapS) gl::glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  return t;
}

// The map of one kind for the world's environment, built on the CPU (env_maps.h) or uploaded
// from the scene's own images when they already have the right layout. A solid colour becomes
// a one-texel map: bilinear filtering of a constant is that constant.
gl::Texture buildMap(const Environment& env, EnvMapKind kind, int resolution,
                     const mat3& eyeToWorld) {
  const bool constant = env.type == EnvironmentType::Color;
  const int res = constant ? 1 : resolution;
  switch (kind) {
    case EnvMapKind::Cube:
      if (env.type == EnvironmentType::Cube) {
        std::array<Image, 6> faces;
        for (int f = 0; f < 6; ++f) faces[f] = envmap::rgbaScaled(env.cubeFaces[f], env.intensity);
        return makeCube(faces);
      }
      return makeCube(envmap::cubeFacesFrom(env, res));
    case EnvMapKind::Equirect:
      if (env.type == EnvironmentType::Equirect)
        return make2D(envmap::rgbaScaled(env.equirect, env.intensity), true);
      return make2D(envmap::equirectFrom(env, res), true);
    case EnvMapKind::Sphere:
      return make2D(envmap::sphereMapFrom(env, res, eyeToWorld), false);
  }
  return {};
}

// GL state of the env_* passes, one per RenderWorld (render_world.h: never in the pass).
struct EnvReflectionGl {
  struct Map {
    gl::Texture texture;
    mat3 eyeToWorld{1.f};  // the frame a sphere map was built for
  };
  std::map<EnvMapKind, gl::Program> programs;
  std::map<std::pair<EnvMapKind, int>, Map> maps;

  // Compiled for the world's scene (engine/gl/shader_features.h): the material paths it lacks
  // are folded away.
  const gl::Program& program(EnvMapKind kind, const std::vector<gl::ShaderDefine>& scene) {
    auto it = programs.find(kind);
    if (it != programs.end()) return it->second;
    const char* define = kind == EnvMapKind::Cube     ? "ENV_CUBE"
                         : kind == EnvMapKind::Sphere ? "ENV_SPHERE"
                                                      : "ENV_EQUIRECT";
    return programs
        .emplace(kind,
                 gl::loadProgram({"env_reflection.comp"}, gl::withDefines(scene, {{define, ""}})))
        .first->second;
  }

  // A sphere map depends on the view; it is rebuilt when the camera turns.
  const gl::Texture& map(const Environment& env, EnvMapKind kind, int resolution,
                         const mat3& eyeToWorld) {
    Map& m = maps[{kind, resolution}];
    const bool stale = kind == EnvMapKind::Sphere && m.eyeToWorld != eyeToWorld;
    if (!m.texture || stale) {
      m.texture = buildMap(env, kind, resolution, eyeToWorld);
      m.eyeToWorld = eyeToWorld;
    }
    return m.texture;
  }
};

}  // namespace

ParamSchema EnvReflectionPass::schema(EnvMapKind kind) {
  // Sides of a resampled map: cube face, sphere map, lat-long height (width = 2 height). A
  // cube-face source for env_cube and a lat-long source for env_equirect are used as they are.
  return {ParamSpec::integer("resolution", kind == EnvMapKind::Cube ? 256 : 512, 1, 8192,
                             kind == EnvMapKind::Cube     ? "cube face side of a resampled map"
                             : kind == EnvMapKind::Sphere ? "sphere map side"
                                                          : "lat-long height of a resampled map")};
}

void EnvReflectionPass::setup(PassBuilder& b) {
  resolution_ = b.params().integer("resolution");
  io_ = slotIo(b, "reflection");
}

void EnvReflectionPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Camera& camera = c.frame().camera;
  const mat3 worldToEye(viewMatrix(camera));
  EnvReflectionGl& state = world.glCached<EnvReflectionGl>();
  const gl::Texture& map =
      state.map(world.scene().environment, kind_, resolution_, glm::transpose(worldToEye));
  const gl::GlShadingBuffers& shading = world.glShading();
  const gl::Program& program = state.program(kind_, shading.defines);

  world.glScene().bindStorage();
  shading.bindStorage();
  const gl::Texture& out = c.glTexture(io_.signal);
  program.use();
  program.set("uLightCount", shading.lightCount);
  program.set("uCameraPosition", camera.position);
  program.set("uWorldToEye", mat4(worldToEye));
  // Filtering across cube faces (GL 4.5 section 8.13.1) instead of clamping at each face edge.
  if (kind_ == EnvMapKind::Cube) gl::glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  gl::glBindTextureUnit(0, c.glTexture(io_.hits).id());
  gl::glBindTextureUnit(1, map.id());
  gl::glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl::glDispatchCompute(GLuint((out.width() + 7) / 8), GLuint((out.height() + 7) / 8), 1);
  // Later passes and readbacks fetch or copy the image written here.
  gl::glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                      GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace diptych
