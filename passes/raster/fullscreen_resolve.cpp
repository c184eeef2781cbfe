#include "passes/raster/fullscreen_resolve.h"

#include "engine/gl/scene_buffers.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"

namespace diptych {

FullscreenResolve::FullscreenResolve(gl::Program program)
    : program_(std::move(program)),
      framebuffer_(gl::Framebuffer::create()),
      empty_(gl::VertexArray::create()) {}

void FullscreenResolve::draw(RenderWorld& world, const gl::Texture& target,
                             const FullscreenOptions& o) {
  world.glScene().bindStorage();
  world.glShading().bindStorage();
  framebuffer_.attachColor(0, target);
  if (o.depth)
    framebuffer_.attachDepth(*o.depth);
  else
    gl::glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, 0, 0);
  framebuffer_.checkComplete("fullscreen resolve");
  framebuffer_.bind();
  gl::glViewport(0, 0, target.width(), target.height());
  // The G-buffer's convention, under which the triangle's depth 0 is the cleared "far".
  gl::glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  if (o.depth) {
    const bool write = o.depthMode == FullscreenDepth::Write;
    gl::glEnable(GL_DEPTH_TEST);
    gl::glDepthFunc(write ? GL_ALWAYS : o.depthFunc);
    gl::glDepthMask(write ? GL_TRUE : GL_FALSE);
  } else {
    gl::glDisable(GL_DEPTH_TEST);
  }
  if (o.multiply) {
    gl::glEnable(GL_BLEND);
    gl::glBlendFunc(GL_ZERO, GL_SRC_COLOR);
  } else {
    gl::glDisable(GL_BLEND);
  }
  gl::glDisable(GL_CULL_FACE);
  gl::glDisable(GL_SCISSOR_TEST);
  if (o.scissor) {
    gl::glEnable(GL_SCISSOR_TEST);
    gl::glScissor(o.scissor->x, o.scissor->y, o.scissor->z, o.scissor->w);
  }
  gl::glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  program_.set("uViewportSize", vec2(float(target.width()), float(target.height())));
  program_.use();
  empty_.bind();
  gl::glDrawArrays(GL_TRIANGLES, 0, 3);

  // The contract of fullscreen_resolve.h, the same after every mode.
  gl::glBindVertexArray(0);
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glDisable(GL_DEPTH_TEST);
  gl::glDepthFunc(GL_LESS);
  gl::glDepthMask(GL_TRUE);
  gl::glDisable(GL_BLEND);
  gl::glBlendFunc(GL_ONE, GL_ZERO);
  gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void clearToZero(const gl::Texture& texture) {
  const float zero[4] = {0.f, 0.f, 0.f, 0.f};
  gl::glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

}  // namespace diptych
