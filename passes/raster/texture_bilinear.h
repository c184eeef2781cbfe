#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_bilinear: level 0, bilinear, no mipmaps.
class TextureBilinearPass : public TextureFilterPass {
 public:
  TextureBilinearPass() : TextureFilterPass(TextureFilterKind::Bilinear) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Bilinear); }
};

}  // namespace diptych
