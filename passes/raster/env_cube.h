#pragma once
#include "passes/raster/env_reflection.h"

namespace diptych {

// env_cube: GL cube map (seamless), the scene's faces or the environment resampled.
class EnvCubePass : public EnvReflectionPass {
 public:
  EnvCubePass() : EnvReflectionPass(EnvMapKind::Cube) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Cube); }
};

}  // namespace diptych
