#include "passes/raster/fullscreen_resolve.h"

#include "engine/gl/scene_buffers.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"

namespace diptych {
namespace {

// One framebuffer and one vertex array (core profile: the triangle needs a VAO) per world, shared
// by every full-screen draw: consecutive draws into the same attachments (GL shade's split) then
// stay one llvmpipe scene. A framebuffer per program made llvmpipe flush between the two draws:
// +0.2 ms CPU a frame at 640x480 (two constant-colour programs, medians of 400 interleaved pairs).
struct FullscreenTarget {
  gl::Framebuffer framebuffer = gl::Framebuffer::create();
  gl::VertexArray empty = gl::VertexArray::create();
};

}  // namespace

FullscreenResolve::FullscreenResolve(gl::Program program) : program_(std::move(program)) {}

void FullscreenResolve::draw(RenderWorld& world, const gl::Texture& target,
                             const FullscreenOptions& o) {
  world.glScene().bind();
  world.glShading().bind();
  auto& [framebuffer, empty] = world.glCached<FullscreenTarget>();
  framebuffer.attachColor(0, target, 0, o.layer);
  if (o.depth)
    framebuffer.attachDepth(*o.depth);
  else
    gl::glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, 0, 0);
  framebuffer.checkComplete("fullscreen resolve");
  framebuffer.bind();
  gl::glViewport(0, 0, target.width(), target.height());
  // The G-buffer's convention, under which the triangle's depth 0 is the cleared "far".
  gl::glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  // Clears obey the scissor and the write masks.
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl::glDepthMask(GL_TRUE);
  if (o.clearColor) gl::glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, &o.clearColor->x);
  if (o.clearDepth && o.depth)
    gl::glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &*o.clearDepth);
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
  if (o.scissor) {
    gl::glEnable(GL_SCISSOR_TEST);
    gl::glScissor(o.scissor->x, o.scissor->y, o.scissor->z, o.scissor->w);
  }
  program_.set("uViewportSize", vec2(float(target.width()), float(target.height())));
  program_.use();
  empty.bind();
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
