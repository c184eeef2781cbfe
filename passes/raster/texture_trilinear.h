#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_trilinear: GL's derivative-based level (OpenGL 4.5, 8.14.1), trilinear.
class TextureTrilinearPass : public TextureFilterPass {
 public:
  TextureTrilinearPass() : TextureFilterPass(TextureFilterKind::Trilinear) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Trilinear); }
};

}  // namespace diptych
