#include "passes/raster/env_reflection.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "engine/core/log.h"
#include "engine/gl/objects.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/shading/shading.h"
#include "passes/raster/env_map_build.h"
#include "passes/raster/env_maps.h"
#include "passes/raster/env_prefilter.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/screen_rect.h"

namespace diptych {
namespace {

// GL state of the env_* passes, one per RenderWorld (render_world.h: never in the pass).
struct EnvReflectionGl {
  struct Map {
    gl::Texture texture;
    mat3 eyeToWorld{1.f};  // the frame a sphere map was built for
  };
  // (kind, stored surface) -> the full-screen lookup (shaders/env_reflection.frag)
  std::map<std::pair<EnvMapKind, bool>, FullscreenResolve> programs;
  std::map<std::tuple<EnvMapKind, int, bool>, Map> maps;

  // Compiled for the world's scene (engine/gl/shader_features.h): the material paths it lacks
  // are folded away.
  FullscreenResolve& program(EnvMapKind kind, const std::vector<gl::ShaderDefine>& scene,
                             ResourceId surface) {
    auto it = programs.find({kind, surface != kNoResource});
    if (it != programs.end()) return it->second;
    const char* define = kind == EnvMapKind::Cube     ? "ENV_CUBE"
                         : kind == EnvMapKind::Sphere ? "ENV_SPHERE"
                                                      : "ENV_EQUIRECT";
    return programs
        .emplace(
            std::pair(kind, surface != kNoResource),
            FullscreenResolve(gl::loadProgram(
                {"fullscreen.vert", "env_reflection.frag"},
                gl::withDefines(gl::withDefines(scene, {{define, ""}}), surfaceDefines(surface)))))
        .first->second;
  }

  // env_sphere's view-independent levels per sphere-map side (sphereWorldLevels).
  std::map<int, envmap::PrefilteredCube> sphereLevels;

  // What this call did, for the pass's counters (the test reads them: a counter, not a time).
  struct Built {
    bool map = false;         // a texture was (re)built
    double mapMs = 0;         // its build (resampling and upload), prefilter excluded, in ms
    double prefilterMs = -1;  // levels were integrated (a one-time cost), in ms
  };

  // A sphere map depends on the view: its level 0 is resampled from the environment and its
  // prefiltered levels from sphereLevels when the camera turns (not when it moves); the GGX
  // integration itself runs once per environment and side.
  const gl::Texture& map(const Environment& env, EnvMapKind kind, int resolution,
                         const mat3& eyeToWorld, bool prefilter, Built& built) {
    Map& m = maps[{kind, resolution, prefilter}];
    const bool stale = kind == EnvMapKind::Sphere && m.eyeToWorld != eyeToWorld;
    if (m.texture && !stale) return m.texture;
    const envmap::PrefilteredCube* levels = nullptr;
    if (kind == EnvMapKind::Sphere && prefilter && env.type != EnvironmentType::Color) {
      auto it = sphereLevels.find(resolution);
      if (it == sphereLevels.end()) {
        const auto start = std::chrono::steady_clock::now();
        it = sphereLevels.emplace(resolution, sphereWorldLevels(env, resolution)).first;
        built.prefilterMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
      }
      levels = &it->second;
    }
    const auto start = std::chrono::steady_clock::now();
    const double prefilterBefore = built.prefilterMs;
    m.texture = buildMap(env, kind, resolution, eyeToWorld, prefilter, built.prefilterMs, levels);
    m.eyeToWorld = eyeToWorld;
    built.map = true;
    // buildMap integrates env_cube's and env_equirect's levels inside its own time.
    const double inside = built.prefilterMs != prefilterBefore ? built.prefilterMs : 0.0;
    built.mapMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count() -
        inside;
    return m.texture;
  }
};

ParamSpec prefilterParam() {
  return ParamSpec::boolean("prefilter", true,
                            "GGX-prefiltered levels for rough glTF materials (split sum); false: "
                            "one mirror lookup, faded by roughness");
}

}  // namespace

ParamSchema EnvReflectionPass::schema(EnvMapKind kind) {
  // Sides of a map: cube face, sphere map, lat-long height (width = 2 height). For env_cube
  // and env_equirect, 0 uses a source of the map's own layout (cube faces, lat-long) as it is
  // and resamples any other at 256 / 512; a non-zero side resamples unless the source has it.
  if (kind == EnvMapKind::Sphere)
    return {ParamSpec::integer("resolution", 512, 1, 8192, "sphere map side"), prefilterParam()};
  return {ParamSpec::integer("resolution", 0, 0, 8192,
                             kind == EnvMapKind::Cube
                                 ? "cube face side; 0: cube-face sources as they are, else 256"
                                 : "lat-long height; 0: lat-long sources as they are, else 512"),
          prefilterParam()};
}

void EnvReflectionPass::setup(PassBuilder& b) {
  resolution_ = b.params().integer("resolution");
  // Prefiltered levels only serve glTF lobes: a scene without one keeps the single-level map.
  prefilter_ = b.params().boolean("prefilter") &&
               std::ranges::any_of(b.scene().materials, [](const Material& m) {
                 return m.model == ShadingModel::Gltf && shading::materialHasReflection(m, true);
               });
  io_ = slotIo(b, "reflection");
  surface_ = readSurface(b, io_.hits);
}

void EnvReflectionPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Camera& camera = c.frame().camera;
  const mat3 worldToEye(viewMatrix(camera));
  EnvReflectionGl& state = world.glCached<EnvReflectionGl>();
  EnvReflectionGl::Built built;
  const gl::Texture& map = state.map(world.scene().environment, kind_, resolution_,
                                     glm::transpose(worldToEye), prefilter_, built);
  // Counters of this frame: map_builds (the texture was built; env_sphere: the camera turned)
  // and prefilter_builds (the GGX levels were integrated: once per environment).
  c.count("map_builds", built.map ? 1.0 : 0.0);
  c.count("prefilter_builds", built.prefilterMs >= 0.0 ? 1.0 : 0.0);
  const char* name = kind_ == EnvMapKind::Cube     ? "env_cube"
                     : kind_ == EnvMapKind::Sphere ? "env_sphere"
                                                   : "env_equirect";
  // The cube and lat-long maps depend on the environment only: built once per world, a
  // one-time cost reported apart (as the static shadow map), so a measured frame that built one
  // is measured again. The sphere map follows the camera's rotation: its rebuilds stay in frames.
  if (built.map && kind_ != EnvMapKind::Sphere) {
    c.count("map_ms", built.mapMs);
    world.addOneTime(std::string(name) + " map", built.mapMs);
  }
  if (built.prefilterMs >= 0.0) {  // a one-time cost per environment, reported apart
    c.count("prefilter_ms", built.prefilterMs);
    world.addOneTime(std::string(name) + " prefilter", built.prefilterMs);
    log().info("{}: GGX-prefiltered {} levels in {:.1f} ms (once per environment)", name,
               map.levels() - 1, built.prefilterMs);
  }
  const gl::GlShadingBuffers& shading = world.glShading();
  FullscreenResolve& pass = state.program(kind_, shading.defines, surface_);
  const gl::Program& program = pass.program();

  const gl::Texture& out = c.glTexture(io_.signal);
  program.set("uLightCount", shading.lightCount);
  program.set("uCameraPosition", camera.position);
  program.set("uWorldToEye", mat4(worldToEye));
  program.set("uMaxLod", float(map.levels() - 1));
  // Filtering across cube faces (GL 4.5 section 8.13.1) instead of clamping at each face edge.
  if (kind_ == EnvMapKind::Cube) gl::glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  gl::glBindTextureUnit(0, c.glTexture(io_.hits).id());
  gl::glBindTextureUnit(1, map.id());
  bindSurface(c, surface_);
  // 0 where the material cannot reflect: those pixels are discarded before any surface work,
  // and the lookup is scissored to the window rectangle of the meshes whose material may
  // reflect (the shader's gate, sceneHitMayReflect): no other pixel can show one of them.
  clearToZero(out);
  const Scene& scene = world.scene();
  const WorldGeometry& geometry = world.geometry();
  const bool lobe = map.levels() > 1;  // as the shader's uMaxLod > 0
  const mat4 viewProj =
      reversedZProjection(camera, float(out.width()) / float(out.height())) * viewMatrix(camera);
  std::vector<PixelRect> rects;
  const PixelRect covered = unionRect(
      meshBounds(world), viewProj, out.width(), out.height(),
      [&](int m) {
        return shading::materialHasReflection(
            scene.material(geometry.meshes[std::size_t(m)].material), lobe);
      },
      rects);
  c.count("env_scissor_pixels", covered.empty() ? 0.0
                                                : double(covered.hi.x - covered.lo.x) *
                                                      double(covered.hi.y - covered.lo.y));
  if (!covered.empty()) pass.draw(world, out, {.scissor = covered.scissor()});
}

}  // namespace diptych
