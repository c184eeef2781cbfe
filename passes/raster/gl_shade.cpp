#include "passes/raster/gl_shade.h"

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/gl_environment.h"

namespace diptych {
namespace {

// GL state of the shade pass, one per RenderWorld (render_world.h: never in the pass): one
// program per combination of connected inputs, compiled for the world's scene.
struct GlShadeState {
  std::map<std::string, FullscreenResolve> programs;
  std::unique_ptr<GlEnvironment> environment;  // uploaded on the first frame
};

// SHADE_PART of gl_shade.frag: every pixel, the background only, the surfaces only.
enum class Part { All = 0, Background = 1, Surfaces = 2 };

// The permutation of gl_shade.frag for these inputs: the scene's features
// (gl/scene_features.glsl), its light count and environment kind, and which optional inputs are
// connected, all as constants. llvmpipe executes every side of a branch under a lane mask, so
// with uniforms every pixel paid for both material models, every texture path, every light
// type and every environment kind (docs/benchmarks.md has the before/after).
FullscreenResolve& shadeProgram(GlShadeState& state, RenderWorld& world, int visibilityLayers,
                                const ShadeIo& io, Part part) {
  const gl::GlShadingBuffers& shading = world.glShading();
  std::vector<gl::ShaderDefine> own = {
      {"SHADE_LIGHTS", std::to_string(shading.lightCount)},
      {"SHADE_VISIBILITY", std::to_string(visibilityLayers)},
      {"SHADE_REFLECTION", io.reflection != kNoResource ? "1" : "0"},
      {"SHADE_TRANSMISSION", io.transmission != kNoResource ? "1" : "0"},
      {"SHADE_ALBEDO", io.albedo != kNoResource ? "1" : "0"},
      {"SCENE_ENVIRONMENT_TYPE", std::to_string(state.environment->type())},
      {"SHADE_PART", std::to_string(int(part))}};
  own = gl::withDefines(own, surfaceDefines(io.surface));
  std::string key;
  for (const gl::ShaderDefine& d : own) key += d.name + "=" + d.value + ",";
  auto it = state.programs.find(key);
  if (it == state.programs.end())
    it =
        state.programs
            .emplace(key, FullscreenResolve(gl::loadProgram({"fullscreen.vert", "gl_shade.frag"},
                                                            gl::withDefines(shading.defines, own))))
            .first;
  return it->second;
}

void bindImage(GLuint unit, const gl::Texture& texture, GLenum format, bool layered) {
  gl::glBindImageTexture(unit, texture.id(), 0, layered ? GL_TRUE : GL_FALSE, 0, GL_READ_ONLY,
                         format);
}

}  // namespace

void shadeOnGl(PassContext& c, const ShadeIo& io) {
  RenderWorld& world = c.world();
  GlShadeState& state = world.glCached<GlShadeState>();
  if (!state.environment)
    state.environment = std::make_unique<GlEnvironment>(world.scene().environment);
  const int visibilityLayers =
      io.lightVisibility != kNoResource ? c.desc(io.lightVisibility).layers : 0;
  const bool split = io.depth != kNoResource && world.glCached<GlShadeOptions>().split;
  FullscreenResolve& first =
      shadeProgram(state, world, visibilityLayers, io, split ? Part::Background : Part::All);
  FullscreenResolve* second =
      split ? &shadeProgram(state, world, visibilityLayers, io, Part::Surfaces) : nullptr;
  const Camera& camera = c.frame().camera;
  const FrameSettings& frame = c.frame();

  // The ray frame of primaryRay() (engine/scene/camera_math.cpp), as the G-buffer builds it.
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  for (const FullscreenResolve* resolve : {&first, second}) {
    if (!resolve) continue;
    const gl::Program& program = resolve->program();
    program.set("uCameraPosition", camera.position);
    program.set("uForward", forward);
    program.set("uRight", right);
    program.set("uUp", glm::cross(right, forward));
    program.set("uAspect", float(frame.width) / float(frame.height));
    program.set("uTanHalfFov", std::tan(0.5f * camera.verticalFov));
    program.set("uAmbient", world.scene().ambient);
    state.environment->bind(program);
  }

  bindImage(0, c.glTexture(io.hits), GL_RGBA32UI, false);
  bindSurface(c, io.surface);
  if (visibilityLayers > 0)
    bindImage(visibilityLayers > 1 ? 2 : 1, c.glTexture(io.lightVisibility), GL_R32F,
              visibilityLayers > 1);
  const ResourceId optional[] = {io.reflection, io.transmission, io.albedo};
  GLuint unit = 3;
  for (ResourceId id : optional) {
    if (id != kNoResource) bindImage(unit, c.glTexture(id), GL_RGBA32F, false);
    ++unit;
  }
  // Producers that wrote their signal with imageStore made it visible to image loads only
  // after this barrier (GL 4.5, section 7.12.2).
  gl::glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  const gl::Texture& color = c.glTexture(io.color);
  if (!split) {
    first.draw(world, color);
    return;
  }
  // The background, then the surfaces, each behind an early depth test against the G-buffer's
  // depth (never written): the full-screen triangle lies at depth 0, the value the G-buffer
  // clears to and keeps where no surface is (reversed-Z, every surface > 0), so GL_GEQUAL
  // passes only there and GL_LESS only on surfaces.
  const gl::Texture& depth = c.glTexture(io.depth);
  first.draw(world, color,
             {.depth = &depth, .depthMode = FullscreenDepth::Test, .depthFunc = GL_GEQUAL});
  second->draw(world, color,
               {.depth = &depth, .depthMode = FullscreenDepth::Test, .depthFunc = GL_LESS});
}

}  // namespace diptych
