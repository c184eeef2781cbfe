#pragma once
// The `texture_lod` parameter of the producers that forward-render the scene (planar_mirror,
// sorted_blend, unsorted_blend, env_dynamic_cube): how their raster draws filter colour
// textures (gl::ForwardOptions::textureLod, docs/forward-producers.md).
#include "engine/graph/pass.h"

namespace diptych {

inline ParamSpec forwardTextureLodParam() {
  return ParamSpec::choice("texture_lod", "fragment", {"fragment", "level0"},
                           "colour textures of the rendered scene: at each fragment's level of "
                           "detail (GL's mipmapping), or level 0 (a ray's hit lookup)");
}

inline bool forwardTextureLod(PassBuilder& b) {
  return b.params().string("texture_lod") == "fragment";
}

}  // namespace diptych
