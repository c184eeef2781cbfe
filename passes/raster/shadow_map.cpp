#include "passes/raster/shadow_map.h"

#include "engine/graph/render_world.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/shadow_map_frusta.h"
#include "passes/raster/shadow_map_gl.h"

namespace diptych {

void ShadowMapPass::setup(PassBuilder& b) {
  settings_ = shadowmap::readSettings(b.params());
  io_ = slotIo(b, "visibility");
  surface_ = readSurface(b, io_.hits);
}

void ShadowMapPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  // PCSS's point/spot size is relative to the scene so that penumbrae scale with it (a scene
  // scaled by s must give the same image: docs/numerics.md).
  const Aabb& bounds = world.geometry().bounds;
  const float diagonal = bounds.empty() ? 1.f : glm::length(bounds.hi - bounds.lo);
  const auto frusta =
      shadowmap::fitLightFrusta(world.scene().lights, bounds,
                                {.resolution = settings_.resolution,
                                 .pointLightSize = settings_.lightFraction * diagonal,
                                 .directionalAngle = settings_.lightAngle});
  auto& state = world.glCached<shadowmap::ShadowMapGl>();
  shadowmap::ShadowMapGl::Built built;
  const gl::Texture& maps = state.mapsFor(world, frusta, settings_, built);
  state.lookup(world, frusta, settings_, maps, c.glTexture(io_.hits),
               surface_ != kNoResource ? &c.glTexture(surface_) : nullptr, c.glTexture(io_.signal));
  // Counters of this frame (read by tests: counts, not times). With static update the render is
  // a one-time cost of the world, reported apart from the frame as env_*'s prefilter is.
  c.count("shadow_map_texels",
          double(maps.width()) * maps.height() * shadowmap::totalLayers(frusta));
  c.count("shadow_map_caster_draws", built.draws);
  c.count("shadow_map_builds", built.rendered ? 1.0 : 0.0);
  if (built.rendered && settings_.update == shadowmap::Update::Static) {
    c.count("shadow_map_build_ms", built.ms);
    world.addOneTime("shadow_map build", built.ms);
  }
}

}  // namespace diptych
