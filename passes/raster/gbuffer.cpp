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
                             "read (3 texels) instead of rebuilding it from the hits; same image"),
          ParamSpec::boolean("impostors", true,
                             "in a visibility buffer, draw analytic spheres as ray-cast impostors "
                             "(their box) instead of their triangles, where no reader needs the "
                             "triangles: the exact sphere's silhouette, at a box's raster cost")};
}

void GBufferPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  const int w = b.frame().width, h = b.frame().height;
  hits_ = b.write(kHits, {Format::RGBA32UI, w, h}, vec4(0.f));
  normal_ = b.write("normal", {Format::RGBA32F, w, h}, vec4(0.f));
  impostorsAllowed_ = b.params().boolean("impostors");
  if (b.params().boolean("surface"))
    surface_ = b.write(kSurface, {Format::RGBA32F, w, h, 3}, vec4(0.f));
  depth_ = b.write("depth", {Format::D32F, w, h}, vec4(0.f));
}

std::string GBufferPass::adapt(const ReaderQuery& readers) {
  // A CPU reader computes (u, v) itself where the texel has none (exactTexel). Outputs do not
  // count beside a CPU reader (compare requests the hits beside its timed frames: inspecting must
  // not change the cost); a G-buffer nobody reads is one being inspected, and keeps them.
  const bool gl = readers.readIn(hits_, Domain::Gl);
  const bool cpu = readers.readIn(hits_, Domain::Cpu);
  const bool normal = readers.consumed(normal_);
  const bool surface = surface_ != kNoResource && readers.consumed(surface_);
  barycentrics_ = gl || !cpu || normal || surface;
  // Every CPU reader lifts the texels onto the exact surface: analytic spheres need no triangles.
  impostors_ = impostorsAllowed_ && !barycentrics_ && !readers.trianglesRead(hits_);
  if (!barycentrics_)
    return std::string(
               "visibility buffer: only CPU passes read the hits, so the fragments leave "
               "their (u, v) NaN and the CPU passes intersect the pixel ray with the "
               "named triangle (passes/common/hits_texel.h)") +
           (impostors_          ? "; analytic spheres drawn as ray-cast impostors (their box, no "
                                  "triangles), lifted onto the exact sphere by the same CPU passes"
            : impostorsAllowed_ ? "; analytic spheres as triangles, which a reader needs"
                                : "; analytic spheres as triangles (impostors false)");
  return std::string("exact hits: (u, v) computed per fragment, because ") +
         (gl       ? "a GL pass reads the hits"
          : !cpu   ? "no CPU pass reads the hits"
          : normal ? "the normal is read"
                   : "the surface is read");
}

void GBufferPass::execute(PassContext& c) {
  const gl::GlSceneBuffers& scene = c.world().glScene();
  // Only what a live pass reads is written: the hybrid frame (CPU passes, which rebuild the
  // exact surface from the hits) pays for neither the normal nor the surface.
  gl::GBufferTargets targets{.hits = &c.glTexture(hits_),
                             .depth = &c.glTexture(depth_),
                             .barycentrics = barycentrics_,
                             .impostors = impostors_};
  if (consumed(c, normal_)) targets.normal = &c.glTexture(normal_);
  if (surface_ != kNoResource && consumed(c, surface_)) targets.surface = &c.glTexture(surface_);
  // The shading buffers carry the alpha masks, so the G-buffer sees through the holes that
  // the Embree filter cuts for rays. The scene's textures only for the normal and surface
  // (normal and bump maps, gbuffer_surface.comp): the hits read none, the masks have their own
  // array.
  const gl::GlShadingBuffers& shading =
      c.world().glShading(targets.normal != nullptr || targets.surface != nullptr);
  // The scene's materials: single-sided ones show the camera no back faces (glTF doubleSided).
  c.world().glCached<gl::GBufferRasterizer>().render(scene, c.frame().camera, targets, &shading,
                                                     &c.world().scene());
}

}  // namespace diptych
