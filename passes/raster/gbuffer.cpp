#include "passes/raster/gbuffer.h"

#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"

namespace diptych {

void GBufferPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  const int w = b.frame().width, h = b.frame().height;
  hits_ = b.write(kHits, {Format::RGBA32UI, w, h}, vec4(0.f));
  normal_ = b.write("normal", {Format::RGBA32F, w, h}, vec4(0.f));
  depth_ = b.write("depth", {Format::D32F, w, h}, vec4(0.f));
}

void GBufferPass::execute(PassContext& c) {
  const gl::GlSceneBuffers& scene = c.world().glScene();
  // The shading buffers carry the alpha masks, so the G-buffer sees through the holes that
  // the Embree filter cuts for rays.
  const gl::GlShadingBuffers& shading = c.world().glShading();
  c.world().glCached<gl::GBufferRasterizer>().render(scene, c.frame().camera, c.glTexture(hits_),
                                                     c.glTexture(normal_), c.glTexture(depth_),
                                                     &shading);
}

}  // namespace diptych
