#include "passes/raster/gl_shade.h"

#include <cmath>

#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/gl_environment.h"

namespace diptych {
namespace {

// GL state of the shade pass, one per RenderWorld (render_world.h: never in the pass).
struct GlShadeState {
  FullscreenResolve resolve{gl::loadProgram({"fullscreen.vert", "gl_shade.frag"})};
  std::unique_ptr<GlEnvironment> environment;  // uploaded on the first frame
};

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
  const gl::Program& program = state.resolve.program();
  const Camera& camera = c.frame().camera;
  const FrameSettings& frame = c.frame();

  // The ray frame of primaryRay() (engine/scene/camera_math.cpp), as the G-buffer builds it.
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  program.set("uCameraPosition", camera.position);
  program.set("uForward", forward);
  program.set("uRight", right);
  program.set("uUp", glm::cross(right, forward));
  program.set("uAspect", float(frame.width) / float(frame.height));
  program.set("uTanHalfFov", std::tan(0.5f * camera.verticalFov));
  program.set("uAmbient", world.scene().ambient);
  program.set("uLightCount", world.glShading().lightCount);
  state.environment->bind(program);

  bindImage(0, c.glTexture(io.hits), GL_RGBA32UI, false);
  int visibilityLayers = 0;
  if (io.lightVisibility != kNoResource) {
    visibilityLayers = c.desc(io.lightVisibility).layers;
    bindImage(visibilityLayers > 1 ? 2 : 1, c.glTexture(io.lightVisibility), GL_R32F,
              visibilityLayers > 1);
  }
  program.set("uVisibilityCount", visibilityLayers);
  const std::pair<ResourceId, const char*> optional[] = {{io.reflection, "uHasReflection"},
                                                         {io.transmission, "uHasTransmission"},
                                                         {io.albedo, "uHasAlbedo"}};
  GLuint unit = 3;
  for (const auto& [id, flag] : optional) {
    if (id != kNoResource) bindImage(unit, c.glTexture(id), GL_RGBA32F, false);
    program.set(flag, id != kNoResource ? 1 : 0);
    ++unit;
  }
  // Producers that wrote their signal with imageStore made it visible to image loads only
  // after this barrier (GL 4.5, section 7.12.2).
  gl::glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  state.resolve.draw(world, c.glTexture(io.color));
}

}  // namespace diptych
