#pragma once
#include "passes/raster/texture_filter.h"

namespace diptych {

// texture_anisotropic: anisotropic probes along the footprint's long axis
// (EXT_texture_filter_anisotropic).
class TextureAnisotropicPass : public TextureFilterPass {
 public:
  TextureAnisotropicPass() : TextureFilterPass(TextureFilterKind::Anisotropic) {}
  static ParamSchema schema() { return TextureFilterPass::schema(TextureFilterKind::Anisotropic); }
};

}  // namespace diptych
