#include "passes/raster/gbuffer_surface.h"

#include "engine/gl/bindings.h"
#include "engine/gl/objects.h"
#include "engine/graph/companion.h"

namespace diptych {

ResourceId readSurface(PassBuilder& b, ResourceId hits) {
  return readCompanion(b, hits, kSurface, Format::RGBA32F, /*glOnly=*/true);
}

std::vector<gl::ShaderDefine> surfaceDefines(ResourceId surface) {
  if (surface == kNoResource) return {};
  return {{"DIPTYCH_GBUFFER_SURFACE", "1"}};
}

void bindSurface(PassContext& c, ResourceId surface) {
  if (surface != kNoResource)
    gl::glBindTextureUnit(gl::UNIT_GBUFFER_SURFACE, c.glTexture(surface).id());
}

}  // namespace diptych
