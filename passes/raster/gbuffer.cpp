#include "passes/raster/gbuffer.h"

#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/companion.h"
#include "engine/graph/render_world.h"
#include "passes/raster/gbuffer_surface.h"

namespace diptych {

ParamSchema GBufferPass::schema() {
  // Off by default: on llvmpipe storing costs as much as the rebuilds it saves
  // (docs/benchmarks.md, "The stored G-buffer surface").
  return {ParamSpec::boolean("surface", false,
                             "resolve the surface point once into a 3-layer target that GL passes "
                             "read (3 texels) instead of rebuilding it from the hits; same image")};
}

void GBufferPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  const int w = b.frame().width, h = b.frame().height;
  hits_ = b.write(kHits, {Format::RGBA32UI, w, h}, vec4(0.f));
  normal_ = b.write("normal", {Format::RGBA32F, w, h}, vec4(0.f));
  if (b.params().boolean("surface"))
    surface_ = b.write(kSurface, {Format::RGBA32F, w, h, 3}, vec4(0.f));
  depth_ = b.write("depth", {Format::D32F, w, h}, vec4(0.f));
}

std::string GBufferPass::adapt(const ReaderQuery& readers) {
  // The CPU passes never read the texel's (u, v) (exactTexel recomputes them), and requested
  // outputs do not count (as in placement: inspecting a signal must not change the frame).
  const bool normal = readers.consumed(normal_);
  const bool surface = surface_ != kNoResource && readers.consumed(surface_);
  barycentrics_ = readers.readOnGl(hits_) || normal || surface;
  if (barycentrics_)
    return readers.readOnGl(hits_)
               ? "exact hits: a GL pass reads the hits, (u, v) computed per fragment"
               : "exact hits: the normal or the surface is read, (u, v) computed per fragment";
  return "visibility buffer: no GL pass reads the hits, so their (u, v) are left 0; the CPU "
         "passes intersect the pixel ray with the named triangle (passes/common/hits_texel.h)";
}

void GBufferPass::execute(PassContext& c) {
  const gl::GlSceneBuffers& scene = c.world().glScene();
  // The shading buffers carry the alpha masks, so the G-buffer sees through the holes that
  // the Embree filter cuts for rays.
  const gl::GlShadingBuffers& shading = c.world().glShading();
  // Only what a live pass reads is written: the hybrid frame (CPU passes, which rebuild the
  // exact surface from the hits) pays for neither the normal nor the surface.
  gl::GBufferTargets targets{
      .hits = &c.glTexture(hits_), .depth = &c.glTexture(depth_), .barycentrics = barycentrics_};
  if (consumed(c, normal_)) targets.normal = &c.glTexture(normal_);
  if (surface_ != kNoResource && consumed(c, surface_)) targets.surface = &c.glTexture(surface_);
  c.world().glCached<gl::GBufferRasterizer>().render(scene, c.frame().camera, targets, &shading);
}

}  // namespace diptych
