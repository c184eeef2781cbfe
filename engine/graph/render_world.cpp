#include "engine/graph/render_world.h"

#include "engine/core/error.h"
#include "engine/gl/context.h"
#include "engine/gl/forward_renderer.h"
#include "engine/gl/loader.h"
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

void RenderWorld::addOneTime(const std::string& what, double ms) {
  const std::lock_guard lock(oneTimeMutex_);
  oneTimeMs[what] += ms;
}

double RenderWorld::oneTimeTotalMs() const {
  const std::lock_guard lock(oneTimeMutex_);
  double sum = 0;
  for (const auto& [what, ms] : oneTimeMs) sum += ms;
  return sum;
}

const RtScene& RenderWorld::rtScene() {
  std::call_once(rtOnce_, [this] {
    const Stopwatch clock;
    device_ = std::make_unique<RtDevice>();
    rt_ = std::make_unique<RtScene>(*device_, world_, scene_);
    addOneTime(kBvhBuild, clock.milliseconds());
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
    const Stopwatch clock;
    glContext().makeCurrent();
    glScene_ = std::make_unique<gl::GlSceneBuffers>(gl::uploadScene(world_));
    gl::glFinish();  // a driver may copy later: the upload completes here, not in a frame
    addOneTime(kGlSceneUpload, clock.milliseconds());
  }
  return *glScene_;
}

const gl::GlShadingBuffers& RenderWorld::glShading(bool textures) {
  if (!glShading_) {
    const gl::GlSceneBuffers& geometry = glScene();
    const Stopwatch clock;
    glShading_ = std::make_unique<gl::GlShadingBuffers>(gl::uploadShading(scene_, geometry));
    gl::glFinish();
    addOneTime(kGlShadingUpload, clock.milliseconds());
  }
  if (textures && !glTexturesUploaded_) {
    const Stopwatch clock;
    glContext().makeCurrent();
    glShading_->textures = gl::uploadTextures(scene_);
    gl::glFinish();
    glTexturesUploaded_ = true;
    addOneTime(kGlTextureUpload, clock.milliseconds());
  }
  return *glShading_;
}

gl::ForwardScene RenderWorld::forwardScene() {
  const gl::GlShadingBuffers& shading = glShading();
  return {scene_, *glScene_, shading};
}

}  // namespace diptych
