#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_sampler: the texture's own glTF sampler (magnification filter when lambda <= 0, else
// the minification filter with its mipmap mode) at GL's derivative-based lambda.
class TextureSamplerPass : public TextureFilterPass {
 public:
  TextureSamplerPass() : TextureFilterPass(TextureFilterKind::Sampler) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Sampler); }
};

}  // namespace diptych
