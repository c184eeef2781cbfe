#include "passes/raster/shadow_map.h"

#include "engine/graph/render_world.h"
#include "passes/raster/shadow_map_frusta.h"
#include "passes/raster/shadow_map_gl.h"

namespace diptych {

void ShadowMapPass::setup(PassBuilder& b) {
  settings_ = shadowmap::readSettings(b.params());
  b.needs(SceneNeed::ShadowCastingLight);
  gbuffer_ = b.read("visibility", Format::RGBA32UI);
  const int layers = std::max<int>(1, int(b.scene().lights.size()));
  visibility_ =
      b.write("visibility", {Format::R32F, b.frame().width, b.frame().height, layers}, vec4(1.f));
}

void ShadowMapPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const auto frusta = shadowmap::fitLightFrusta(world.scene().lights, world.geometry().bounds,
                                                {.resolution = settings_.resolution,
                                                 .pointLightSize = settings_.lightSize,
                                                 .directionalAngle = settings_.lightAngle});
  auto& state = world.glCached<shadowmap::ShadowMapGl>();
  const gl::Texture& maps =
      state.maps(settings_.resolution, std::max(1, shadowmap::totalLayers(frusta)));
  state.renderMaps(world, frusta, settings_, maps);
  state.lookup(world, frusta, settings_, maps, c.glTexture(gbuffer_), c.glTexture(visibility_));
  c.count("shadow_map_texels",
          double(maps.width()) * maps.height() * shadowmap::totalLayers(frusta));
}

}  // namespace diptych
