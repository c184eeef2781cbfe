#include "engine/graph/render_world.h"

#include "engine/core/error.h"
#include "engine/gl/context.h"
#include "engine/gl/forward_renderer.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/shading_buffers.h"

namespace diptych {

RenderWorld::RenderWorld(const Scene& scene, gl::GlContext* context)
    : scene_(scene), world_(flattenScene(scene)), context_(context) {}

RenderWorld::~RenderWorld() {
  if (!context_) return;
  context_->makeCurrent();  // GL objects die with their context current
  glCache_.clear();
  glShading_.reset();
  glScene_.reset();
}

const RtScene& RenderWorld::rtScene() {
  std::call_once(rtOnce_, [this] {
    device_ = std::make_unique<RtDevice>();
    rt_ = std::make_unique<RtScene>(*device_, world_, scene_);
  });
  return *rt_;
}

void RenderWorld::makeContextCurrent() {
  glContext().makeCurrent();
}

gl::GlContext& RenderWorld::glContext() {
  if (!context_) throw Error("this frame needs OpenGL but no GL context was created");
  return *context_;
}

const gl::GlSceneBuffers& RenderWorld::glScene() {
  if (!glScene_) {
    glContext().makeCurrent();
    glScene_ = std::make_unique<gl::GlSceneBuffers>(gl::uploadScene(world_));
  }
  return *glScene_;
}

const gl::GlShadingBuffers& RenderWorld::glShading() {
  if (!glShading_) {
    const gl::GlSceneBuffers& geometry = glScene();
    glShading_ = std::make_unique<gl::GlShadingBuffers>(gl::uploadShading(scene_, geometry));
  }
  return *glShading_;
}

gl::ForwardScene RenderWorld::forwardScene() {
  const gl::GlShadingBuffers& shading = glShading();
  return {scene_, *glScene_, shading};
}

}  // namespace diptych
