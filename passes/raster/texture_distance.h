#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_distance: the lecture's level from log2 of the eye distance, trilinear between the two
// nearest levels.
class TextureDistancePass : public TextureFilterPass {
 public:
  TextureDistancePass() : TextureFilterPass(TextureFilterKind::Distance) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Distance); }
};

}  // namespace diptych
