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
  const gl::Texture& maps =
      state.maps(settings_.resolution, std::max(1, shadowmap::totalLayers(frusta)));
  const int draws = state.renderMaps(world, frusta, settings_, maps);
  state.lookup(world, frusta, settings_, maps, c.glTexture(io_.hits),
               surface_ != kNoResource ? &c.glTexture(surface_) : nullptr, c.glTexture(io_.signal));
  c.count("shadow_map_texels",
          double(maps.width()) * maps.height() * shadowmap::totalLayers(frusta));
  c.count("shadow_map_caster_draws", draws);
}

}  // namespace diptych
