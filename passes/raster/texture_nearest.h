#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_nearest: level 0, nearest texel, no mipmaps.
class TextureNearestPass : public TextureFilterPass {
 public:
  TextureNearestPass() : TextureFilterPass(TextureFilterKind::Nearest) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Nearest); }
};

}  // namespace diptych
